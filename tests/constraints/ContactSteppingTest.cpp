// Contact stepping (patch 0053, btDiscreteDynamicsWorld::setContactStepping): the world cuts its internal steps so
// that no pair in or near contact moves more than a given distance in one, and leaves them whole otherwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"

namespace
{
constexpr double kFrame_s = 1.0 / 60.0;
constexpr double kFloorTop_m = 0.01;   // a static floor 2 cm thick, its top at y = 1 cm
constexpr double kRadius_m = 0.05;     // the falling sphere's
// a speculative contact of the sphere reaches 1 mm (its bounding radius times gContactBreakingThreshold, 0.02)
constexpr double kTravel_m = 5e-4;
constexpr double kMinimumStep_s = 1e-5;

// A sphere above a thin static floor, under gravity; collisions on, no deactivation.
struct FloorWorld
{
	explicit FloorWorld(double height_m, double speed_m_s)
		: dispatcher(&configuration), world(&dispatcher, &broadphase, &solver, &configuration)
	{
		world.setGravity(btVector3(0, btScalar(-9.81), 0));
		btTransform t;
		t.setIdentity();
		floor = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &floorShape));
		world.addRigidBody(floor.get());
		btVector3 inertia(0, 0, 0);
		sphereShape.calculateLocalInertia(1, inertia);
		btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &sphereShape, inertia);
		t.setOrigin(btVector3(0, btScalar(height_m), 0));
		info.m_startWorldTransform = t;
		sphere = std::make_unique<btRigidBody>(info);
		sphere->setActivationState(DISABLE_DEACTIVATION);
		sphere->setLinearVelocity(btVector3(0, btScalar(-speed_m_s), 0));
		world.addRigidBody(sphere.get());
	}
	~FloorWorld()
	{
		for (auto& ball : balls) world.removeRigidBody(ball.get());
		world.removeRigidBody(sphere.get());
		world.removeRigidBody(floor.get());
	}
	double height_m() const { return sphere->getCenterOfMassPosition().y(); }
	// a small sphere (1 cm radius, 1 kg) at (x, 5 m, 0) moving along x, in a collision filter group and mask
	btRigidBody* addBall(double x_m, double speed_m_s, int group = 1, int mask = -1)
	{
		btVector3 inertia(0, 0, 0);
		ballShape.calculateLocalInertia(1, inertia);
		btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &ballShape, inertia);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setOrigin(btVector3(btScalar(x_m), 5, 0));
		balls.push_back(std::make_unique<btRigidBody>(info));
		balls.back()->setActivationState(DISABLE_DEACTIVATION);
		balls.back()->setLinearVelocity(btVector3(btScalar(speed_m_s), 0, 0));
		world.addRigidBody(balls.back().get(), group, mask);
		return balls.back().get();
	}

	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher;
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver solver;
	btDiscreteDynamicsWorld world;
	btBoxShape floorShape{btVector3(1, btScalar(kFloorTop_m), 1)};
	btSphereShape sphereShape{btScalar(kRadius_m)};
	std::unique_ptr<btRigidBody> floor;
	std::unique_ptr<btRigidBody> sphere;
	btSphereShape ballShape{btScalar(0.01)};
	std::vector<std::unique_ptr<btRigidBody>> balls;
};

// the length of each internal step, from the world's pre-tick callback
std::vector<double>* gSteps = nullptr;
void recordStep(btDynamicsWorld*, btScalar step_s) { gSteps->push_back(double(step_s)); }
}  // namespace

TEST(ContactStepping, OffByDefaultEachInternalStepIsWhole)
{
	FloorWorld w(0.25, 20);
	EXPECT_EQ(w.world.getMaximumContactTravel(), btScalar(0));
	w.world.stepSimulation(btScalar(kFrame_s), 0);
	EXPECT_EQ(w.world.getNumInternalSteps(), 1);
	// fixed internal steps: two of them
	w.world.stepSimulation(btScalar(2 * kFrame_s), 10, btScalar(kFrame_s));
	EXPECT_EQ(w.world.getNumInternalSteps(), 2);
}

