// Springs of parallel layers that harden (patch 0028, bt6DofElasticPlastic2Constraint::setHardeningLayers), against the
// closed forms of a bilinear spring with kinematic hardening. One body on a constraint to the world, every DOF locked
// but the twist about z, which is a layer of k1 = 1000 N m/rad yielding at c1 = 10 N m beside an elastic layer of
// k2 = 100 N m/rad: elastic stiffness K = 1100 N m/rad up to My = K c1 / k1 = 11 N m, then k2. A torque about z rises
// and falls slowly (16 s ramps, the spring's period is 0.16 s) and each level is held 2 s; the angle is averaged over
// the last second of each hold. Kinematic hardening (Masing): after loading to +20 N m the spring unloads with K and
// yields again at 20 - 2 My = -2 N m, so at -20 N m it is back at -0.1 rad; isotropic hardening would reach only
// 0.0636 rad. Dissipation: layer 1 flows 0.09 rad on the way up and 0.18 rad on the way down, at 10 N m: 2.7 J.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "BulletDynamics/ConstraintSolver/bt6DofElasticPlastic2Constraint.h"
#include "PhysicsWorld.h"

namespace
{
const double kStep = 1.0 / 240.0;
const double kLayerStiffness = 1000, kLayerCap = 10, kElasticStiffness = 100;
const double kYieldMoment = (kLayerStiffness + kElasticStiffness) * kLayerCap / kLayerStiffness;  // 11 N m
const double kLinearScale = 150.0;  // the box's mass over its moment of inertia, 100 kg / (100 x 0.2^2 / 6) kg m^2

struct Twist
{
	std::unique_ptr<bt6DofElasticPlastic2Constraint> joint;  // outlives the world, which removes it
	PhysicsWorld w;
	btRigidBody* body = nullptr;
	double workJ = 0;
	double torqueNm = 0;

	// layers 4: the same law on the linear DOF along x, stiffnesses and forces 150 times (N/m, N: the body's mass is 150
	// times its moment of inertia, 100 kg against 0.667 kg m^2, so its motion is the twist's), the force 150 times
	bool linear = false;

	// layers: 2 (kinematic: a yielding layer beside an elastic one), 1 (one EPP spring, the control), 3 (isotropic: one
	// layer of the whole stiffness whose cap grows by 110 N m/rad of its flow, a post-yield slope of 100 N m/rad), 4 (2
	// on the linear DOF along x)
	explicit Twist(int layers) : linear(layers == 4)
	{
		body = w.addBox(btVector3(0.1, 0.1, 0.1), 100.0, btVector3(0, 0, 0));
		joint.reset(new bt6DofElasticPlastic2Constraint(*body, btTransform::getIdentity()));
		for (int i = 0; i < 6; i++)
		{
			joint->setStiffness(i, 0, false);  // rigid-plastic locks that never yield here
			joint->setMaxForce(i, btScalar(1e6));
		}
		const btScalar k[2] = {btScalar(kLayerStiffness), btScalar(kElasticStiffness)};
		const btScalar c[2] = {btScalar(kLayerCap), SIMD_INFINITY};
		if (layers == 2)
		{
			joint->setHardeningLayers(5, 2, k, c);
		}
		else if (layers == 4)
		{
			const btScalar kx[2] = {btScalar(kLinearScale * kLayerStiffness), btScalar(kLinearScale * kElasticStiffness)};
			const btScalar cx[2] = {btScalar(kLinearScale * kLayerCap), SIMD_INFINITY};
			joint->setHardeningLayers(0, 2, kx, cx);
		}
		else if (layers == 3)
		{
			const btScalar whole[1] = {btScalar(kLayerStiffness + kElasticStiffness)};
			const btScalar cap[1] = {btScalar(kYieldMoment)};
			const btScalar growth[1] = {btScalar(110)};
			joint->setHardeningLayers(5, 1, whole, cap, growth);
		}
		else
		{
			// control: the same DOF as one elastic-perfectly plastic spring of the whole stiffness, capped at My
			joint->setStiffness(5, btScalar(kLayerStiffness + kElasticStiffness), false);
			joint->setMaxForce(5, btScalar(kYieldMoment));
		}
		w.world.addConstraint(joint.get(), true);
	}
	void step()
	{
		if (linear)
		{
			body->applyCentralForce(btVector3(btScalar(kLinearScale * torqueNm), 0, 0));
			w.world.stepSimulation(btScalar(kStep), 0);
			workJ += kLinearScale * torqueNm * double(body->getLinearVelocity().x()) * kStep;
			return;
		}
		body->applyTorque(btVector3(0, 0, btScalar(torqueNm)));
		w.world.stepSimulation(btScalar(kStep), 0);
		workJ += torqueNm * double(body->getAngularVelocity().z()) * kStep;
	}
	// rad (Spring2 measures the twist the other way), or m along x for the linear DOF
	double angle() const { return linear ? double(body->getCenterOfMassPosition().x()) : -double(joint->getAngle(2)); }
	// ramps the torque to target over 16 s, holds it 2 s; the mean angle over the last second
	double rampTo(double target)
	{
		const double start = torqueNm;
		const int ramp = int(16.0 / kStep), hold = int(2.0 / kStep);
		for (int i = 1; i <= ramp; i++)
		{
			torqueNm = start + (target - start) * i / ramp;
			step();
		}
		double sum = 0;
		int n = 0;
		for (int i = 0; i < hold; i++)
		{
			step();
			if (i >= hold / 2)
			{
				sum += angle();
				n++;
			}
		}
		return sum / n;
	}
};
}  // namespace

