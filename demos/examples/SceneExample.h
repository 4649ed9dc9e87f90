// ExampleBrowser examples (CommonExampleInterface) of every scene: Charpy, the structure scenes and the game scene, one
// class (SceneExample.cpp). Each draws the scene its controls build (the class the console runner steps), colours its
// joints, and shows its ledger on screen.
#pragma once

class CommonExampleInterface;
struct CommonExampleOptions;

// options.m_option: the Charpy method 1-8 in thesis order (CharpyMethod); 0 = plastic-hinge
CommonExampleInterface* CharpyExampleCreateFunc(CommonExampleOptions& options);
// options.m_option: the joint method 1-4 (hinge-motor, plastic-hinge, elastic-plastic, elastic-plastic2); 0 = plastic-hinge
CommonExampleInterface* CantileverExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* PortalExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* DropWeightExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* PaperClipExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* WreckingBallExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* BuildingExampleCreateFunc(CommonExampleOptions& options);
// options.m_option: the mode 1-3 (jit, jointed, rigid); 0 = jit
CommonExampleInterface* CityExampleCreateFunc(CommonExampleOptions& options);
