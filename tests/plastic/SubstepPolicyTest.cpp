// The contact substep policy (demos/plastic/SubstepPolicy): how a frame is split, and the reach test, against
// a ball flying at a wall with a known arrival time.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "plastic/SubstepPolicy.h"
#include "btBulletDynamicsCommon.h"

namespace
{
struct BallAndWall
{
	btSphereShape ballShape{btScalar(0.1)};
	btBoxShape wallShape{btVector3(btScalar(0.1), 1, 1)};
	std::unique_ptr<btRigidBody> ball;
	std::unique_ptr<btCollisionObject> wall;

	// the ball's surface is gap_m from the wall's face and closes at speed_m_s
	BallAndWall(double gap_m, double speed_m_s)
	{
		btTransform t;
		t.setIdentity();
		ball = std::make_unique<btRigidBody>(btScalar(1), nullptr, &ballShape, btVector3(1, 1, 1));
		t.setOrigin(btVector3(btScalar(-0.1 - gap_m), 0, 0));
		ball->setWorldTransform(t);
		ball->setLinearVelocity(btVector3(btScalar(speed_m_s), 0, 0));
		wall = std::make_unique<btCollisionObject>();
		wall->setCollisionShape(&wallShape);
		t.setOrigin(btVector3(btScalar(0.1), 0, 0));
		wall->setWorldTransform(t);
		wall->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
	}
	bool near(double horizon_s) const { return plastic::mayTouchWithin({ball.get()}, {wall.get()}, horizon_s, 0.0); }
	// moves the ball as the world would in a step
	void move(double h_s)
	{
		btTransform t = ball->getWorldTransform();
		t.setOrigin(t.getOrigin() + ball->getLinearVelocity() * btScalar(h_s));
		ball->setWorldTransform(t);
	}
};
}  // namespace

TEST(SubstepPolicy, ReachGrowsWithSpeedTimesHorizon)
{
	BallAndWall s(0.5, 10.0);  // arrives after 0.05 s
	EXPECT_FALSE(s.near(0.04));
	EXPECT_TRUE(s.near(0.06));
	s.ball->setLinearVelocity(btVector3(0, 0, 0));
	EXPECT_FALSE(s.near(1e3));  // at rest it never arrives
}

TEST(SubstepPolicy, OnlyThePartOfAFrameNearContactIsSubstepped)
{
	// 1/60 s frame, contact after 10 ms: the first ~10 ms go in a few halves, the rest in 1 ms steps
	BallAndWall s(0.1, 10.0);
	plastic::ContactSubstepPolicy policy(plastic::ContactSubstepSettings{1e-3});
	std::vector<double> steps;
	const int n = policy.advance(
		1.0 / 60.0, [&](double horizon) { return s.near(horizon); },
		[&](double h) {
			steps.push_back(h);
			s.move(h);
		});
	EXPECT_EQ(n, int(steps.size()));
	double sum = 0;
	for (double h : steps) sum += h;
	EXPECT_NEAR(sum, 1.0 / 60.0, 1e-12);
	// whole frame in contact substeps would be 17 steps; the approach takes only a few
	EXPECT_LT(n, 17);
	EXPECT_GT(n, 6);  // 6.7 ms from arrival to the frame's end are substepped
	// no step that starts before the contact may carry the ball more than one substep into the wall
	double start = 0;
	for (double h : steps)
	{
		if (10.0 * start < 0.1)  // the step starts before the ball reaches the wall
		{
			const double depth = 10.0 * (start + h) - 0.1;  // how far past the face the ball is at the step's end
			EXPECT_LE(depth, 10.0 * 1e-3 + 1e-9) << "step of " << h << " s starting at " << start;
		}
		start += h;
	}
}

TEST(SubstepPolicy, FarFromContactAFrameIsOneStep)
{
	BallAndWall s(10.0, 1.0);
	plastic::ContactSubstepPolicy policy(plastic::ContactSubstepSettings{1e-5});
	EXPECT_EQ(policy.advance(1.0 / 60.0, [&](double h) { return s.near(h); }, [](double) {}), 1);
}

TEST(SubstepPolicy, BadSettingsAreRefusedByName)
{
	int steps = 0;
	const auto step = [&steps](double)
	{ steps++; };
	const auto far = [](double)
	{ return false; };
	const plastic::ContactSubstepPolicy negative(plastic::ContactSubstepSettings{-1e-3});
	EXPECT_EQ(1u, negative.errors().size());
	const plastic::ContactSubstepPolicy tooLong(plastic::ContactSubstepSettings{1.0});
	ASSERT_EQ(1u, tooLong.errors().size());
	EXPECT_NE(tooLong.errors().front().find("contact-substep: 1 is not in"), std::string::npos) << tooLong.errors().front();
	EXPECT_EQ(-1, tooLong.advance(1.0 / 60.0, far, step));  // refused settings step nothing
	plastic::ContactSubstepPolicy policy(plastic::ContactSubstepSettings{0});
	EXPECT_TRUE(policy.errors().empty());
	EXPECT_EQ(-1, policy.advance(0, far, step));
	EXPECT_EQ(-1, policy.advance(NAN, far, step));
	EXPECT_EQ(0, steps);
	EXPECT_EQ(1, policy.advance(1.0 / 60.0, far, step));
}
