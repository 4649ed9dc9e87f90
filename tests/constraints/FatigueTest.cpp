// Low-cycle fatigue (patch 0030, btPlasticConstraintSettings::m_fatigueDuctilityRotation): a lever on a plastic joint
// to the world is bent back and forth through +-A about z by a kinematic hand whose rotation is locked to it (a driven angle, as fingers
// bend a paper clip), theta(t) = A sin(2 pi t / T). The answers come from the driven angle alone, not from the joint:
// a rigid-plastic hinge's plastic rotation is the whole rotation, so its half-cycles have ranges A, 2A, 2A, ... and
// Coffin-Manson with Miner's rule, dtheta / 2 = theta_f (2 N) ^ c, gives the angle at which the damage reaches 1. A
// spring of layers (a yielding layer k1, c1 beside an elastic k2) moves its zero-force position by k1 / K of layer
// 1's flow, which under an imposed rotation is A - c1 / k1, then 2 (A - c1 / k1) per half-cycle. The work is measured
// from the hand's lock (its torque on the lever times the hand's rotation), apart from what the joint books.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "BulletDynamics/ConstraintSolver/bt6DofElasticPlastic2Constraint.h"
#include "BulletDynamics/ConstraintSolver/btPlasticHingeConstraint.h"
#include "PhysicsWorld.h"

namespace
{
const double kPi = 3.14159265358979323846;
const double kPeriodS = 2.0;
const double kAmplitudeRad = 0.3;
const double kDuctilityRad = 0.5;  // theta_f
const double kExponent = -0.5;     // c: a half-cycle of range r uses (r / (2 theta_f))^2

// the driven angle at time t
double drivenAngle(double t) { return kAmplitudeRad * std::sin(2 * kPi * t / kPeriodS); }

// The damage of a plastic rotation history sampled at steps: Miner's sum over half-cycles cut at reversals, the open
// one included. Written from the rule's statement, for the driven angles.
struct DamageOfPath
{
	double closed = 0, open = 0;
	double flowOf(double range) const { return std::pow(range / (2 * kDuctilityRad), -1 / kExponent); }
	void add(double flow)
	{
		if (flow == 0) return;
		if (open * flow < 0)
		{
			closed += flowOf(std::fabs(open));
			open = 0;
		}
		open += flow;
	}
	double damage() const { return closed + flowOf(std::fabs(open)); }
};

struct BentLever
{
	PhysicsWorld w;
	std::unique_ptr<btTypedConstraint> joint;  // the plastic joint, lever to world at the origin, about z
	std::unique_ptr<btGeneric6DofConstraint> lock;
	std::unique_ptr<btDefaultMotionState> handMotion;
	std::unique_ptr<btBoxShape> handShape;
	std::unique_ptr<btRigidBody> hand;
	btJointFeedback feedback;
	btRigidBody* lever = nullptr;
	double step = 1.0 / 240.0;
	double t = 0;
	double workJ = 0;  // by the hand on the lever

