// The world every structures scene runs in: the toolkit's plastic::StructureWorld (its solver settings: by default
// btDirectJointSolver, 10 iterations, 1/240 s; zero gravity, the textbook answers are for the applied loads
// alone), a static ground that supports are fixed to (it collides with nothing), and the internal step loop. Loads
// and joints that need something before or after each internal step register callbacks.
#pragma once

#include <chrono>
#include <functional>
#include <vector>

#include "plastic/JointFactory.h"
#include "plastic/SolverSettings.h"
#include "Ranges.h"
#include "RunStats.h"

namespace scene
{
// How a scene is solved: the joint method of every plastic joint, and the world's solver settings (solver kind,
// iterations, internal step, ERP) as the toolkit defines them.
struct SolverSettings
{
	plastic::JointMethod method = plastic::JointMethod::PlasticHinge;
	plastic::WorldSolverSettings world;
};

std::vector<std::string> validateSolverSettings(const SolverSettings& settings);

// Takes a constraint out of the world when it goes out of scope (declare it after what owns the constraint).
struct ConstraintInWorld
{
	ConstraintInWorld(btDiscreteDynamicsWorld& world, btTypedConstraint& constraint, bool disableCollisions = true) : m_world(world), m_constraint(constraint)
	{
		world.addConstraint(&constraint, disableCollisions);
	}
	~ConstraintInWorld() { m_world.removeConstraint(&m_constraint); }
	ConstraintInWorld(const ConstraintInWorld&) = delete;
	ConstraintInWorld& operator=(const ConstraintInWorld&) = delete;
	btDiscreteDynamicsWorld& m_world;
	btTypedConstraint& m_constraint;
};

// Takes a body out of the world when it goes out of scope.
struct BodyInWorld
{
	btDiscreteDynamicsWorld& world;
	btRigidBody& body;
	~BodyInWorld() { world.removeRigidBody(&body); }
};

class StructureRig
{
public:
	explicit StructureRig(const SolverSettings& settings);
	~StructureRig();
	StructureRig(const StructureRig&) = delete;
	StructureRig& operator=(const StructureRig&) = delete;

	btDiscreteDynamicsWorld& world() { return m_world.world(); }
	btRigidBody& ground() { return m_ground; }
	const SolverSettings& settings() const { return m_settings; }
	double step_s() const { return m_settings.world.internal_step_s; }
	double time_s() const { return m_time_s; }
	// internal steps in which the direct or MLCP solver failed and sequential impulse solved the step instead (0 for SI)
	int solverFallbacks() const { return m_world.solverFallbacks(); }
	// the run so far: its internal steps, simulated time, wall time since start, fallbacks, and finite as the scene found it
	RunStats runStats(std::chrono::steady_clock::time_point start, bool finite) const
	{
		RunStats stats;
		stats.internal_steps = m_steps;
		stats.simulated_s = m_time_s;
		stats.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
		stats.solver_fallbacks = solverFallbacks();
		stats.finite = finite;
		return stats;
	}

	void beforeEachStep(std::function<void(double step_s)> callback) { m_before.push_back(std::move(callback)); }
	void afterEachStep(std::function<void()> callback) { m_after.push_back(std::move(callback)); }
	// one internal step of step_s()
	void step();

private:
	SolverSettings m_settings;
	plastic::StructureWorld m_world;
	btBoxShape m_groundShape{btVector3(0.01, 0.01, 0.01)};
	btRigidBody m_ground{btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &m_groundShape)};
	std::vector<std::function<void(double)>> m_before;
	std::vector<std::function<void()>> m_after;
	double m_time_s = 0;
	long m_steps = 0;
};
}  // namespace scene
