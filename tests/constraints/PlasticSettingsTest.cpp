// Issue 21, design review: the plastic constraints' settings apart from their results. btPlasticConstraintSettings
// (patch 0005) holds the four settings the three classes share; isValid() is the one check of them, and
// setPlasticSettings takes settings whole or not at all. Checked here: each field's range as the header documents it
// (edges, NaN, infinities), every class keeping all four settings when one field of a new set is bad, and settings
// given whole acting in the step as the same values given field by field do (a bar driven by 3 Mp breaks at the limit
// given either way, in the same step and bit for bit; the control with the default settings never breaks).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "BulletDynamics/ConstraintSolver/bt6DofElasticPlastic2Constraint.h"
#include "BulletDynamics/ConstraintSolver/bt6DofElasticPlasticConstraint.h"
#include "PhysicsWorld.h"

namespace
{
constexpr double kMp = 2.0;  // N m

btPlasticConstraintSettings nonDefaultSettings()
{
	btPlasticConstraintSettings s;
	s.m_maxPlasticDisplacement = btScalar(0.05);
	s.m_maxPlasticRotation = btScalar(0.3);
	s.m_yieldTolerance = btScalar(0.002);
	s.m_minStepsPerPeriod = btScalar(40);
	return s;
}

void expectSettings(const btPlasticConstraintSettings& expected, const btPlasticConstraintSettings& actual, const std::string& what)
{
	EXPECT_EQ(expected.m_maxPlasticDisplacement, actual.m_maxPlasticDisplacement) << what;
	EXPECT_EQ(expected.m_maxPlasticRotation, actual.m_maxPlasticRotation) << what;
	EXPECT_EQ(expected.m_yieldTolerance, actual.m_yieldTolerance) << what;
	EXPECT_EQ(expected.m_minStepsPerPeriod, actual.m_minStepsPerPeriod) << what;
}

// A 1 kg bar held to the world by a rigid-plastic joint of one class about one axis (Mp = 2 N m), its settings given
// whole (setPlasticSettings) or field by field (the single setters).
struct Bar
{
	PhysicsWorld w;
	btRigidBody* body = nullptr;
	btTypedConstraint* constraint = nullptr;
	btVector3 moment;

	Bar(const std::string& kind, const btPlasticConstraintSettings* whole, const btPlasticConstraintSettings* fields)
	{
		if (kind == "plastic_hinge")
		{
			body = w.addBox(btVector3(0.5, 0.05, 0.05), 1.0, btVector3(0, 0, 0));
			auto* h = new btPlasticHingeConstraint(*body, btVector3(0, 0, 0), btVector3(0, 0, 1));
			h->setPlasticMoment(btScalar(kMp));
			if (whole)
			{
				EXPECT_TRUE(h->setPlasticSettings(*whole));
			}
			if (fields)
			{
				h->setMaxPlasticRotation(fields->m_maxPlasticRotation);
				h->setYieldTolerance(fields->m_yieldTolerance);
			}
			constraint = h;
			moment = btVector3(0, 0, btScalar(3 * kMp));
		}
		else
		{
			body = w.addBox(btVector3(0.05, 0.05, 0.5), 1.0, btVector3(0, 0, 0));
			const btTransform frame = btTransform::getIdentity();
			if (kind == "elastic_plastic2")
			{
				auto* c = new bt6DofElasticPlastic2Constraint(*body, frame);
				for (int i = 0; i < 6; i++)
				{
					c->setStiffness(i, btScalar(0), false);  // rigid-plastic
					c->setMaxForce(i, btScalar(i == 3 ? kMp : 1e6));
				}
				if (whole)
				{
					EXPECT_TRUE(c->setPlasticSettings(*whole));
				}
				if (fields) setFields(*c, *fields);
				constraint = c;
			}
			else
			{
				auto* c = new bt6DofElasticPlasticConstraint(*body, frame, true);
				for (int i = 0; i < 6; i++)
				{
					c->setStiffness(i, btScalar(0));
					c->setMaxForce(i, btScalar(i == 3 ? kMp : 1e6));
				}
				if (whole)
				{
					EXPECT_TRUE(c->setPlasticSettings(*whole));
				}
				if (fields) setFields(*c, *fields);
				constraint = c;
			}
			moment = btVector3(btScalar(3 * kMp), 0, 0);
		}
		w.world.addConstraint(constraint);
	}
	~Bar()
	{
		w.world.removeConstraint(constraint);
		delete constraint;
	}

