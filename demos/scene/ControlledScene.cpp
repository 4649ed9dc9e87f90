#include "ControlledScene.h"

namespace scene
{
std::vector<float> initialValues(const ControlledScene& scene)
{
	std::vector<float> v;
	for (const SliderSpec& s : scene.sliders) v.push_back(s.initial);
	return v;
}
}  // namespace scene
