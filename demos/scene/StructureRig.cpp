#include "StructureRig.h"

#include <cmath>
#include <sstream>

namespace scene
{
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