	template <class C>
	static void setFields(C& c, const btPlasticConstraintSettings& s)
	{
		c.setMaxPlasticDisplacement(s.m_maxPlasticDisplacement);
		c.setMaxPlasticRotation(s.m_maxPlasticRotation);
		c.setYieldTolerance(s.m_yieldTolerance);
		c.setMinStepsPerPeriod(s.m_minStepsPerPeriod);
	}

	// steps at 1/240 s under the moment until the joint breaks, at most maxSteps; returns the steps taken
	int driveUntilBroken(int maxSteps)
	{
		int steps = 0;
		for (; steps < maxSteps && constraint->isEnabled(); steps++)
		{
			body->applyTorque(moment);
			w.world.stepSimulation(btScalar(1. / 240.), 0);
		}
		return steps;
	}
};

const char* const kKinds[] = {"plastic_hinge", "elastic_plastic2", "elastic_plastic"};

template <class C>
void expectWholeOrNothing(C& c, const std::string& kind)
{
	expectSettings(btPlasticConstraintSettings(), c.getPlasticSettings(), kind + " defaults");
	const btPlasticConstraintSettings good = nonDefaultSettings();
	EXPECT_TRUE(c.setPlasticSettings(good)) << kind;
	expectSettings(good, c.getPlasticSettings(), kind + " after valid settings");
	EXPECT_EQ(good.m_maxPlasticRotation, c.getMaxPlasticRotation()) << kind;
	EXPECT_EQ(good.m_yieldTolerance, c.getYieldTolerance()) << kind;

	// three fields changed to good values, one out of its range: nothing is taken
	btPlasticConstraintSettings bad;
	bad.m_maxPlasticDisplacement = btScalar(1);
	bad.m_maxPlasticRotation = btScalar(1);
	bad.m_yieldTolerance = btScalar(1);  // [0, 1)
	bad.m_minStepsPerPeriod = btScalar(30);
	EXPECT_FALSE(c.setPlasticSettings(bad)) << kind;
	expectSettings(good, c.getPlasticSettings(), kind + " after invalid settings");
	bad.m_yieldTolerance = btScalar(0.01);
	bad.m_maxPlasticRotation = btScalar(NAN);
	EXPECT_FALSE(c.setPlasticSettings(bad)) << kind;
	expectSettings(good, c.getPlasticSettings(), kind + " after a NaN");
}
}  // namespace

TEST(PlasticSettings, DefaultsAreTheDocumentedOnes)
{
	const btPlasticConstraintSettings s;
	EXPECT_EQ(SIMD_INFINITY, s.m_maxPlasticDisplacement);
	EXPECT_EQ(SIMD_INFINITY, s.m_maxPlasticRotation);
	EXPECT_EQ(btScalar(1e-3), s.m_yieldTolerance);
	EXPECT_EQ(btScalar(25), s.m_minStepsPerPeriod);
	EXPECT_TRUE(s.isValid());
}

