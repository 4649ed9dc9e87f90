// The scenes' use of the toolkit's validation: the toolkit returns a message per bad field (it throws nothing, so a
// game built without exceptions can take it); a scene, which refuses bad parameters with std::invalid_argument,
// throws them as one.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace scene
{
// throws std::invalid_argument with the messages joined by "; " when there is any
inline void throwIfAny(const std::vector<std::string>& errors)
{
	if (errors.empty()) return;
	std::string all = errors.front();
	for (size_t i = 1; i < errors.size(); i++) all += "; " + errors[i];
	throw std::invalid_argument(all);
}

// spec itself, once the toolkit's validate(spec) (found by argument-dependent lookup: plastic::BeamSpec, JointSpec,
// ...) has nothing against it; else throws its messages. For building a toolkit object in an initializer list.
template <class Spec>
const Spec& requireValid(const Spec& spec)
{
	throwIfAny(validate(spec));
	return spec;
}
}  // namespace scene
