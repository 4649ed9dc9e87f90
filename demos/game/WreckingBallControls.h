// The wrecking ball example's sliders (no GUI code): labels with units, ranges, and the parameters they stand for.
#pragma once

#include <vector>

#include "scene/ControlledScene.h"
#include "WreckingBall.h"

namespace game
{
WreckingBallParameters wreckingBallFromSliders(const std::vector<float>& values, plastic::JointMethod method);
scene::ControlledScene wreckingBallControls();
// The same scene with a building: the wrecking ball's sliders, then storeys and bays (default 5 and 4: 200 joints)
WreckingBallParameters buildingFromSliders(const std::vector<float>& values, plastic::JointMethod method);
scene::ControlledScene buildingControls();
}  // namespace game
