// The city example's sliders (no GUI code): labels with units, ranges, and the parameters they stand for. Its method
// choice is the way the buildings are simulated (jit, jointed, rigid).
#pragma once

#include <string>
#include <vector>

#include "City.h"
#include "scene/ControlledScene.h"

namespace game
{
// throws std::invalid_argument naming the mode for a mode that is not jit, jointed or rigid
CityParameters cityFromSliders(const std::vector<float>& values, const std::string& mode);
scene::ControlledScene cityControls();
}  // namespace game
