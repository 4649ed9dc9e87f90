#include "JointScene.h"

#include <stdexcept>

#include "BulletCollision/CollisionDispatch/btSimulationIslandManager.h"
#if !defined(BP_UPSTREAM_ONLY) && !defined(BP_THREADS)
#include "BulletDynamics/ConstraintSolver/btDirectJointSolver.h"
#endif

namespace
{
const btScalar kMass_kg = 1;
const btScalar kArm_m = 0.2;                      // box centre to joint
const btScalar kLoadMoment_nm = kMass_kg * btScalar(9.81) * kArm_m;
const btScalar kIdleCap_nm = 1000 * kLoadMoment_nm;
const btScalar kYieldCap_nm = btScalar(0.5) * kLoadMoment_nm;

btTransform at(const btVector3& origin) { return btTransform(btQuaternion::getIdentity(), origin); }

// Spring and Spring2 (and their elastic-plastic subclasses): every DOF a 1e4 spring.
template <class Constraint>
Constraint* springy(Constraint* g)
{
	for (int i = 0; i < 6; i++)
	{
		g->enableSpring(i, true);
		g->setStiffness(i, 1e4);
	}
	return g;
}

#ifndef BP_UPSTREAM_ONLY
// The elastic-plastic classes: 1e4 springs, caps of 1 kN and half the load moment, never breaking.
template <class Constraint>
Constraint* elasticPlastic(Constraint* g)
{
	for (int i = 0; i < 6; i++)
	{
		g->setStiffness(i, 1e4);
		g->setMaxForce(i, i < 3 ? 1e3 : kYieldCap_nm);
	}
	g->setMaxPlasticDisplacement(1e6);
	g->setMaxPlasticRotation(1e6);
	return g;
}
#endif

btTypedConstraint* makeJoint(JointKind kind, btRigidBody& anchor, btRigidBody& box, const btVector3& pivot)
{
	// the joint sits at pivot (world), kArm_m from the box centre along +Z; hinge axis X: gravity bends it
	const btVector3 inAnchor = pivot - anchor.getCenterOfMassPosition();
	const btVector3 inBox(0, 0, kArm_m);
	const btVector3 axis(1, 0, 0);
	switch (kind)
	{
		case JointKind::HingeLocked:
		{
			auto* h = new btHingeConstraint(anchor, box, inAnchor, inBox, axis, axis);
			h->setLimit(0, 0);
			return h;
		}
		case JointKind::HingeMotor:
		{
			auto* h = new btHingeConstraint(anchor, box, inAnchor, inBox, axis, axis);
			h->enableAngularMotor(true, 0, kYieldCap_nm * JointScene::kStep_s);
			return h;
		}
		case JointKind::FixedBreakable:
		{
			auto* g = new btGeneric6DofConstraint(anchor, box, at(inAnchor), at(inBox), true);
			g->setLinearLowerLimit(btVector3(0, 0, 0));
			g->setLinearUpperLimit(btVector3(0, 0, 0));
			g->setAngularLowerLimit(btVector3(0, 0, 0));
			g->setAngularUpperLimit(btVector3(0, 0, 0));
			g->setBreakingImpulseThreshold(1e6);
			return g;
		}
#ifndef BP_UPSTREAM_ONLY  // built once more against an unpatched BulletDynamics for the idle-cost comparison
		case JointKind::PlasticHingeIdle:
		case JointKind::PlasticHingeYielding:
		{
			auto* h = new btPlasticHingeConstraint(anchor, box, inAnchor, inBox, axis, axis);
			h->setPlasticMoment(kind == JointKind::PlasticHingeIdle ? kIdleCap_nm : kYieldCap_nm);
			h->setMaxPlasticRotation(1e6);
			return h;
		}
#endif
		case JointKind::Spring:
			return springy(new btGeneric6DofSpringConstraint(anchor, box, at(inAnchor), at(inBox), true));
#ifndef BP_UPSTREAM_ONLY
		case JointKind::ElasticPlastic:
			return elasticPlastic(new bt6DofElasticPlasticConstraint(anchor, box, at(inAnchor), at(inBox), true));
#endif
		case JointKind::Spring2:
			return springy(new btGeneric6DofSpring2Constraint(anchor, box, at(inAnchor), at(inBox)));
#ifndef BP_UPSTREAM_ONLY
		case JointKind::ElasticPlastic2:
			return elasticPlastic(new bt6DofElasticPlastic2Constraint(anchor, box, at(inAnchor), at(inBox)));
#endif
		default:
			break;
	}
	return nullptr;
}
}  // namespace

