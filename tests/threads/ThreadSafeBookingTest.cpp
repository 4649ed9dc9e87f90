// The plastic bookkeeping under btSequentialImpulseConstraintSolverMt (a BT_THREADSAFE build of the patched tree):
// the solver writes the rows back in parallel chunks of 400 rows, so a constraint's rows may be split between two
// chunks and the chunks may run in any order and on any thread. The booking must not depend on that.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"
#include "BulletCollision/CollisionDispatch/btSimulationIslandManager.h"
#include "BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolverMt.h"
#include "LinearMath/btThreads.h"
#include "../common/TurningPendulum.h"

#if !BT_THREADSAFE
#error "this test needs the BT_THREADSAFE build of the patched libraries"
#endif

namespace
{
// Runs the chunks of every loop on the calling thread, last chunk first: a valid scheduler that changes the order.
class ReverseChunkScheduler : public btITaskScheduler
{
public:
	ReverseChunkScheduler() : btITaskScheduler("ReverseChunks") {}
	int getMaxNumThreads() const override { return 1; }
	int getNumThreads() const override { return 1; }
	void setNumThreads(int) override {}
	void parallelFor(int iBegin, int iEnd, int grainSize, const btIParallelForBody& body) override
	{
		const int grain = grainSize > 0 ? grainSize : 1;
		for (int end = iEnd; end > iBegin;)
		{
			const int begin = std::max(iBegin, iBegin + ((end - iBegin - 1) / grain) * grain);
			body.forLoop(begin, end);
			end = begin;
		}
	}
	btScalar parallelSum(int iBegin, int iEnd, int grainSize, const btIParallelSumBody& body) override
	{
		btScalar sum = 0;
		const int grain = grainSize > 0 ? grainSize : 1;
		for (int end = iEnd; end > iBegin;)
		{
			const int begin = std::max(iBegin, iBegin + ((end - iBegin - 1) / grain) * grain);
			sum += body.sumLoop(begin, end);
			end = begin;
		}
		return sum;
	}
};

struct Booking
{
	std::vector<double> energy, rotation;
	std::vector<bool> enabled;
	bool operator==(const Booking& o) const { return energy == o.energy && rotation == o.rotation && enabled == o.enabled; }
};

// the first joint whose booking differs, for the failure message
std::string firstDifference(const Booking& a, const Booking& b)
{
	for (size_t i = 0; i < a.energy.size() && i < b.energy.size(); i++)
	{
		if (a.energy[i] != b.energy[i] || a.rotation[i] != b.rotation[i] || a.enabled[i] != b.enabled[i])
		{
			char text[200];
			std::snprintf(text, sizeof text, "joint %zu: %.17g J %.17g rad %d vs %.17g J %.17g rad %d", i, a.energy[i], a.rotation[i], int(a.enabled[i]),
						  b.energy[i], b.rotation[i], int(b.enabled[i]));
			return text;
		}
	}
	return "sizes differ";
}

// A world without gravity on the multithreaded solver, and the bar shape both tests use.
struct MtWorld
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolverMt solver;
	btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
	btBoxShape shape{btVector3(0.5, 0.05, 0.05)};
	btVector3 inertia;
	MtWorld()
	{
		world.setGravity(btVector3(0, 0, 0));
		shape.calculateLocalInertia(1, inertia);
	}
};

// 1200 bars, each held to the world by a plastic hinge (6 rows) or an elastic-plastic2 joint (6 rows), under moments
// from 0.5 to 2 times their cap, in one group of 7200 rows (18 write-back chunks, some of them splitting a joint).
Booking run(btITaskScheduler* scheduler)
{
	btSetTaskScheduler(scheduler);
	MtWorld mt;
	btDiscreteDynamicsWorld& world = mt.world;
	world.getSimulationIslandManager()->setSplitIslands(false);
	btBoxShape& shape = mt.shape;
	const btVector3& inertia = mt.inertia;
	const int n = 1200;
	std::vector<std::unique_ptr<btRigidBody>> bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> joints;
	for (int i = 0; i < n; i++)
	{
		btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &shape, inertia);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setOrigin(btVector3(btScalar(2 * (i % 40)), btScalar(2 * (i / 40)), 0));
		bodies.emplace_back(new btRigidBody(info));
		bodies.back()->setActivationState(DISABLE_DEACTIVATION);
		world.addRigidBody(bodies.back().get(), 0, 0);
		if (i % 2 == 0)
		{
			auto* h = new btPlasticHingeConstraint(*bodies.back(), btVector3(0, 0, 0), btVector3(0, 0, 1));
			h->setPlasticMoment(2.0);
			h->setMaxPlasticRotation(btScalar(0.2 + 0.001 * i));
			joints.emplace_back(h);
		}
		else
		{
			auto* c = new bt6DofElasticPlastic2Constraint(*bodies.back(), btTransform::getIdentity());
			for (int d = 0; d < 6; d++) c->setLimit(d, 0, 0);
			c->setStiffness(5, 0, false);
			c->setMaxForce(5, 2.0);
			c->setMaxPlasticRotation(btScalar(0.2 + 0.001 * i));
			joints.emplace_back(c);
		}
		world.addConstraint(joints.back().get());
	}
	for (int step = 0; step < 60; step++)
	{
		for (int i = 0; i < n; i++) bodies[i]->applyTorque(btVector3(0, 0, btScalar(1.0 + 3.0 * (i % 7) / 6.0)));
		world.stepSimulation(btScalar(1.0 / 60.0), 0);
	}
	Booking b;
	for (auto& j : joints)
	{
		if (auto* h = dynamic_cast<btPlasticHingeConstraint*>(j.get()))
		{
			b.energy.push_back(h->getAbsorbedEnergy());
			b.rotation.push_back(h->getCurrentPlasticRotation());
		}
		else
		{
			auto* c = static_cast<bt6DofElasticPlastic2Constraint*>(j.get());
			b.energy.push_back(c->getAbsorbedEnergy());
			b.rotation.push_back(c->getCurrentPlasticRotation());
		}
		b.enabled.push_back(j->isEnabled());
	}
	for (auto& j : joints) world.removeConstraint(j.get());
	for (auto& body : bodies) world.removeRigidBody(body.get());
	btSetTaskScheduler(btGetSequentialTaskScheduler());
	return b;
}
}  // namespace

