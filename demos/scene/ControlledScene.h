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
	std::vector<std::string> methods;  // the ways of joining it the example offers, by name ("plastic-hinge")
	std::string method;                // the one it starts with
	// the scene of these slider values (one per slider, in order) and a method of methods; throws
	// std::invalid_argument naming a value out of its range
	std::function<std::unique_ptr<SteppedScene>(const std::vector<float>& values, const std::string& method)> build;
	// the view direction; the examples frame the scene's view envelope from it (demos/examples/ViewFraming.h)
	float camera_yaw_deg = 180;  // from +z
	float camera_pitch_deg = 0;
	float time_scale = 1;  // simulated seconds per browser second
	float joint_marker_px = 12;  // the size of the dot at each joint
};

// the starting values of a scene's sliders
std::vector<float> initialValues(const ControlledScene& scene);

// the joint methods of the structure scenes' examples (hinge-motor, plastic-hinge, elastic-plastic, elastic-plastic2)
std::vector<std::string> structureMethodNames();
// the method of that name; throws std::invalid_argument naming the methods for any other
plastic::JointMethod structureMethod(const std::string& name);
}  // namespace scene