TEST(Hardening, LayersFollowTheBilinearKinematicLaw)
{
	Twist t(2);
	ASSERT_EQ(2, t.joint->getNumHardeningLayers(5));
	EXPECT_EQ(btScalar(kLayerStiffness + kElasticStiffness), t.joint->getRotationalLimitMotor(2)->m_springStiffness) << "the DOF's stiffness is the layers' sum";
	const double K = kLayerStiffness + kElasticStiffness;
	const double elastic = t.rampTo(8.0);
	EXPECT_NEAR(elastic, 8.0 / K, 0.02 * 8.0 / K) << "below My the spring is elastic with K";
	const double up = t.rampTo(20.0);
	const double upExpected = kYieldMoment / K + (20.0 - kYieldMoment) / kElasticStiffness;  // 0.1 rad
	EXPECT_NEAR(up, upExpected, 0.02 * upExpected) << "above My it hardens with k2";
	const double unloaded = t.rampTo(0.0);
	const double setExpected = upExpected - 20.0 / K;  // 0.0818 rad: unloads with K
	EXPECT_NEAR(unloaded, setExpected, 0.02 * setExpected) << "the permanent set";
	EXPECT_NEAR(-double(t.joint->getRotationalLimitMotor(2)->m_equilibriumPoint), setExpected, 0.02 * setExpected) << "the equilibrium point is the set";
	const double down = t.rampTo(-20.0);
	EXPECT_NEAR(down, -upExpected, 0.02 * upExpected) << "reversed, it yields again at 20 - 2 My = -2 N m (Bauschinger)";
	const double isotropic = setExpected - 20.0 / K;
	EXPECT_LT(down, isotropic - 0.1) << "not at the isotropic answer " << isotropic;
	// the books: layer 1 flowed 0.09 + 0.18 rad at 10 N m; against the torque's work measured from the body's motion
	const double dissipated = kLayerCap * (2 * (upExpected - kLayerCap / kLayerStiffness) + (upExpected - kLayerCap / kLayerStiffness));
	const double booked = double(t.joint->getAbsorbedEnergy());
	EXPECT_NEAR(booked, dissipated, 0.03 * dissipated);
	const double elasticEnd = double(t.joint->getElasticEnergy());
	const double kinetic = t.w.kineticEnergy(t.body);
	EXPECT_NEAR(t.workJ, booked + elasticEnd + kinetic, 0.03 * t.workJ) << "work = dissipated + elastic + kinetic";
	// the plastic rotation is the motion of the zero-force position: 0.0818 up, 0.1636 down
	EXPECT_NEAR(double(t.joint->getCurrentPlasticRotation()), 3 * setExpected, 0.03 * 3 * setExpected);
	std::printf("[ info     ] angles %.5f (elastic, %.5f), %.5f (%.5f), set %.5f (%.5f), %.5f (%.5f; isotropic %.5f); booked %.4f J (%.4f), "
				"work %.4f J, elastic %.4f J, kinetic %.2e J; plastic rotation %.4f rad\n",
				elastic, 8.0 / K, up, upExpected, unloaded, setExpected, down, -upExpected, isotropic, booked, dissipated, t.workJ, elasticEnd, kinetic,
				double(t.joint->getCurrentPlasticRotation()));
}

// The same law on a linear DOF (patch 0028 keeps a linear DOF's equilibrium point apart from the step's spring):
// 0.1 m at 3000 N, a set of 0.0818 m, -0.1 m at -3000 N, and 150 times the twist's dissipation, 405 J.
TEST(Hardening, ALinearDofFollowsTheSameLaw)
{
	Twist t(4);
	const double K = kLayerStiffness + kElasticStiffness;
	const double up = t.rampTo(20.0);
	const double upExpected = kYieldMoment / K + (20.0 - kYieldMoment) / kElasticStiffness;
	EXPECT_NEAR(up, upExpected, 0.02 * upExpected);
	const double unloaded = t.rampTo(0.0);
	EXPECT_NEAR(unloaded, upExpected - 20.0 / K, 0.02 * upExpected);
	EXPECT_NEAR(double(t.joint->getTranslationalLimitMotor()->m_equilibriumPoint[0]), unloaded, 0.02 * upExpected)
		<< "the equilibrium point is the set";
	const double down = t.rampTo(-20.0);
	EXPECT_NEAR(down, -upExpected, 0.02 * upExpected);
	const double dissipated = kLinearScale * kLayerCap * 3 * (upExpected - kLayerCap / kLayerStiffness);
	EXPECT_NEAR(double(t.joint->getAbsorbedEnergy()), dissipated, 0.03 * dissipated);
	EXPECT_NEAR(t.workJ, double(t.joint->getAbsorbedEnergy()) + double(t.joint->getElasticEnergy()) + t.w.kineticEnergy(t.body), 0.03 * t.workJ);
	std::printf("[ info     ] linear: %.5f, set %.5f (equilibrium %.5f), %.5f m; booked %.2f J (%.2f)\n", up, unloaded,
				double(t.joint->getTranslationalLimitMotor()->m_equilibriumPoint[0]), down, double(t.joint->getAbsorbedEnergy()), dissipated);
}

