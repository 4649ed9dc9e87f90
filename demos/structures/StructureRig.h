// The world every structures scene runs in: a sequential-impulse world without gravity (the textbook answers
// are for the applied loads alone), a static ground that supports are fixed to (it collides with nothing), the
// solver settings, and the internal step loop. Loads and joints that need something before or after each
// internal step register callbacks.
#pragma once

#include <functional>
#include <vector>

#include "JointFactory.h"

namespace structures
{
// How a scene is solved: the joint method of every plastic joint, the internal step and the iterations.
struct SolverSettings
{
	plastic::JointMethod method = plastic::JointMethod::PlasticHinge;
	double step_s = 1e-3;
	int iterations = 1000;
};

// "name: value is not in [low, high] unit" into errors when value is outside the range (or not finite)
void requireRange(std::vector<std::string>& errors, const char* name, double value, double low, double high, const char* unit);
void requireWhole(std::vector<std::string>& errors, const char* name, int value, int low, int high);
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

	btDiscreteDynamicsWorld& world() { return m_world; }
	btRigidBody& ground() { return m_ground; }
	const SolverSettings& settings() const { return m_settings; }
	double time_s() const { return m_time_s; }
	long steps() const { return m_steps; }

	void beforeEachStep(std::function<void(double step_s)> callback) { m_before.push_back(std::move(callback)); }
	void afterEachStep(std::function<void()> callback) { m_after.push_back(std::move(callback)); }
	// one internal step of settings().step_s
	void step();

private:
	SolverSettings m_settings;
	btDefaultCollisionConfiguration m_configuration;
	btCollisionDispatcher m_dispatcher{&m_configuration};
	btDbvtBroadphase m_broadphase;
	btSequentialImpulseConstraintSolver m_solver;
	btDiscreteDynamicsWorld m_world{&m_dispatcher, &m_broadphase, &m_solver, &m_configuration};
	btBoxShape m_groundShape{btVector3(0.01, 0.01, 0.01)};
	btRigidBody m_ground{btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &m_groundShape)};
	std::vector<std::function<void(double)>> m_before;
	std::vector<std::function<void()>> m_after;
	double m_time_s = 0;
	long m_steps = 0;
};
}  // namespace structures
