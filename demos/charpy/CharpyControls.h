// The Charpy example's controls: its sliders (scene::ControlledScene, the structure scenes' kind: labels with units,
// ranges, starting values), the eight methods, and the CharpyParameters they stand for. No GUI code here, so the tests
// can check every range.
#pragma once

#include <vector>

#include "CharpyParameters.h"
#include "scene/ControlledScene.h"

// What the sliders say, in the units their names say.
struct CharpyControls
{
	double yieldStress_MPa = 400;
	double friction = 0;
	double releaseAngle_rad = 2.8;
	double strikerRadius_mm = 0;
	double maxPlasticRotation_rad = 3;
	double frameStep_ms = 0.1;
	double solverIterations = 10;
	double partPairs = 1;
	double anvilGap_mm = 40;
};

// The controls of slider values in the order of charpyControls().sliders; throws std::invalid_argument for another
// count.
CharpyControls charpyControlsFromSliders(const std::vector<float>& values);

// The scene parameters of the controls for a method; the rest stays at CharpyParameters' defaults.
CharpyParameters charpyParametersFromControls(const CharpyControls& controls, CharpyMethod method);

// The example's sliders (starting at CharpyControls' values), its methods by name (thesis order) and how they build a
// CharpyScene; its view (from the hammer's side and above) and its pace (slow motion).
scene::ControlledScene charpyControls();
