// The collapse protocol on made-up rotations (no physics): a joint turning with the load is not a collapse, a
// runaway is, a held load that stops turning is loaded further, and the mechanism is what turned after the hold.
#include <gtest/gtest.h>

#include <cmath>

#include "CollapseTest.h"

using namespace structures;

namespace
{
// slow 0.02/s, fast 0.2/s up to 0.9 (the ramp's defaults: 0.9 of a collapse factor of 1), 0.05 rad/s over 0.1 s,
// 0.05 rad, hold 2 s
CollapseTest defaultTest() { return CollapseTest(CollapseRamp{}, 0.02, 1.0); }
}  // namespace

TEST(CollapseTest, ElasticTurningWithTheLoadIsNoCollapse)
{
	CollapseTest test = defaultTest();
	const double dt = 1e-3;
	for (int i = 1; i <= 20000; i++)  // 20 s: an elastic joint turning 0.1 rad per unit load factor
	{
		test.advance(dt);
		test.update(i * dt, {0.1 * test.factor(), 0.0});
	}
	EXPECT_FALSE(test.done());
	EXPECT_EQ(test.holds(), 0);
	EXPECT_NEAR(test.factor(), 0.9 + 0.02 * (20.0 - 4.5), 2e-4);  // the last fast step may pass 0.9 by up to 0.2 x 1 ms
}

TEST(CollapseTest, RunawayAboveOneIsTheCollapseWithItsJoints)
{
	CollapseTest test = defaultTest();
	const double dt = 1e-3;
	double theta = 0;  // a rigid-plastic mechanism: accelerates in proportion to the load above 1
	double omega = 0;
	int i = 0;
	while (!test.done() && i < 100000)
	{
		test.advance(dt);
		omega += 100 * std::max(0.0, test.factor() - 1.0) * dt;
		theta += omega * dt;
		test.update(++i * dt, {theta, 0.0, -2 * theta});
	}
	ASSERT_TRUE(test.done());
	EXPECT_GT(test.collapseFactor(), 1.0);
	EXPECT_LT(test.collapseFactor(), 1.01);
	EXPECT_EQ(test.mechanism({theta, 0.0, -2 * theta}), (std::vector<int>{0, 2}));
}

TEST(CollapseTest, SofteningThatStopsUnderAHeldLoadIsLoadedFurther)
{
	CollapseTest test = defaultTest();
	const double dt = 1e-3;
	int i = 0;
	// a joint that jumps 0.02 rad at 0.95 (a hinge forming elsewhere) and then stays, runaway above 1.1
	double omega = 0, runaway = 0;
	while (!test.done() && i < 200000)
	{
		test.advance(dt);
		omega += 100 * std::max(0.0, test.factor() - 1.1) * dt;
		runaway += omega * dt;
		const double step = test.factor() > 0.95 ? 0.02 : 0.0;
		test.update(++i * dt, {step + runaway});
	}
	ASSERT_TRUE(test.done());
	EXPECT_EQ(test.holds(), 2);
	EXPECT_GT(test.collapseFactor(), 1.1);
	EXPECT_LT(test.collapseFactor(), 1.11);
}