// Whole 1/60 s steps move a sphere falling at 20 m/s 33 cm each, and a 2 cm floor is met between two of them: it
// passes through. Cut near the floor, the step that meets it starts within the sphere's speculative contact, which
// stops it on the floor's face.
TEST(ContactStepping, AFastSphereStopsOnAThinFloorWhereWholeStepsLetItThrough)
{
	FloorWorld whole(0.25, 20);
	for (int frame = 0; frame < 10; frame++) whole.world.stepSimulation(btScalar(kFrame_s), 0);
	EXPECT_LT(whole.height_m(), -0.5) << "the sphere should fall through the floor in whole steps";

	FloorWorld cut(0.25, 20);
	cut.world.setContactStepping(btScalar(kTravel_m), btScalar(kMinimumStep_s));
	int mostSteps = 0;
	double deepest_m = 0;
	for (int frame = 0; frame < 30; frame++)
	{
		cut.world.stepSimulation(btScalar(kFrame_s), 0);
		mostSteps = std::max(mostSteps, cut.world.getNumInternalSteps());
		deepest_m = std::max(deepest_m, kFloorTop_m + kRadius_m - cut.height_m());
	}
	EXPECT_NEAR(cut.height_m(), kFloorTop_m + kRadius_m, 1e-3) << "the sphere should rest on the floor";
	EXPECT_LT(deepest_m, kTravel_m) << "no deeper than a step's travel";
	EXPECT_LT(cut.sphere->getLinearVelocity().length(), 0.05);
	EXPECT_GT(mostSteps, 1) << "the frame that meets the floor is cut";
}

// Far from any other object a body's steps are whole, and the world moves exactly as without contact stepping.
TEST(ContactStepping, FarFromContactTheStepsAreWholeAndTheMotionTheSame)
{
	FloorWorld plain(100, 0);
	FloorWorld cut(100, 0);
	cut.world.setContactStepping(btScalar(kTravel_m), btScalar(kMinimumStep_s));
	for (int frame = 0; frame < 20; frame++)
	{
		plain.world.stepSimulation(btScalar(kFrame_s), 0);
		cut.world.stepSimulation(btScalar(kFrame_s), 0);
		ASSERT_EQ(cut.world.getNumInternalSteps(), 1) << "frame " << frame;
	}
	EXPECT_EQ(cut.sphere->getCenterOfMassPosition().y(), plain.sphere->getCenterOfMassPosition().y());
	EXPECT_EQ(cut.sphere->getLinearVelocity().y(), plain.sphere->getLinearVelocity().y());
}

// A sphere resting on the floor and a travel no step can keep: the steps are as short as allowed, equal, none shorter
// than the minimum, and they add up to the frame.
TEST(ContactStepping, NoStepIsShorterThanTheMinimumAndTheStepsAddUpToTheFrame)
{
	FloorWorld w(kFloorTop_m + kRadius_m, 0);
	const double minimum_s = 1e-3;
	w.world.setContactStepping(btScalar(1e-9), btScalar(minimum_s));
	std::vector<double> steps;
	gSteps = &steps;
	w.world.setInternalTickCallback(recordStep, nullptr, true);
	w.world.stepSimulation(btScalar(kFrame_s), 0);
	w.world.setInternalTickCallback(nullptr, nullptr, true);
	gSteps = nullptr;
	ASSERT_EQ(int(steps.size()), w.world.getNumInternalSteps());
	EXPECT_EQ(int(steps.size()), 16) << "1/60 s in steps of at least 1 ms";
	double sum = 0;
	for (double step : steps)
	{
		EXPECT_GE(step, minimum_s * (1 - 1e-6));
		sum += step;
	}
	EXPECT_NEAR(sum, kFrame_s, 1e-7);
}

// Two spheres closing on each other at 30 m/s, 0.38 m apart: whole 1/60 s steps carry each past the other; cut by
// their relative speed, they meet.
TEST(ContactStepping, TwoBodiesClosingOnEachOtherAreCutByTheirRelativeSpeed)
{
	for (bool cut : {false, true})
	{
		FloorWorld w(100, 0);
		w.world.setGravity(btVector3(0, 0, 0));
		btRigidBody* left = w.addBall(-0.2, 15);
		btRigidBody* right = w.addBall(0.2, -15);
		if (cut) w.world.setContactStepping(btScalar(1e-4), btScalar(1e-6));
		for (int frame = 0; frame < 3; frame++) w.world.stepSimulation(btScalar(kFrame_s), 0);
		const bool passed = left->getCenterOfMassPosition().x() > right->getCenterOfMassPosition().x();
		EXPECT_EQ(passed, !cut) << (cut ? "cut steps should let the spheres meet" : "whole steps should carry them past");
	}
}

