// The sliders of the structures scenes' examples (scene::ControlledScene): how slider values become each scene's
// parameters.
#pragma once

#include <vector>

#include "Cantilever.h"
#include "DropWeight.h"
#include "PaperClip.h"
#include "plastic/JointFactory.h"
#include "Portal.h"
#include "scene/ControlledScene.h"

namespace structures
{
// The parameters slider values stand for (the rest at the parameters' defaults); bad values are left for the
// scene's validation to name.
CantileverParameters cantileverFromSliders(const std::vector<float>& values, plastic::JointMethod method);
PortalParameters portalFromSliders(const std::vector<float>& values, plastic::JointMethod method);
DropWeightParameters dropWeightFromSliders(const std::vector<float>& values, plastic::JointMethod method);
PaperClipParameters paperClipFromSliders(const std::vector<float>& values, plastic::JointMethod method);

scene::ControlledScene cantileverControls();
scene::ControlledScene portalControls();
scene::ControlledScene dropWeightControls();
scene::ControlledScene paperClipControls();
}  // namespace structures
