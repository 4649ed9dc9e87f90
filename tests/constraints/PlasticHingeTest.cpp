// btPlasticHingeConstraint: moment cap, permanent set, energy balance, breaking.
#include <gtest/gtest.h>

#include <cmath>

#include "PhysicsWorld.h"

namespace
{
// A 1 kg bar (1.0 x 0.1 x 0.1 m) on a plastic hinge about world Y at its centre, attached to the world.
struct Lever
{
	PhysicsWorld w;
	btRigidBody* bar;
	btPlasticHingeConstraint* hinge;
	btJointFeedback feedback;
	double plasticMoment;

	explicit Lever(double mp) : plasticMoment(mp)
	{
		bar = w.addBox(btVector3(0.5, 0.05, 0.05), 1.0, btVector3(0, 0, 0));
		hinge = new btPlasticHingeConstraint(*bar, btVector3(0, 0, 0), btVector3(0, 1, 0));
		hinge->setPlasticMoment(btScalar(mp));
		hinge->setJointFeedback(&feedback);
		w.world.addConstraint(hinge);
	}
	~Lever()
	{
		w.world.removeConstraint(hinge);
		delete hinge;
	}
	// world rotation of the bar about Y, unwrapped by the caller
	double angle() const { return hinge->getHingeAngle(); }
	void step(double dt, double torque)
	{
		bar->applyTorque(btVector3(0, btScalar(torque), 0));
		w.world.stepSimulation(btScalar(dt), 0);
	}
};

double unwrap(double delta)
{
	while (delta > M_PI) delta -= 2 * M_PI;
	while (delta < -M_PI) delta += 2 * M_PI;
	return delta;
}

class PlasticHingeStep : public ::testing::TestWithParam<double>
{
};
}  // namespace

TEST_P(PlasticHingeStep, BelowPlasticMomentNoRotation)
{
	const double dt = GetParam();
	Lever lever(2.0);
	for (int i = 0; i < 200; i++) lever.step(dt, 1.0);  // half of Mp
	EXPECT_LT(std::fabs(lever.angle()), 1e-3);
	EXPECT_EQ(lever.hinge->getCurrentPlasticRotation(), 0.0);
	EXPECT_EQ(lever.hinge->getAbsorbedEnergy(), 0.0);
}

TEST_P(PlasticHingeStep, AbovePlasticMomentTransmitsAtMostMpAndAbsorbsMpTimesRotation)
{
	const double dt = GetParam();
	const double mp = 2.0;
	Lever lever(mp);
	double rotation = 0, previous = lever.angle(), maxMoment = 0;
	const int steps = static_cast<int>(std::ceil(0.5 / dt));
	for (int i = 0; i < steps; i++)
	{
		lever.step(dt, 3.0 * mp);
		maxMoment = std::max(maxMoment, std::fabs(double(lever.feedback.m_appliedTorqueBodyA.y())));
		rotation += std::fabs(unwrap(lever.angle() - previous));
		previous = lever.angle();
	}
	EXPECT_LE(maxMoment, mp * (1 + 1e-5)) << "joint feedback moment exceeds Mp";
	EXPECT_GT(maxMoment, mp * 0.999) << "the hinge should be at its cap while yielding";
	ASSERT_GT(rotation, 0.1);
	// booked in the step it happened: the rotation measured from the hinge angle, and Mp times it
	EXPECT_NEAR(lever.hinge->getCurrentPlasticRotation(), rotation, 1e-3 * rotation);
	EXPECT_NEAR(lever.hinge->getAbsorbedEnergy(), mp * rotation, 1e-3 * mp * rotation);
}

TEST_P(PlasticHingeStep, PermanentSetNoSpringBack)
{
	const double dt = GetParam();
	Lever lever(2.0);
	const int loading = static_cast<int>(std::ceil(0.3 / dt));
	for (int i = 0; i < loading; i++) lever.step(dt, 6.0);
	lever.bar->setAngularVelocity(btVector3(0, 0, 0));
	const double set = lever.angle();
	ASSERT_GT(std::fabs(set), 0.05);
	const int unloaded = static_cast<int>(std::ceil(1.0 / dt));
	for (int i = 0; i < unloaded; i++) lever.step(dt, 0);
	EXPECT_NEAR(lever.angle(), set, 1e-3) << "a plastic hinge must keep its new angle";
}

