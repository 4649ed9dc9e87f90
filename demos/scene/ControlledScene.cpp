#include "ControlledScene.h"

#include <stdexcept>

namespace scene
{
std::vector<float> initialValues(const ControlledScene& scene)
{
	std::vector<float> v;
	for (const SliderSpec& s : scene.sliders) v.push_back(s.initial);
	return v;
}

namespace
{
const plastic::JointMethod kStructureMethods[] = {plastic::JointMethod::HingeMotor, plastic::JointMethod::PlasticHinge, plastic::JointMethod::ElasticPlastic,
												  plastic::JointMethod::ElasticPlastic2};
}

std::vector<std::string> structureMethodNames()
{
	std::vector<std::string> names;
	for (plastic::JointMethod m : kStructureMethods) names.push_back(plastic::jointMethodName(m));
	return names;
}

plastic::JointMethod structureMethod(const std::string& name)
{
	for (plastic::JointMethod m : kStructureMethods)
		if (name == plastic::jointMethodName(m)) return m;
	throw std::invalid_argument("method: '" + name + "' is not one of hinge-motor, plastic-hinge, elastic-plastic, elastic-plastic2");
}
}  // namespace scene