// Each field against the range its comment gives, one field changed at a time from the defaults.
TEST(PlasticSettings, IsValidChecksEachFieldAgainstItsRange)
{
	const btScalar nan = std::numeric_limits<btScalar>::quiet_NaN();
	const btScalar inf = std::numeric_limits<btScalar>::infinity();
	struct Field
	{
		const char* name;
		btScalar btPlasticConstraintSettings::*member;
		std::vector<btScalar> valid, invalid;
	};
	const Field fields[] = {
		{"maxPlasticDisplacement", &btPlasticConstraintSettings::m_maxPlasticDisplacement, {btScalar(1e-9), 1, SIMD_INFINITY}, {0, -1, -inf, nan}},
		{"maxPlasticRotation", &btPlasticConstraintSettings::m_maxPlasticRotation, {btScalar(1e-9), 1, SIMD_INFINITY}, {0, -1, -inf, nan}},
		{"yieldTolerance", &btPlasticConstraintSettings::m_yieldTolerance, {0, btScalar(0.5), btScalar(0.999)}, {btScalar(-1e-6), 1, 2, inf, nan}},
		{"minStepsPerPeriod", &btPlasticConstraintSettings::m_minStepsPerPeriod, {1, 25, btScalar(1e6)}, {btScalar(0.999), 0, -1, inf, nan}},
	};
	for (const Field& f : fields)
	{
		for (btScalar v : f.valid)
		{
			btPlasticConstraintSettings s;
			s.*f.member = v;
			EXPECT_TRUE(s.isValid()) << f.name << " = " << v;
		}
		for (btScalar v : f.invalid)
		{
			btPlasticConstraintSettings s;
			s.*f.member = v;
			EXPECT_FALSE(s.isValid()) << f.name << " = " << v;
		}
	}
}

TEST(PlasticSettings, EveryClassTakesSettingsWholeOrNotAtAll)
{
	PhysicsWorld w;
	btRigidBody* body = w.addBox(btVector3(0.5, 0.5, 0.5), 1.0, btVector3(0, 0, 0));
	btPlasticHingeConstraint hinge(*body, btVector3(0, 0, 0), btVector3(0, 0, 1));
	bt6DofElasticPlastic2Constraint ep2(*body, btTransform::getIdentity());
	bt6DofElasticPlasticConstraint ep(*body, btTransform::getIdentity(), true);
	expectWholeOrNothing(hinge, "plastic_hinge");
	expectWholeOrNothing(ep2, "elastic_plastic2");
	expectWholeOrNothing(ep, "elastic_plastic");
}

// The settings act in the step: the limit given whole breaks the joint as the same limit given field by field does,
// near Mp x 0.3 rad of absorbed work, and bit for bit the same; with the default settings the joint never breaks.
TEST(PlasticSettings, SettingsGivenWholeActAsTheSameFieldsGivenOneByOne)
{
	const btPlasticConstraintSettings settings = nonDefaultSettings();
	for (const char* kind : kKinds)
	{
		Bar whole(kind, &settings, nullptr);
		Bar fields(kind, nullptr, &settings);
		Bar control(kind, nullptr, nullptr);
		const int steps = whole.driveUntilBroken(2000);
		EXPECT_EQ(steps, fields.driveUntilBroken(2000)) << kind;
		EXPECT_EQ(2000, control.driveUntilBroken(2000)) << kind << ": the default settings never break";
		ASSERT_FALSE(whole.constraint->isEnabled()) << kind;
		EXPECT_FALSE(fields.constraint->isEnabled()) << kind;
		EXPECT_TRUE(control.constraint->isEnabled()) << kind;
		const btTransform& a = whole.body->getWorldTransform();
		const btTransform& b = fields.body->getWorldTransform();
		EXPECT_EQ(a.getRotation(), b.getRotation()) << kind;
		EXPECT_EQ(a.getOrigin(), b.getOrigin()) << kind;
		EXPECT_EQ(whole.body->getAngularVelocity(), fields.body->getAngularVelocity()) << kind;
		// the rotation it broke at, measured from the body (no gravity, one axis): the limit within one step's turn
		const btScalar angle = whole.body->getOrientation().getAngle();
		const btScalar lastStep = whole.body->getAngularVelocity().length() / btScalar(240);
		EXPECT_NEAR(settings.m_maxPlasticRotation, angle, lastStep + btScalar(1e-3)) << kind;
	}
}