// A static plane's box is unbounded: a sphere far above one is not near it, and its steps stay whole.
TEST(ContactStepping, AStaticPlaneFarBelowDoesNotCutTheSteps)
{
	FloorWorld w(10, 5);
	btStaticPlaneShape planeShape(btVector3(0, 1, 0), btScalar(-1));
	btRigidBody plane(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &planeShape));
	w.world.addRigidBody(&plane);
	w.world.setContactStepping(btScalar(kTravel_m), btScalar(kMinimumStep_s));
	int steps = 0;
	for (int frame = 0; frame < 10; frame++)
	{
		w.world.stepSimulation(btScalar(kFrame_s), 0);
		steps += w.world.getNumInternalSteps();
	}
	EXPECT_EQ(steps, 10) << "the sphere is metres above the plane";
	w.world.removeRigidBody(&plane);
}

// An object without contact response (a sensor) holds no step: a sphere flying through one is not cut by it.
TEST(ContactStepping, AnObjectWithoutContactResponseDoesNotCutTheSteps)
{
	FloorWorld w(10, 0);
	w.world.setGravity(btVector3(0, 0, 0));
	btBoxShape sensorShape(btVector3(2, 2, 2));
	btCollisionObject sensor;
	sensor.setCollisionShape(&sensorShape);
	btTransform t;
	t.setIdentity();
	t.setOrigin(btVector3(0, 10, 0));
	sensor.setWorldTransform(t);
	sensor.setCollisionFlags(sensor.getCollisionFlags() | btCollisionObject::CF_NO_CONTACT_RESPONSE);
	w.world.addCollisionObject(&sensor);
	w.sphere->setLinearVelocity(btVector3(50, 0, 0));
	w.world.setContactStepping(btScalar(kTravel_m), btScalar(kMinimumStep_s));
	for (int frame = 0; frame < 3; frame++)
	{
		w.world.stepSimulation(btScalar(kFrame_s), 0);
		EXPECT_EQ(w.world.getNumInternalSteps(), 1) << "frame " << frame;
	}
	w.world.removeCollisionObject(&sensor);
}

// With a travel larger than any pair moves every step is whole, and a pile of boxes falling on a floor moves bit for
// bit as without contact stepping: the stepping reads the broadphase and does not change it (the contact rows' turn
// prediction, which setContactStepping also turns on, is turned off here to isolate the stepping).
TEST(ContactStepping, WholeStepsOfABusySceneAreBitIdenticalToNoStepping)
{
	std::vector<double> positions[2];
	for (int run = 0; run < 2; run++)
	{
		FloorWorld w(100, 0);
		btBoxShape boxShape(btVector3(btScalar(0.1), btScalar(0.1), btScalar(0.1)));
		btVector3 inertia(0, 0, 0);
		boxShape.calculateLocalInertia(1, inertia);
		std::vector<std::unique_ptr<btRigidBody>> boxes;
		for (int i = 0; i < 60; i++)
		{
			btTransform t;
			t.setIdentity();
			t.setOrigin(btVector3(btScalar(0.05 * (i % 5) - 0.1), btScalar(0.2 + 0.25 * i), btScalar(0.03 * (i % 3))));
			btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &boxShape, inertia);
			info.m_startWorldTransform = t;
			boxes.push_back(std::make_unique<btRigidBody>(info));
			w.world.addRigidBody(boxes.back().get());
		}
		if (run == 1)
		{
			w.world.setContactStepping(btScalar(100), btScalar(kMinimumStep_s));
			EXPECT_TRUE(w.world.getSolverInfo().m_contactTurnPrediction);
			w.world.getSolverInfo().m_contactTurnPrediction = false;  // the stepping alone: the rows' turn prediction apart
		}
		for (int frame = 0; frame < 120; frame++)
		{
			w.world.stepSimulation(btScalar(kFrame_s), 0);
			ASSERT_EQ(w.world.getNumInternalSteps(), 1);
		}
		for (auto& box : boxes)
		{
			for (int axis = 0; axis < 3; axis++) positions[run].push_back(box->getCenterOfMassPosition()[axis]);
			w.world.removeRigidBody(box.get());
		}
	}
	ASSERT_EQ(positions[0].size(), positions[1].size());
	for (size_t i = 0; i < positions[0].size(); i++) ASSERT_EQ(positions[0][i], positions[1][i]) << "coordinate " << i;
}

// Two spheres whose collision filters keep them apart (groups and masks, as the broadphase applies them) never touch:
// closing on each other they do not cut the steps, where spheres that may collide do.
TEST(ContactStepping, BodiesWhoseFiltersKeepThemApartDoNotCutTheSteps)
{
	for (bool filtered : {false, true})
	{
		FloorWorld w(100, 0);
		w.world.setGravity(btVector3(0, 0, 0));
		// groups 2 and 4 each collide with group 1 (the floor's default) only: the two never meet
		w.addBall(-0.03, 2, filtered ? 2 : 1, filtered ? 1 : -1);
		w.addBall(0.03, -2, filtered ? 4 : 1, filtered ? 1 : -1);
		w.world.setContactStepping(btScalar(1e-4), btScalar(1e-6));
		w.world.stepSimulation(btScalar(kFrame_s), 0);
		if (filtered)
			EXPECT_EQ(w.world.getNumInternalSteps(), 1) << "filtered apart, the spheres cut no step";
		else
			EXPECT_GT(w.world.getNumInternalSteps(), 1) << "spheres that may collide cut the frame";
	}
}

