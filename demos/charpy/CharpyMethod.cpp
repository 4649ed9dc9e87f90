#include "CharpyMethod.h"

#include <array>

namespace
{
struct MethodInfo
{
	std::string_view name;
	std::string_view description;
};

constexpr std::array<MethodInfo, kCharpyMethodCount> kMethods = {{
	{"rigid", "single rigid body (no joint)"},
	{"brittle", "btGeneric6DofConstraint, zero limits, breakingImpulseThreshold"},
	{"spring", "btGeneric6DofSpringConstraint, rotational springs k = Mp per rad"},
	{"spring2", "btGeneric6DofSpring2Constraint, rotational springs k = Mp per rad"},
	{"hinge-motor", "btHingeConstraint, motor at target velocity 0, max impulse Mp * internal dt"},
	{"plastic-hinge", "btPlasticHingeConstraint, plastic moment Mp"},
	{"elastic-plastic", "bt6DofElasticPlasticConstraint, steel stiffness, capped at the section's capacities"},
	{"elastic-plastic2", "bt6DofElasticPlastic2Constraint, steel stiffness, capped at the section's capacities"},
}};
}  // namespace

std::string_view charpyMethodName(CharpyMethod method)
{
	return kMethods[static_cast<int>(method) - 1].name;
}

std::string_view charpyMethodDescription(CharpyMethod method)
{
	return kMethods[static_cast<int>(method) - 1].description;
}

CharpyMethod charpyMethodByNumber(int number)
{
	return static_cast<CharpyMethod>(number);
}

std::optional<CharpyMethod> parseCharpyMethod(std::string_view name)
{
	for (int i = 1; i <= kCharpyMethodCount; i++)
	{
		if (kMethods[i - 1].name == name)
		{
			return charpyMethodByNumber(i);
		}
	}
	return std::nullopt;
}

bool charpyMethodBooksJointWork(CharpyMethod method)
{
	return method == CharpyMethod::PlasticHinge || method == CharpyMethod::ElasticPlastic || method == CharpyMethod::ElasticPlastic2;
}