JointScene::JointScene(JointKind kind, int joints, bool splitIslands, bool directSolver)
{
#if !defined(BP_UPSTREAM_ONLY) && !defined(BP_THREADS)
	if (directSolver) m_directSolver = std::make_unique<btDirectJointSolver>();
#else
	if (directSolver) throw std::invalid_argument("JointScene: btDirectJointSolver is not in this build");
#endif
#ifdef BP_THREADS
	// islands in parallel on a pool of solvers; one large island (no splitting) on the multithreaded solver
	m_solverPool = std::make_unique<btConstraintSolverPoolMt>(BT_MAX_THREAD_COUNT);
	m_world = std::make_unique<btDiscreteDynamicsWorldMt>(&m_dispatcher, &m_broadphase, m_solverPool.get(), &m_solverMt, &m_configuration);
#else
	btConstraintSolver* solver = m_directSolver ? m_directSolver.get() : static_cast<btConstraintSolver*>(&m_solver);
	m_world = std::make_unique<btDiscreteDynamicsWorld>(&m_dispatcher, &m_broadphase, solver, &m_configuration);
#endif
	m_world->setGravity(btVector3(0, btScalar(-9.81), 0));
	m_world->getSimulationIslandManager()->setSplitIslands(splitIslands);
	btRigidBody::btRigidBodyConstructionInfo anchorInfo(0, nullptr, &m_shape);
	m_anchor = std::make_unique<btRigidBody>(anchorInfo);
	m_world->addRigidBody(m_anchor.get(), 0, 0);
	btVector3 inertia;
	m_shape.calculateLocalInertia(kMass_kg, inertia);
	for (int i = 0; i < joints; i++)
	{
		const btVector3 pivot(btScalar(i), 0, 0);
		btRigidBody::btRigidBodyConstructionInfo info(kMass_kg, nullptr, &m_shape, inertia);
		info.m_startWorldTransform = at(pivot - btVector3(0, 0, kArm_m));
		m_bodies.push_back(std::make_unique<btRigidBody>(info));
		m_bodies.back()->setActivationState(DISABLE_DEACTIVATION);
		m_world->addRigidBody(m_bodies.back().get(), 0, 0);  // collides with nothing
		m_joints.emplace_back(makeJoint(kind, *m_anchor, *m_bodies.back(), pivot));
		m_world->addConstraint(m_joints.back().get(), true);
	}
}

JointScene::~JointScene()
{
	for (auto& j : m_joints) m_world->removeConstraint(j.get());
	for (auto& b : m_bodies) m_world->removeRigidBody(b.get());
	m_world->removeRigidBody(m_anchor.get());
}

size_t JointScene::constraintSize(JointKind kind)
{
	switch (kind)
	{
		case JointKind::HingeLocked:
		case JointKind::HingeMotor:
			return sizeof(btHingeConstraint);
		case JointKind::FixedBreakable:
			return sizeof(btGeneric6DofConstraint);
		case JointKind::Spring:
			return sizeof(btGeneric6DofSpringConstraint);
		case JointKind::Spring2:
			return sizeof(btGeneric6DofSpring2Constraint);
#ifndef BP_UPSTREAM_ONLY
		case JointKind::PlasticHingeIdle:
		case JointKind::PlasticHingeYielding:
			return sizeof(btPlasticHingeConstraint);
		case JointKind::ElasticPlastic:
			return sizeof(bt6DofElasticPlasticConstraint);
		case JointKind::ElasticPlastic2:
			return sizeof(bt6DofElasticPlastic2Constraint);
#endif
		default:
			return 0;
	}
}

BreakingScene::BreakingScene(int members, bool plastic)
{
#ifdef BP_UPSTREAM_ONLY
	(void)plastic;  // the unpatched build has upstream hinges only
#endif
	m_world = std::make_unique<btDiscreteDynamicsWorld>(&m_dispatcher, &m_broadphase, &m_solver, &m_configuration);
	m_world->setGravity(btVector3(0, btScalar(-9.81), 0));
	btRigidBody::btRigidBodyConstructionInfo anchorInfo(0, nullptr, &m_shape);
	m_anchor = std::make_unique<btRigidBody>(anchorInfo);
	m_world->addRigidBody(m_anchor.get(), 0, 0);
	btVector3 inertia;
	m_shape.calculateLocalInertia(kMass_kg, inertia);
	const btVector3 axis(1, 0, 0);
	for (int m = 0; m < members; m++)
	{
		btRigidBody* previous = m_anchor.get();
		for (int k = 0; k < 4; k++)
		{
			// a horizontal cantilever along +Z; joint k at z = 2 kArm_m k, box k centred kArm_m further
			const btVector3 pivot(btScalar(m), 0, 2 * kArm_m * k);
			btRigidBody::btRigidBodyConstructionInfo info(kMass_kg, nullptr, &m_shape, inertia);
			info.m_startWorldTransform = at(pivot + btVector3(0, 0, kArm_m));
			m_bodies.push_back(std::make_unique<btRigidBody>(info));
			m_world->addRigidBody(m_bodies.back().get(), 0, 0);
			btRigidBody* box = m_bodies.back().get();
			const btVector3 inPrevious = pivot - previous->getCenterOfMassPosition();
			const btVector3 inBox(0, 0, -kArm_m);
			// the root carries the moment of the whole member: it breaks first, then the pieces fall on their own
			const btScalar loadMoment = kMass_kg * btScalar(9.81) * (4 - k) * (4 - k) * 2 * kArm_m / 2;
#ifndef BP_UPSTREAM_ONLY
			if (plastic)
			{
				auto* h = new btPlasticHingeConstraint(*previous, *box, inPrevious, inBox, axis, axis);
				h->setPlasticMoment(btScalar(0.8) * loadMoment);
				h->setMaxPlasticRotation(btScalar(0.2 + 0.05 * (m % 5)));
				m_joints.emplace_back(h);
			}
			else
#endif
			{
				auto* h = new btHingeConstraint(*previous, *box, inPrevious, inBox, axis, axis);
				h->setLimit(0, 0);
				h->setBreakingImpulseThreshold(btScalar(0.8 + 0.05 * (m % 5)) * loadMoment * JointScene::kStep_s);
				m_joints.emplace_back(h);
			}
			m_world->addConstraint(m_joints.back().get(), true);
			previous = box;
		}
	}
}

BreakingScene::~BreakingScene()
{
	for (auto& j : m_joints) m_world->removeConstraint(j.get());
	for (auto& b : m_bodies) m_world->removeRigidBody(b.get());
	m_world->removeRigidBody(m_anchor.get());
}

int BreakingScene::enabledJoints() const
{
	int n = 0;
	for (auto& j : m_joints) n += j->isEnabled() ? 1 : 0;
	return n;
}