namespace
{
// A 10 cm box (1 kg) over the floor's top at a gap, moving at a velocity and turned about z, no gravity.
struct BoxOverFloor
{
	BoxOverFloor(double gap_m, const btVector3& velocity_m_s, double turn_rad = 0) : w(100, 0)
	{
		w.world.setGravity(btVector3(0, 0, 0));
		btVector3 inertia(0, 0, 0);
		shape.calculateLocalInertia(1, inertia);
		btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &shape, inertia);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setRotation(btQuaternion(btVector3(0, 0, 1), btScalar(turn_rad)));
		// the turned box's lowest corner gap_m above the floor
		const double reach_m = 0.05 * (std::cos(turn_rad) + std::sin(std::fabs(turn_rad)));
		info.m_startWorldTransform.setOrigin(btVector3(-0.5, btScalar(kFloorTop_m + reach_m + gap_m), 0));
		box = std::make_unique<btRigidBody>(info);
		box->setActivationState(DISABLE_DEACTIVATION);
		box->setLinearVelocity(velocity_m_s);
		w.world.addRigidBody(box.get());
	}
	~BoxOverFloor() { w.world.removeRigidBody(box.get()); }
	// the lowest point of the box below the floor's top (negative: above it)
	double depth_m() const
	{
		btVector3 lo, hi;
		box->getAabb(lo, hi);
		return kFloorTop_m - lo.y();
	}

	FloorWorld w;
	btBoxShape shape{btVector3(btScalar(0.05), btScalar(0.05), btScalar(0.05))};
	std::unique_ptr<btRigidBody> box;
};
}  // namespace

// A box sliding at 10 m/s along the floor 0.2 mm above it does not close on it: along the floor's normal the gap does
// not shrink, so its steps stay whole. A bound of its speed alone (the gap and the travel, 0.7 mm, at 10 m/s: 70 us)
// would cut each 1/60 s frame into hundreds.
TEST(ContactStepping, ABoxSlidingAlongAFaceWithoutClosingOnItKeepsWholeSteps)
{
	BoxOverFloor b(2e-4, btVector3(10, 0, 0));
	b.w.world.setContactStepping(btScalar(kTravel_m), btScalar(kMinimumStep_s));
	for (int frame = 0; frame < 5; frame++)
	{
		b.w.world.stepSimulation(btScalar(kFrame_s), 0);
		EXPECT_EQ(b.w.world.getNumInternalSteps(), 1) << "frame " << frame;
	}
	EXPECT_NEAR(b.box->getLinearVelocity().x(), 10, 1e-6);
}

// Boxes turned 0 and 0.3 rad falling on the 2 cm floor at 20 m/s: whole 1/60 s steps carry them through it, the
// stepping along the floor's axes stops them on it, no deeper than the travel.
TEST(ContactStepping, AFastBoxStopsOnAThinFloorNoDeeperThanTheTravel)
{
	for (double turn : {0.0, 0.3})
	{
		BoxOverFloor whole(0.2, btVector3(0, -20, 0), turn);
		for (int frame = 0; frame < 10; frame++) whole.w.world.stepSimulation(btScalar(kFrame_s), 0);
		EXPECT_GT(whole.depth_m(), 0.5) << turn << " rad: whole steps should carry the box through the floor";

		BoxOverFloor cut(0.2, btVector3(0, -20, 0), turn);
		cut.w.world.setContactStepping(btScalar(kTravel_m), btScalar(kMinimumStep_s));
		double deepest_m = 0;
		int steps = 0;
		for (int frame = 0; frame < 30; frame++)
		{
			cut.w.world.stepSimulation(btScalar(kFrame_s), 0);
			steps += cut.w.world.getNumInternalSteps();
			deepest_m = std::max(deepest_m, cut.depth_m());
		}
		EXPECT_LT(deepest_m, kTravel_m) << turn << " rad";
		EXPECT_LT(cut.depth_m(), kTravel_m) << turn << " rad: the box should rest on the floor";
		EXPECT_GT(steps, 30) << turn << " rad: the frames that meet the floor are cut";
	}
}