// Isotropic hardening: the same elastic stiffness, first yield and post-yield slope (1100 N m/rad to 11 N m, then 100)
// with the cap growing instead of a back force. Loaded to 20 N m it is at 0.1 rad and unloads to 0.0818 rad as the
// kinematic one does; reversed to -20 N m it does not yield again (its cap has grown to 20 N m): 0.0636 rad, where the
// kinematic layers reached -0.1. It books the work of its growing cap over its flow, 11 x 0.0818 + 110 x 0.0818^2 / 2
// = 1.268 J.
TEST(Hardening, AnIsotropicLayerYieldsAgainOnlyAtItsGrownCap)
{
	Twist t(3);
	const double K = kLayerStiffness + kElasticStiffness;
	const double up = t.rampTo(20.0);
	const double upExpected = kYieldMoment / K + (20.0 - kYieldMoment) / kElasticStiffness;
	EXPECT_NEAR(up, upExpected, 0.02 * upExpected);
	const double unloaded = t.rampTo(0.0);
	const double setExpected = upExpected - 20.0 / K;
	EXPECT_NEAR(unloaded, setExpected, 0.02 * setExpected);
	const double down = t.rampTo(-20.0);
	EXPECT_NEAR(down, setExpected - 20.0 / K, 0.03 * setExpected) << "no reverse yield before -20 N m";
	const double flow = (20.0 - kYieldMoment) / 110.0;
	const double dissipated = kYieldMoment * flow + 0.5 * 110.0 * flow * flow;
	const double booked = double(t.joint->getAbsorbedEnergy());
	EXPECT_NEAR(booked, dissipated, 0.03 * dissipated);
	EXPECT_NEAR(t.workJ, booked + double(t.joint->getElasticEnergy()) + t.w.kineticEnergy(t.body), 0.03 * t.workJ);
	std::printf("[ info     ] isotropic: %.5f (%.5f), set %.5f (%.5f), %.5f (%.5f); booked %.4f J (%.4f), work %.4f J\n", up, upExpected, unloaded,
				setExpected, down, setExpected - 20.0 / K, booked, dissipated, t.workJ);
}

// Control: one elastic-perfectly plastic spring of the same elastic stiffness and yield moment does not harden: at
// 11.5 N m it keeps turning, where the layers stop 0.005 rad past My.
TEST(Hardening, WithoutLayersTheSpringDoesNotHarden)
{
	Twist t(1);
	EXPECT_EQ(0, t.joint->getNumHardeningLayers(5));
	t.rampTo(10.0);
	const double before = t.angle();
	t.torqueNm = 11.5;
	for (int i = 0; i < int(1.0 / kStep); i++) t.step();
	EXPECT_GT(t.angle() - before, 0.2) << "above its cap an EPP spring keeps turning";
	// the layers at the same torque stop 0.005 rad past My
	Twist layered(2);
	layered.rampTo(10.0);
	const double layeredBefore = layered.angle();
	layered.torqueNm = 11.5;
	for (int i = 0; i < int(1.0 / kStep); i++) layered.step();
	EXPECT_LT(layered.angle() - layeredBefore, 0.02) << "the layers harden";
	std::printf("[ info     ] 1 s at 11.5 N m after 10 N m: one EPP spring turned %.4f rad, the layers %.4f rad\n", t.angle() - before,
				layered.angle() - layeredBefore);
}

// Rejected layers keep the previous ones (release builds); none with no finite cap, none with a stiffness <= 0.
TEST(Hardening, BadLayersAreRefused)
{
#ifdef NDEBUG
	Twist t(2);
	const btScalar k[2] = {btScalar(1000), btScalar(-1)};
	const btScalar c[2] = {btScalar(10), SIMD_INFINITY};
	t.joint->setHardeningLayers(5, 2, k, c);
	EXPECT_EQ(2, t.joint->getNumHardeningLayers(5));
	const btScalar k2[1] = {btScalar(1000)};
	const btScalar c2[1] = {SIMD_INFINITY};
	t.joint->setHardeningLayers(5, 1, k2, c2);
	EXPECT_EQ(2, t.joint->getNumHardeningLayers(5)) << "a DOF of layers needs one that yields";
	t.joint->setHardeningLayers(6, 1, k, c);
	t.joint->setHardeningLayers(5, bt6DofElasticPlastic2Constraint::MAX_HARDENING_LAYERS + 1, k, c);
	EXPECT_EQ(2, t.joint->getNumHardeningLayers(5));
	EXPECT_EQ(0, t.joint->getNumHardeningLayers(6));
#else
	GTEST_SKIP() << "debug builds assert";
#endif
}
