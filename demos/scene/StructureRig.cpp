#include "StructureRig.h"

#include <cmath>
#include <sstream>

namespace scene
{
void requireRange(std::vector<std::string>& errors, const char* name, double value, double low, double high, const char* unit)
{
	if (!(std::isfinite(value) && value >= low && value <= high))
	{
		std::ostringstream out;
		out << name << ": " << value << " is not in [" << low << ", " << high << "]" << (*unit ? " " : "") << unit;
		errors.push_back(out.str());
	}
}

void requireWhole(std::vector<std::string>& errors, const char* name, int value, int low, int high)
{
	if (value < low || value > high)
	{
		errors.push_back(std::string(name) + ": " + std::to_string(value) + " is not in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
	}
}

std::vector<std::string> validateSolverSettings(const SolverSettings& s)
{
	return plastic::validate(s.world, "dt");
}

StructureRig::StructureRig(const SolverSettings& settings) : m_settings(settings), m_world(settings.world)
{
	world().addRigidBody(&m_ground, 0, 0);
}

StructureRig::~StructureRig() { world().removeRigidBody(&m_ground); }

void StructureRig::step()
{
	for (auto& f : m_before) f(step_s());
	m_world.stepOnce();
	for (auto& f : m_after) f();
	m_time_s += step_s();
	m_steps++;
}
}  // namespace scene