namespace
{
// A 1 kg shape of radius 1 m rolling at 48 m/s (48 rad/s) on a 1000 kg slab (dynamic, so the pair is predicted with
// both bodies' turns: patch 0055) lying on a static floor; whole 1 ms steps (0.048 rad a step, within the 0.05 rad the
// prediction takes: a swung point would rise 1.15 mm a step). The shape's lowest and highest centre height above the
// slab's top over the last half of 0.6 s.
struct Rolling
{
	double lowest_m = 1e9, highest_m = -1e9;
};

Rolling rollOnASlab(btCollisionShape& shape, bool turnPrediction)
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver solver;
	btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
	world.setGravity(btVector3(0, btScalar(-9.81), 0));
	btBoxShape floorShape(btVector3(100, 1, 100));
	btRigidBody::btRigidBodyConstructionInfo floorInfo(0, nullptr, &floorShape);
	floorInfo.m_startWorldTransform.setIdentity();
	floorInfo.m_startWorldTransform.setOrigin(btVector3(0, -1, 0));
	btRigidBody floor(floorInfo);
	world.addRigidBody(&floor);
	btBoxShape slabShape(btVector3(50, btScalar(0.1), 5));
	btVector3 slabInertia;
	slabShape.calculateLocalInertia(1000, slabInertia);
	btRigidBody::btRigidBodyConstructionInfo slabInfo(1000, nullptr, &slabShape, slabInertia);
	slabInfo.m_startWorldTransform.setIdentity();
	slabInfo.m_startWorldTransform.setOrigin(btVector3(0, btScalar(0.1), 0));
	btRigidBody slab(slabInfo);
	slab.setActivationState(DISABLE_DEACTIVATION);
	world.addRigidBody(&slab);
	btVector3 inertia;
	shape.calculateLocalInertia(1, inertia);
	btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &shape, inertia);
	info.m_startWorldTransform.setIdentity();
	info.m_startWorldTransform.setOrigin(btVector3(-40, btScalar(1.2), 0));
	btRigidBody body(info);
	body.setActivationState(DISABLE_DEACTIVATION);
	body.setLinearVelocity(btVector3(48, 0, 0));
	body.setAngularVelocity(btVector3(0, 0, -48));
	world.addRigidBody(&body);
	world.setContactStepping(btScalar(100), btScalar(kMinimumStep_s));  // whole steps: the rows' prediction alone
	world.getSolverInfo().m_contactTurnPrediction = turnPrediction;
	Rolling r;
	for (int frame = 0; frame < 600; frame++)
	{
		world.stepSimulation(btScalar(1e-3), 0);
		const double height_m = body.getCenterOfMassPosition().y() - (slab.getCenterOfMassPosition().y() + 0.1);
		if (frame >= 300)
		{
			r.lowest_m = std::min(r.lowest_m, height_m);
			r.highest_m = std::max(r.highest_m, height_m);
		}
	}
	world.removeRigidBody(&body);
	world.removeRigidBody(&slab);
	world.removeRigidBody(&floor);
	return r;
}
}  // namespace

// A curved surface rolls: the contact point stays under its centre of curvature, which swings with the body, and does
// not swing itself (a rolling sphere's lowest point would rise by R (1 - cos(w h)) a step in the prediction, and the
// row let it sink by as much: at 20 rad/s in 1/60 s steps 14 cm before the radius of curvature was read from the
// shape; here, with the radius taken as 0, the sphere and the capsule sink 5.8 mm and the cylinder bounces 19 cm).
// A sphere, a capsule and a cylinder rolling on a moving slab stay on it with the prediction as without.
TEST(ContactStepping, ShapesRollingOnAMovingSlabDoNotSinkWithTheTurnPrediction)
{
	btSphereShape sphere(1);
	btCapsuleShapeZ capsule(1, btScalar(0.4));
	btCylinderShapeZ cylinder(btVector3(1, 1, btScalar(0.2)));
	for (btCollisionShape* shape : {static_cast<btCollisionShape*>(&sphere), static_cast<btCollisionShape*>(&capsule),
									static_cast<btCollisionShape*>(&cylinder)})
	{
		const Rolling without = rollOnASlab(*shape, false);
		const Rolling with = rollOnASlab(*shape, true);
		EXPECT_GT(with.lowest_m, without.lowest_m - 2e-4) << shape->getName() << " " << without.lowest_m << " " << with.lowest_m;
		EXPECT_LT(with.highest_m, without.highest_m + 2e-4) << shape->getName() << " " << without.highest_m << " " << with.highest_m;
		EXPECT_GT(with.lowest_m, 1 - 0.01) << shape->getName();
	}
}
