// The eight ways of joining the Charpy specimen halves compared in the thesis
// (S. Nikula, Handling of plasticity in physics engine, LUT 2017, sections 2.3-2.10).
#pragma once

#include <optional>
#include <string>
#include <string_view>

enum class CharpyMethod
{
	RigidBody = 1,          // 2.3 single rigid body
	BrittleZeroLimits,      // 2.4 btGeneric6DofConstraint, zero limits + breakingImpulseThreshold
	Spring,                 // 2.5 btGeneric6DofSpringConstraint
	Spring2,                // 2.6 btGeneric6DofSpring2Constraint
	HingeMotor,             // 2.7 btHingeConstraint with a motor, max impulse Mp * dt
	PlasticHinge,           // 2.8 btPlasticHingeConstraint
	ElasticPlastic,         // 2.9 bt6DofElasticPlasticConstraint
	ElasticPlastic2,        // 2.10 bt6DofElasticPlastic2Constraint
};

constexpr int kCharpyMethodCount = 8;

// Command-line name, e.g. "plastic-hinge".
std::string_view charpyMethodName(CharpyMethod method);
// One-line description naming the Bullet class.
std::string_view charpyMethodDescription(CharpyMethod method);
// Method 1-8 in thesis order.
CharpyMethod charpyMethodByNumber(int number);
std::optional<CharpyMethod> parseCharpyMethod(std::string_view name);
// The joints of the new constraint classes (methods 6-8) book the plastic work they do at their cap.
bool charpyMethodBooksJointWork(CharpyMethod method);
