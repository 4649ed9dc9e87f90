// How a structure scene is shown: the colour of each body by the state of the joints at its ends (elastic, yielded,
// broken), a marker at every joint pivot in the same colours (the ledger's text and the camera: ViewFraming.h). Reads
// the scene; changes nothing but the bodies' and shapes' user indices, which are the graphics' (as in upstream's examples).
#pragma once

#include <map>
#include <string>

#include "scene/SteppedScene.h"

struct GUIHelperInterface;
struct CommonGraphicsApp;

enum class JointColour
{
	Elastic,
	Yielded,
	Broken,
};

// RGBA of a body whose worst joint is in that state, and of a joint marker
extern const float kSteelRgba[4];
extern const float kYieldedRgba[4];
extern const float kBrokenRgba[4];
extern const float kElasticMarkerRgba[4];
extern const float kOtherBodyRgba[4];   // moving bodies without plastic joints (ball, chain, carriage)
extern const float kStaticBodyRgba[4];  // ground, supports

// the worst state of the joints at each body's ends
std::map<const btRigidBody*, JointColour> bodyStates(const std::vector<scene::JointView>& joints);

// graphics objects for every body of the world (replacing any there were), coloured as they stand now
void showStructure(GUIHelperInterface* guiHelper, scene::SteppedScene& scene);
// recolour the bodies (before the world is synced and rendered)
void colourStructure(GUIHelperInterface* guiHelper, scene::SteppedScene& scene);
// a point of size_px at every joint pivot in its state's colour, 0.15 m towards +z (after the world is rendered); none
// at the joints of a whole structure (their bodies out of the world)
void drawJointMarkers(GUIHelperInterface* guiHelper, scene::SteppedScene& scene, float size_px);
