// ExampleBrowser examples (CommonExampleInterface) of the structure scenes and the game scene. Each draws the scene its
// controls build (the class the console runner steps), colours its joints, and shows its ledger on screen.
#pragma once

class CommonExampleInterface;
struct CommonExampleOptions;

// options.m_option: the joint method 1-4 (hinge-motor, plastic-hinge, elastic-plastic, elastic-plastic2); 0 = plastic-hinge
CommonExampleInterface* CantileverExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* PortalExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* DropWeightExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* WreckingBallExampleCreateFunc(CommonExampleOptions& options);
CommonExampleInterface* BuildingExampleCreateFunc(CommonExampleOptions& options);
