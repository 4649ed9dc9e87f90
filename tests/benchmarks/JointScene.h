// Benchmark scenes: N boxes, each held to one static anchor by one joint of a given kind, under
// gravity, with collisions off (so the joints are what is measured). Loaded joints carry the
// box's weight moment; an idle plastic joint has a cap far above it, a yielding one below it.
#pragma once

#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"
#ifdef BP_THREADS  // the BT_THREADSAFE build: btDiscreteDynamicsWorldMt with a solver pool and the Mt solver
#include "BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolverMt.h"
#include "BulletDynamics/Dynamics/btDiscreteDynamicsWorldMt.h"
#endif

enum class JointKind
{
	HingeLocked,          // upstream btHingeConstraint, limit low == high (rigid)
	HingeMotor,           // upstream btHingeConstraint, motor target 0 with a max impulse (thesis method 5)
	FixedBreakable,       // upstream btGeneric6DofConstraint, zero limits + breaking impulse (thesis method 2)
	PlasticHingeIdle,     // btPlasticHingeConstraint, cap far above the load
	PlasticHingeYielding, // btPlasticHingeConstraint, cap below the load: yields every step
	Spring,               // upstream btGeneric6DofSpringConstraint
	ElasticPlastic,       // bt6DofElasticPlasticConstraint
	Spring2,              // upstream btGeneric6DofSpring2Constraint
	ElasticPlastic2,      // bt6DofElasticPlastic2Constraint
};

class JointScene
{
public:
	// splitIslands: Bullet's default (each one-joint island solved on its own) or one solver call for all;
	// directSolver: btDirectJointSolver instead of sequential impulse (not in the upstream-only and threads builds)
	JointScene(JointKind kind, int joints, bool splitIslands = false, bool directSolver = false);
	~JointScene();
	void step() { m_world->stepSimulation(kStep_s, 0, kStep_s); }
	static constexpr btScalar kStep_s = btScalar(1.0 / 60);
	// sizeof the constraint class of a kind, bytes
	static size_t constraintSize(JointKind kind);

private:
	btDefaultCollisionConfiguration m_configuration;
	btCollisionDispatcher m_dispatcher{&m_configuration};
	btDbvtBroadphase m_broadphase;
	btSequentialImpulseConstraintSolver m_solver;
	std::unique_ptr<btConstraintSolver> m_directSolver;
#ifdef BP_THREADS
	btSequentialImpulseConstraintSolverMt m_solverMt;
	std::unique_ptr<btConstraintSolverPoolMt> m_solverPool;
#endif
	std::unique_ptr<btDiscreteDynamicsWorld> m_world;
	btBoxShape m_shape{btVector3(0.05, 0.05, 0.2)};
	std::unique_ptr<btRigidBody> m_anchor;
	std::vector<std::unique_ptr<btRigidBody>> m_bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> m_joints;
};

// Structures that break into pieces: N members, each a chain of four boxes hung from a static anchor by joints that
// break under their own weight within the first second (upstream hinges with a breaking impulse threshold, or plastic
// hinges with a small maximum plastic rotation), so the islands multiply while the scene runs. Island splitting on.
class BreakingScene
{
public:
	BreakingScene(int members, bool plastic);
	~BreakingScene();
	void step() { m_world->stepSimulation(JointScene::kStep_s, 0, JointScene::kStep_s); }
	int enabledJoints() const;

private:
	btDefaultCollisionConfiguration m_configuration;
	btCollisionDispatcher m_dispatcher{&m_configuration};
	btDbvtBroadphase m_broadphase;
	btSequentialImpulseConstraintSolver m_solver;
	std::unique_ptr<btDiscreteDynamicsWorld> m_world;
	btBoxShape m_shape{btVector3(0.05, 0.05, 0.2)};
	std::unique_ptr<btRigidBody> m_anchor;
	std::vector<std::unique_ptr<btRigidBody>> m_bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> m_joints;
};