	// hinge: a btPlasticHingeConstraint of Mp = 10 N m; else a bt6DofElasticPlastic2Constraint whose twist is layers
	// (1000 N m/rad to 10 N m beside 100 N m/rad)
	BentLever(bool hinge, double stepS, bool fatigue) : step(stepS)
	{
		lever = w.addBox(btVector3(0.5, 0.02, 0.02), 1.0, btVector3(0.5, 0, 0));
		if (hinge)
		{
			auto* h = new btPlasticHingeConstraint(*lever, btVector3(-0.5, 0, 0), btVector3(0, 0, 1));
			h->setPlasticMoment(10);
			joint.reset(h);
		}
		else
		{
			btTransform frame(btQuaternion::getIdentity(), btVector3(-0.5, 0, 0));
			auto* j = new bt6DofElasticPlastic2Constraint(*lever, frame);
			for (int i = 0; i < 6; i++)
			{
				j->setStiffness(i, 0, false);
				j->setMaxForce(i, btScalar(1e6));
			}
			const btScalar k[2] = {1000, 100};
			const btScalar c[2] = {10, SIMD_INFINITY};
			j->setHardeningLayers(5, 2, k, c);
			joint.reset(j);
		}
		if (fatigue)
		{
			btPlasticConstraintSettings s = settings();
			s.m_fatigueDuctilityRotation = btScalar(kDuctilityRad);
			s.m_fatigueDuctilityExponent = btScalar(kExponent);
			EXPECT_TRUE(setSettings(s));
		}
		w.world.addConstraint(joint.get(), true);
		// the hand: kinematic, about the origin, its rotation locked to the lever's
		handShape = std::make_unique<btBoxShape>(btVector3(0.05, 0.05, 0.05));
		handMotion = std::make_unique<btDefaultMotionState>(btTransform::getIdentity());
		hand = std::make_unique<btRigidBody>(0, handMotion.get(), handShape.get());
		hand->setCollisionFlags(hand->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
		hand->setActivationState(DISABLE_DEACTIVATION);
		w.world.addRigidBody(hand.get(), 0, 0);
		btTransform inHand(btQuaternion::getIdentity(), btVector3(0.5, 0, 0)), inLever = btTransform::getIdentity();
		lock = std::make_unique<btGeneric6DofConstraint>(*hand, *lever, inHand, inLever, true);
		// the hand turns the lever and leaves its position to the joint (the linear DOFs free: lower above upper)
		lock->setLinearLowerLimit(btVector3(1, 1, 1));
		lock->setLinearUpperLimit(btVector3(-1, -1, -1));
		lock->setAngularLowerLimit(btVector3(0, 0, 0));
		lock->setAngularUpperLimit(btVector3(0, 0, 0));
		lock->setJointFeedback(&feedback);
		w.world.addConstraint(lock.get(), true);
		// the lever starts turning with the hand (no impulsive start)
		const double spin = 2 * kPi * kAmplitudeRad / kPeriodS;
		lever->setAngularVelocity(btVector3(0, 0, btScalar(spin)));
		lever->setLinearVelocity(btVector3(0, btScalar(0.5 * spin), 0));
	}
	~BentLever()
	{
		// the constraints go before the world's destructor, which would remove them after their members are gone
		w.world.removeConstraint(lock.get());
		w.world.removeConstraint(joint.get());
		w.world.removeRigidBody(hand.get());
	}
	const btPlasticConstraintState& state() const
	{
		if (auto* h = dynamic_cast<btPlasticHingeConstraint*>(joint.get())) return h->getPlasticState();
		return static_cast<bt6DofElasticPlastic2Constraint*>(joint.get())->getPlasticState();
	}
	btPlasticConstraintSettings settings() const { return state().getSettings(); }
	bool setSettings(const btPlasticConstraintSettings& s)
	{
		if (auto* h = dynamic_cast<btPlasticHingeConstraint*>(joint.get())) return h->setPlasticSettings(s);
		return static_cast<bt6DofElasticPlastic2Constraint*>(joint.get())->setPlasticSettings(s);
	}
	double leverAngle() const
	{
		btVector3 x = lever->getWorldTransform().getBasis().getColumn(0);
		return std::atan2(double(x.y()), double(x.x()));
	}
	void advance()
	{
		const double before = drivenAngle(t);
		t += step;
		handMotion->setWorldTransform(btTransform(btQuaternion(btVector3(0, 0, 1), btScalar(drivenAngle(t)))));
		w.world.stepSimulation(btScalar(step), 0);
		// the hand's torque on the lever times the hand's own rotation in the step (the driver's displacement)
		workJ += double(feedback.m_appliedTorqueBodyB.z()) * (drivenAngle(t) - before);
	}
};
}  // namespace

// Rigid-plastic: the half-cycles are 0.3, 0.6, 0.6 rad, using 0.09, 0.36 and 0.36 of the life; the damage reaches 1
// 0.436 rad into the third full swing, at 3.149 s. The hinge breaks within a step's rotation of that angle, and its damage follows
// the driven path's at every quarter period before.
TEST(Fatigue, ARigidPlasticHingeBreaksWhereCoffinMansonSays)
{
	BentLever b(true, 1.0 / 240.0, true);
	DamageOfPath path;
	double previous = 0, breakTime = -1, expectedBreak = -1;
	int checks = 0;
	while (b.t < 4 * kPeriodS && breakTime < 0)
	{
		b.advance();
		const double driven = drivenAngle(b.t);
		path.add(driven - previous);
		previous = driven;
		if (expectedBreak < 0 && path.damage() >= 1) expectedBreak = b.t;
		if (!b.joint->isEnabled()) breakTime = b.t;
		const double quarter = std::fmod(b.t, kPeriodS / 4);
		if (b.joint->isEnabled() && (quarter < b.step * 0.5 || kPeriodS / 4 - quarter < b.step * 0.5) && b.t > 0.1)
		{
			EXPECT_NEAR(double(b.state().getFatigueDamage()), path.damage(), 0.02) << "at t = " << b.t;
			checks++;
		}
	}
	// 0.09 + 0.36 + 0.36 = 0.81 at t = 2.5 s (at +A); 0.19 more is a range of 0.436 rad: the angle falls to
	// 0.3 - 0.436 = A cos(2 pi (t - 2.5) / T) at t = 2.5 + acos(-0.453) T / (2 pi) = 3.149 s
	const double range = 2 * kDuctilityRad * std::sqrt(1 - 0.09 - 0.72);
	const double closedForm = 2.5 + std::acos((kAmplitudeRad - range) / kAmplitudeRad) * kPeriodS / (2 * kPi);
	EXPECT_GE(checks, 6);
	EXPECT_NEAR(expectedBreak, closedForm, 2 * b.step) << "the test's own sum against the closed form";
	ASSERT_GT(breakTime, 0) << "did not break";
	EXPECT_NEAR(breakTime, closedForm, 3 * b.step);
	std::printf("[ info     ] broke at %.4f s (Coffin-Manson on the driven angle %.4f s, closed form %.4f s), damage %.4f, plastic rotation %.4f rad\n", breakTime,
				expectedBreak, closedForm, double(b.state().getFatigueDamage()), double(b.state().getCurrentPlasticRotation()));
}

// Without fatigue settings the same bending never breaks the hinge, and the work the hand does balances the plastic
// work booked, Mp times the rotation path (4 swings of 0.6 rad a period, 4 periods), and the lever's kinetic energy.
TEST(Fatigue, WithoutTheRuleTheHingeBendsOnAndBooksTheHandsWork)
{
	BentLever b(true, 1.0 / 240.0, false);
	const double startKinetic = b.w.kineticEnergy(b.lever);
	while (b.t < 4 * kPeriodS) b.advance();
	EXPECT_TRUE(b.joint->isEnabled());
	EXPECT_EQ(0.0, double(b.state().getFatigueDamage()));
	const double path = 4 * 4 * kAmplitudeRad;
	EXPECT_NEAR(double(b.state().getCurrentPlasticRotation()), path, 0.01 * path);
	const double booked = double(b.state().getAbsorbedEnergy());
	EXPECT_NEAR(b.workJ, booked + b.w.kineticEnergy(b.lever) - startKinetic, 0.01 * b.workJ) << "the hand's work against the books";
	EXPECT_NEAR(booked, 10 * path, 0.01 * 10 * path);
	std::printf("[ info     ] no fatigue: plastic rotation %.4f rad (path %.4f), booked %.3f J, hand's work %.3f J\n", double(b.state().getCurrentPlasticRotation()),
				path, booked, b.workJ);
}

// Hardening layers (kinematic, Masing): the zero-force position moves 1000/1100 of layer 1's flow, 0.29 rad then 0.58
// rad per half-cycle: ranges 0.2636, 0.5273, ... using 0.0695, 0.278, 0.278, ...: the damage reaches 1 in the fourth
// swing, later than the rigid-plastic hinge's third. Each full period after the first quarter, layer 1 flows
// 4 (A - c1 / k1) = 1.16 rad at 10 N m: 11.6 J. The energy balances through the cycles at each zero crossing (hand's
// work = booked + elastic + kinetic - the lever's kinetic energy at the start, within 1 %). The springs' force is that of the step's start (explicit), so the
// hand does 1/2 K sum(dtheta^2) less work per cycle than the books say: 0.18 J a period (1.5 %) at 2400 Hz, a
// quarter of that at 9600 Hz, the step used here.
TEST(Fatigue, HardeningLayersCountTheirPlasticRotation)
{
	BentLever b(false, 1.0 / 9600.0, true);
	const double share = 1000.0 / 1100.0, elasticRange = 10.0 / 1000.0;
	DamageOfPath path;
	// layer 1 under the imposed angle: an elastic-perfectly plastic spring of range +-0.01 rad
	double layerSet = 0, breakTime = -1, expectedBreak = -1, bookedAt2s = 0;
	int crossings = 0;
	const double startBooks = b.w.kineticEnergy(b.lever);
	while (b.t < 4 * kPeriodS && breakTime < 0)
	{
		b.advance();
		const double driven = drivenAngle(b.t);
		double excess = driven - layerSet;
		double flow = 0;
		if (excess > elasticRange) flow = excess - elasticRange;
		if (excess < -elasticRange) flow = excess + elasticRange;
		layerSet += flow;
		path.add(share * flow);
		if (expectedBreak < 0 && path.damage() >= 1) expectedBreak = b.t;
		if (!b.joint->isEnabled())
		{
			breakTime = b.t;
			break;
		}
		const double half = std::fmod(b.t, kPeriodS / 2);
		if (half < b.step * 0.5 || kPeriodS / 2 - half < b.step * 0.5)
		{
			// a zero crossing: t = 1, 2, 3, 4 s
			const double booked = double(b.state().getAbsorbedEnergy());
			const double books = booked + double(b.state().getElasticEnergy()) + b.w.kineticEnergy(b.lever) - startBooks;
			EXPECT_NEAR(b.workJ, books, 0.01 * b.workJ) << "at t = " << b.t;
			if (std::fabs(b.t - 2) < b.step) bookedAt2s = booked;
			if (std::fabs(b.t - 4) < b.step)
			{
				EXPECT_NEAR(booked - bookedAt2s, 11.6, 0.01 * 11.6) << "a period's dissipation";
			}
			std::printf("[ info     ] t %.3f s: hand's work %.4f J, booked %.4f + elastic %.4f + kinetic %.4f J\n", b.t, b.workJ, booked,
						double(b.state().getElasticEnergy()), b.w.kineticEnergy(b.lever));
			crossings++;
		}
	}
	EXPECT_EQ(4, crossings);
	ASSERT_GT(expectedBreak, 0);
	EXPECT_GT(expectedBreak, 3.0) << "the layers' set is smaller than the rigid hinge's: a later break";
	ASSERT_GT(breakTime, 0) << "did not break";
	EXPECT_NEAR(breakTime, expectedBreak, 0.01 * kPeriodS);
	std::printf("[ info     ] layers broke at %.4f s (the rule on the driven angle %.4f s), damage %.4f\n", breakTime, expectedBreak,
				double(b.state().getFatigueDamage()));
}

// Settings out of range are refused whole, by name of the field's range: c outside [-1, -0.1], theta_f <= 0 or NaN.
TEST(Fatigue, SettingsOutOfRangeAreRefused)
{
	btPlasticConstraintSettings s;
	EXPECT_TRUE(s.isValid());
	EXPECT_FALSE(s.m_fatigueDuctilityRotation < SIMD_INFINITY) << "off by default";
	s.m_fatigueDuctilityRotation = btScalar(0.5);
	EXPECT_TRUE(s.isValid());
	for (double c : {0.0, -0.05, -1.5, 0.5, double(NAN)})
	{
		btPlasticConstraintSettings bad = s;
		bad.m_fatigueDuctilityExponent = btScalar(c);
		EXPECT_FALSE(bad.isValid()) << "exponent " << c;
	}
	for (double r : {0.0, -1.0, double(NAN)})
	{
		btPlasticConstraintSettings bad = s;
		bad.m_fatigueDuctilityRotation = btScalar(r);
		EXPECT_FALSE(bad.isValid()) << "rotation " << r;
	}
	BentLever b(true, 1.0 / 240.0, false);
	btPlasticConstraintSettings bad = b.settings();
	bad.m_fatigueDuctilityExponent = btScalar(-2);
	EXPECT_FALSE(b.setSettings(bad));
	EXPECT_EQ(btScalar(-0.6), b.settings().m_fatigueDuctilityExponent) << "kept";
}