TEST(ThreadSafeBooking, SameBookingWithChunksInAnyOrderAndOnTwoThreads)
{
	const Booking sequential = run(btGetSequentialTaskScheduler());
	// the scene yields and breaks: the comparison is not between empty bookings
	int yielding = 0, broken = 0;
	for (size_t i = 0; i < sequential.energy.size(); i++)
	{
		yielding += sequential.energy[i] > 0;
		broken += !sequential.enabled[i];
	}
	EXPECT_GT(yielding, 600);
	EXPECT_GT(broken, 100);
	EXPECT_LT(broken, 1100);

	ReverseChunkScheduler reverse;
	const Booking reversed = run(&reverse);
	EXPECT_TRUE(reversed == sequential) << "chunks in reverse order: " << firstDifference(reversed, sequential);

	// kept for the life of the process: upstream's btTaskSchedulerDefault can crash in its destructor while a worker
	// thread is still timing its idle loop (btClock freed under it), as upstream's own examples never delete it
	static btITaskScheduler* threads = btCreateDefaultTaskScheduler();
	ASSERT_NE(threads, nullptr);
	threads->setNumThreads(2);
	for (int repeat = 0; repeat < 3; repeat++)
	{
		const Booking threaded = run(threads);
		EXPECT_TRUE(threaded == sequential) << "two threads, run " << repeat << ": " << firstDifference(threaded, sequential);
	}
}

// The booking of a yielding joint is the work the load did on it: the same physics as the single-threaded solver.
TEST(ThreadSafeBooking, YieldingHingeBooksTheWorkOfTheLoad)
{
	btSetTaskScheduler(btGetSequentialTaskScheduler());
	MtWorld mt;
	btDiscreteDynamicsWorld& world = mt.world;
	const btVector3& inertia = mt.inertia;
	btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &mt.shape, inertia);
	btRigidBody bar(info);
	bar.setActivationState(DISABLE_DEACTIVATION);
	world.addRigidBody(&bar, 0, 0);
	btPlasticHingeConstraint hinge(bar, btVector3(0, 0, 0), btVector3(0, 0, 1));
	hinge.setPlasticMoment(2.0);
	world.addConstraint(&hinge);
	const double torque = 3.0;
	double rotation = 0;
	for (int i = 0; i < 30; i++)
	{
		const btVector3 x0 = bar.getWorldTransform().getBasis().getColumn(0);
		bar.applyTorque(btVector3(0, 0, btScalar(torque)));
		world.stepSimulation(btScalar(1.0 / 60.0), 0);
		const btVector3 x1 = bar.getWorldTransform().getBasis().getColumn(0);
		rotation += std::atan2(double(x0.cross(x1).z()), double(x0.dot(x1)));
	}
	const double kinetic = 0.5 * inertia.z() * bar.getAngularVelocity().z() * bar.getAngularVelocity().z();
	// semi-implicit Euler gains (tau - Mp)^2 dt^2 / (2 I) per step over the exact work; the rest must balance
	const double dt = 1.0 / 60.0, integratorGain = 30 * (torque - 2.0) * (torque - 2.0) * dt * dt / (2 * inertia.z());
	EXPECT_NEAR(torque * rotation, kinetic + hinge.getAbsorbedEnergy() + integratorGain, 1e-3 * torque * rotation);
	EXPECT_NEAR(hinge.getAbsorbedEnergy(), 2.0 * rotation, 1e-3 * 2.0 * rotation);
	world.removeConstraint(&hinge);
	world.removeRigidBody(&bar);
}