TEST_P(PlasticHingeStep, EnergyBalanceOfASpinningBodyStoppedByTheHinge)
{
	const double dt = GetParam();
	PhysicsWorld w;
	btRigidBody* wheel = w.addBox(btVector3(0.5, 0.05, 0.5), 1.0, btVector3(0, 0, 0));
	const double inertia = wheel->getLocalInertia().y();
	const double omega0 = 10.0, stopTime = 3.0;
	const double mp = inertia * omega0 / stopTime;
	auto* hinge = new btPlasticHingeConstraint(*wheel, btVector3(0, 0, 0), btVector3(0, 1, 0));
	hinge->setPlasticMoment(btScalar(mp));
	w.world.addConstraint(hinge);
	wheel->setAngularVelocity(btVector3(0, btScalar(omega0), 0));
	const double ke0 = w.kineticEnergy(wheel);
	for (double t = 0; t < stopTime * 1.2; t += dt) w.world.stepSimulation(btScalar(dt), 0);
	w.world.stepSimulation(btScalar(dt), 0);
	const double lost = ke0 - w.kineticEnergy(wheel);
	EXPECT_NEAR(hinge->getAbsorbedEnergy(), lost, 0.01 * lost) << "dt " << dt;
	EXPECT_NEAR(lost, ke0, 1e-6 * ke0) << "the wheel must stop";
	w.world.removeConstraint(hinge);
	delete hinge;
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, PlasticHingeStep, ::testing::Values(1e-5, 1e-4, 1e-3, 1.0 / 60.0));

TEST(PlasticHinge, BreaksAtMaxPlasticRotationBothSignsAndAcrossPi)
{
	const double dt = 1e-3, mp = 2.0;
	for (double sign : {1.0, -1.0})
	{
		for (double maxRotation : {0.5, 4.0})  // 4 rad crosses +/-pi
		{
			Lever lever(mp);
			lever.hinge->setMaxPlasticRotation(btScalar(maxRotation));
			double rotation = 0, previous = lever.angle();
			int steps = 0;
			while (lever.hinge->isEnabled() && steps < 100000)
			{
				lever.step(dt, sign * 3.0 * mp);
				rotation += std::fabs(unwrap(lever.angle() - previous));
				previous = lever.angle();
				steps++;
			}
			ASSERT_FALSE(lever.hinge->isEnabled()) << "sign " << sign << " max " << maxRotation;
			const double lastStep = std::fabs(lever.bar->getAngularVelocity().y()) * dt;
			EXPECT_GE(lever.hinge->getCurrentPlasticRotation(), maxRotation);
			EXPECT_LE(lever.hinge->getCurrentPlasticRotation(), maxRotation + lastStep + 1e-9);
			EXPECT_NEAR(lever.hinge->getCurrentPlasticRotation(), rotation, lastStep + 0.01 * rotation);
		}
	}
}

TEST(PlasticHinge, RejectsInvalidArgumentsAndKeepsItsValues)
{
#ifdef NDEBUG
	Lever lever(2.0);
	lever.hinge->setPlasticMoment(btScalar(-1));
	lever.hinge->setPlasticMoment(btScalar(NAN));
	lever.hinge->setMaxPlasticRotation(btScalar(0));
	EXPECT_EQ(lever.hinge->getPlasticMoment(), btScalar(2.0));
	EXPECT_EQ(lever.hinge->getMaxPlasticRotation(), SIMD_INFINITY);
	for (int i = 0; i < 100; i++) lever.step(1e-3, 6.0);
	EXPECT_TRUE(std::isfinite(lever.angle()));
#else
	GTEST_SKIP() << "debug builds assert on invalid arguments";
#endif
}
