// What an ExampleBrowser example of a scene offers, without any GUI code (so the console side and the tests can read
// it): its sliders (labels with units, ranges, starting values), how slider values become the scene's parameters
// and build the scene (the same scene class the runner steps), its view direction and its pace.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "plastic/JointFactory.h"
#include "SteppedScene.h"

namespace scene
{
struct SliderSpec
{
	const char* label;  // with its unit
	float min;
	float max;
	bool integers;
	float initial;
};

struct ControlledScene
{
	std::string name;
	std::vector<SliderSpec> sliders;
	plastic::JointMethod method = plastic::JointMethod::PlasticHinge;  // the method it starts with
	// the scene of these slider values (one per slider, in order) and method; throws std::invalid_argument naming a
	// value out of its range
	std::function<std::unique_ptr<SteppedScene>(const std::vector<float>& values, plastic::JointMethod method)> build;
	// the view direction; the examples frame the scene's view envelope from it (demos/examples/ViewFraming.h)
	float camera_yaw_deg = 180;  // from +z
	float camera_pitch_deg = 0;
	float time_scale = 1;  // simulated seconds per browser second
};

// the starting values of a scene's sliders
std::vector<float> initialValues(const ControlledScene& scene);
}  // namespace scene