// setSplitPositionCorrectionAfterLongerSteps (patch 0044) on the batched joint setup of the multithreaded solver
// (internalConvertMultipleJoints records the step): a 20 kg box turning at 5.6 rad/s on a hinge 0.8 m from its centre,
// stepped 0.1 ms, then 1.3 ms, then 2 us at a time. The control (the mode off) is kicked by the velocity bias.
TEST(ThreadSafeBooking, ALongerStepsDriftIsCorrectedWithoutMomentumOnTheBatchedSetup)
{
	btSetTaskScheduler(btGetSequentialTaskScheduler());
	const int batching = btSequentialImpulseConstraintSolverMt::s_minimumContactManifoldsForBatching;
	btSequentialImpulseConstraintSolverMt::s_minimumContactManifoldsForBatching = 0;  // batch a world without contacts
	auto largestRise = [](PivotCorrection correction)
	{
		MtWorld mt;
		TurningPendulum pendulum(mt.world, correction);
		return pendulum.largestRise_j(TurningPendulum::gatheredThenShortSteps()) / pendulum.kineticEnergy_j();
	};
	const double without = largestRise(PivotCorrection::Baumgarte);
	const double with = largestRise(PivotCorrection::AfterLongerSteps);
	btSequentialImpulseConstraintSolverMt::s_minimumContactManifoldsForBatching = batching;
	EXPECT_GT(without, 0.05) << "the control: the velocity bias kicks the pendulum";
	EXPECT_LT(with, 1e-3);
}

namespace
{
// 400 boxes spinning and sliding onto a static floor (400 manifolds and more: the solver's batched, parallel contact
// setup) with the world's contact stepping and so the contact rows' turn prediction; the boxes' positions at the end.
std::vector<double> spinningBoxesOnAFloor(btITaskScheduler* scheduler, bool turnPrediction)
{
	btSetTaskScheduler(scheduler);
	MtWorld mt;
	btDiscreteDynamicsWorld& world = mt.world;
	world.setGravity(btVector3(0, btScalar(-9.81), 0));
	world.getSimulationIslandManager()->setSplitIslands(false);
	btBoxShape floorShape(btVector3(50, 1, 50));
	btRigidBody::btRigidBodyConstructionInfo floorInfo(0, nullptr, &floorShape);
	floorInfo.m_startWorldTransform.setIdentity();
	floorInfo.m_startWorldTransform.setOrigin(btVector3(0, -1, 0));
	btRigidBody floor(floorInfo);
	world.addRigidBody(&floor);
	btBoxShape boxShape(btVector3(btScalar(0.2), btScalar(0.05), btScalar(0.1)));
	btVector3 inertia;
	boxShape.calculateLocalInertia(1, inertia);
	std::vector<std::unique_ptr<btRigidBody>> boxes;
	for (int i = 0; i < 400; i++)
	{
		btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &boxShape, inertia);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setOrigin(btVector3(btScalar(1.0 * (i % 20) - 10), btScalar(0.3), btScalar(1.0 * (i / 20) - 10)));
		boxes.emplace_back(new btRigidBody(info));
		boxes.back()->setActivationState(DISABLE_DEACTIVATION);
		boxes.back()->setLinearVelocity(btVector3(btScalar(2 + i % 3), 0, btScalar(i % 5 - 2)));
		boxes.back()->setAngularVelocity(btVector3(btScalar(2 + i % 5), btScalar(i % 3), btScalar(3 - i % 7)));  // under 0.05 rad a step
		world.addRigidBody(boxes.back().get());
	}
	world.setContactStepping(btScalar(0.005), btScalar(1e-3));
	world.getSolverInfo().m_contactTurnPrediction = turnPrediction;
	for (int frame = 0; frame < 60; frame++) world.stepSimulation(btScalar(1.0 / 240.0), 0);
	std::vector<double> positions;
	for (auto& box : boxes)
	{
		for (int axis = 0; axis < 3; axis++) positions.push_back(box->getCenterOfMassPosition()[axis]);
		world.removeRigidBody(box.get());
	}
	world.removeRigidBody(&floor);
	btSetTaskScheduler(btGetSequentialTaskScheduler());
	return positions;
}
}  // namespace

// The contact rows' turn prediction (btContactSolverInfo::m_contactTurnPrediction) reads only the bodies and their
// shapes: the multithreaded solver's contact setup, in chunks in any order or on two threads, gives the same motion.
TEST(ThreadSafeBooking, ContactTurnPredictionIsTheSameInAnyOrderAndOnTwoThreads)
{
	const std::vector<double> sequential = spinningBoxesOnAFloor(btGetSequentialTaskScheduler(), true);
	EXPECT_NE(sequential, spinningBoxesOnAFloor(btGetSequentialTaskScheduler(), false)) << "the prediction changes nothing here";
	ReverseChunkScheduler reverse;
	EXPECT_EQ(spinningBoxesOnAFloor(&reverse, true), sequential) << "chunks in reverse order";
	static btITaskScheduler* threads = btCreateDefaultTaskScheduler();
	ASSERT_NE(threads, nullptr);
	threads->setNumThreads(2);
	for (int repeat = 0; repeat < 3; repeat++) EXPECT_EQ(spinningBoxesOnAFloor(threads, true), sequential) << "two threads, run " << repeat;
}
