// The member that is one body until it must bend (plastic::JitMember, issue 24): every conserved quantity across a
// subdivision and a merge, measured from the bodies here (not from the member's own books), a cantilever hit twice
// (subdivided, at rest and merged, subdivided again) against the same cantilever always jointed, and a slow hit that
// cannot yield it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "CantileverRig.h"
#include "plastic/JitMember.h"
#include "plastic/SolverSettings.h"

using namespace plastic;

namespace
{
struct Mechanics
{
	double mass_kg = 0;
	btVector3 centre_m{0, 0, 0};
	btVector3 momentum{0, 0, 0};
	btVector3 angularMomentum{0, 0, 0};  // about the world's origin
	double kinetic_j = 0;
};

// from the bodies' masses, inertias, transforms and velocities
Mechanics measure(const std::vector<const btRigidBody*>& bodies)
{
	Mechanics m;
	for (const btRigidBody* b : bodies)
	{
		const double mass = 1.0 / double(b->getInvMass());
		const btVector3 x = b->getCenterOfMassPosition(), v = b->getLinearVelocity(), w = b->getAngularVelocity();
		const btVector3 inv = b->getInvInertiaDiagLocal();
		const btMatrix3x3& R = b->getCenterOfMassTransform().getBasis();
		const btMatrix3x3 I = R.scaled(btVector3(1 / inv.x(), 1 / inv.y(), 1 / inv.z())) * R.transpose();
		m.mass_kg += mass;
		m.centre_m += x * btScalar(mass);
		m.momentum += v * btScalar(mass);
		m.angularMomentum += I * w + x.cross(v * btScalar(mass));
		m.kinetic_j += 0.5 * mass * double(v.length2()) + 0.5 * double(w.dot(I * w));
	}
	m.centre_m /= btScalar(m.mass_kg);
	return m;
}

std::vector<const btRigidBody*> bodiesOf(const JitMember& member)
{
	if (member.whole()) return {member.wholeBody()};
	return {member.beam().segments().begin(), member.beam().segments().end()};
}

void expectSameVector(const btVector3& a, const btVector3& b, double tolerance, const char* what)
{
	EXPECT_NEAR(a.x(), b.x(), tolerance) << what;
	EXPECT_NEAR(a.y(), b.y(), tolerance) << what;
	EXPECT_NEAR(a.z(), b.z(), tolerance) << what;
}

void expectSameMechanics(const Mechanics& before, const Mechanics& after, const char* what)
{
	EXPECT_NEAR(after.mass_kg, before.mass_kg, 1e-5 * before.mass_kg) << what;
	expectSameVector(after.centre_m, before.centre_m, 1e-5, what);
	expectSameVector(after.momentum, before.momentum, 1e-5 * (before.momentum.length() + 1), what);
	expectSameVector(after.angularMomentum, before.angularMomentum, 1e-5 * (before.angularMomentum.length() + 1), what);
}

BeamSpec memberSpec(JointMethod method) { return cantileverSpec(rectangle(0.05, 0.10), method); }
}  // namespace

TEST(JitMember, IsBuiltWholeWithTheSegmentsMass)
{
	StructureWorld w;
	JitMember member(w.world(), memberSpec(JointMethod::ElasticPlastic2), nullptr);
	ASSERT_TRUE(member.errors().empty());
	ASSERT_TRUE(member.whole());
	EXPECT_EQ(w.world().getNumCollisionObjects(), 1);
	EXPECT_EQ(w.world().getNumConstraints(), 0);
	EXPECT_NEAR(1 / member.wholeBody()->getInvMass(), 7800 * 0.005 * 2, 1e-3);
	expectSameVector(member.wholeBody()->getCenterOfMassPosition(), btVector3(1, 0, 0), 1e-6, "centre");
	// the least energy that yields a joint: bending alone needs Mp^2 / (2 E I / L) = (400e6 * 1.25e-4)^2 / (2 * 200e9 *
	// 4.1667e-6 / 0.5) = 750 J (about either axis: for a rectangle Mp^2 / EI is 3 fy^2 b d / 4 E); the torsion of this
	// section yields with less (about 650 J by Saint-Venant's J and the plastic torque)
	const double bending = std::pow(400e6 * 0.05 * 0.1 * 0.1 / 4, 2) / (2 * 200e9 * 0.05 * std::pow(0.1, 3) / 12 / 0.5);
	EXPECT_NEAR(bending, 750, 1e-6);
	EXPECT_LE(member.yieldEnergy_j(), bending);
	EXPECT_GT(member.yieldEnergy_j(), 0.8 * bending);
}

// A spinning, flying member: subdivided, each segment moves as its part of the whole did.
TEST(JitMember, SubdivisionKeepsMomentumAngularMomentumAndKineticEnergy)
{
	StructureWorld w;
	JitMember member(w.world(), memberSpec(JointMethod::ElasticPlastic2), nullptr);
	btRigidBody& whole = *member.wholeBody();
	whole.setLinearVelocity(btVector3(1, 2, 0.5));
	whole.setAngularVelocity(btVector3(0.3, -0.2, 2));
	const Mechanics before = measure(bodiesOf(member));
	member.subdivide();
	ASSERT_FALSE(member.whole());
	EXPECT_EQ(w.world().getNumCollisionObjects(), 4);
	EXPECT_EQ(w.world().getNumConstraints(), 3);
	const Mechanics after = measure(bodiesOf(member));
	expectSameMechanics(before, after, "subdivided");
	EXPECT_NEAR(after.kinetic_j, before.kinetic_j, 1e-5 * before.kinetic_j);
	for (size_t i = 0; i < 4; i++)
		expectSameVector(member.beam().segments()[i]->getCenterOfMassPosition(), btVector3(btScalar(0.25 + 0.5 * i), 0, 0), 1e-5, "segment where it was built");
	// one step later the joints hold it as one body: its kinetic energy is kept
	w.stepOnce();
	EXPECT_NEAR(measure(bodiesOf(member)).kinetic_j, before.kinetic_j, 1e-3 * before.kinetic_j);
}

// Segments bent and moving apart: merged, the body has their momentum and angular momentum; the kinetic energy of their
// motion relative to one another is lost, not gained; subdivided again, they are where they were.
TEST(JitMember, MergeKeepsTheMomentaAndTheShapeAndGainsNoEnergy)
{
	StructureWorld w;
	JitMember member(w.world(), memberSpec(JointMethod::PlasticHinge), nullptr);
	member.subdivide();
	const std::vector<btRigidBody*>& s = member.beam().segments();
	std::vector<btTransform> placed;
	for (size_t i = 0; i < s.size(); i++)
	{
		// along an arc, each segment turned 0.2 rad more than the one before
		const btScalar angle = btScalar(0.2 * double(i));
		const btTransform t(btQuaternion(btVector3(0, 0, 1), angle) * s[i]->getCenterOfMassTransform().getRotation(),
							btVector3(btScalar(0.5 * i), btScalar(0.05 * i * i), 0));
		s[i]->setCenterOfMassTransform(t);
		s[i]->setLinearVelocity(btVector3(btScalar(i), btScalar(-0.5 * i), 0.25));
		s[i]->setAngularVelocity(btVector3(btScalar(0.1 * i), 0, btScalar(-0.3)));
		placed.push_back(t);
	}
	const Mechanics before = measure(bodiesOf(member));
	member.merge();
	ASSERT_TRUE(member.whole());
	const Mechanics after = measure(bodiesOf(member));
	expectSameMechanics(before, after, "merged");
	EXPECT_LT(after.kinetic_j, before.kinetic_j);
	EXPECT_NEAR(member.mergeLoss_j(), before.kinetic_j - after.kinetic_j, 1e-4 * before.kinetic_j);
	std::printf("[ info     ] merge: kinetic %.6f J -> %.6f J (relative motion lost %.6f J)\n", before.kinetic_j, after.kinetic_j, member.mergeLoss_j());
	// the same shape: subdivided at once, each segment where it was (and moving with the whole)
	member.subdivide();
	for (size_t i = 0; i < s.size(); i++)
	{
		expectSameVector(s[i]->getCenterOfMassPosition(), placed[i].getOrigin(), 1e-5, "segment back in place");
		EXPECT_NEAR(std::fabs(s[i]->getCenterOfMassTransform().getRotation().dot(placed[i].getRotation())), 1.0, 1e-6);
	}
	expectSameMechanics(after, measure(bodiesOf(member)), "subdivided again");
}

namespace
{
// A 2 m cantilever (50 x 100 mm steel, Mp 50 kN m) fixed to a static block, zero gravity, struck at its tip along -y
// by a steel ball; the member is a JitMember (jit) or always subdivided (jointed).
struct StruckCantilever
{
	StructureWorld w;
	btBoxShape supportShape{btVector3(0.1f, 0.1f, 0.1f)};
	btRigidBody support{btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &supportShape)};
	btSphereShape ballShape{0.1f};
	std::unique_ptr<btRigidBody> ball;
	std::unique_ptr<JitMember> member;
	bool jit;

	static WorldSolverSettings settings(double step_s)
	{
		WorldSolverSettings s;
		s.internal_step_s = step_s;
		return s;
	}

	StruckCantilever(JointMethod method, bool justInTime, double step_s = 1.0 / 240) : w(settings(step_s)), jit(justInTime)
	{
		support.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(-0.1f, 0, 0)));
		w.world().addRigidBody(&support);
		member = std::make_unique<JitMember>(w.world(), memberSpec(method), &support);
		if (!jit) member->subdivide();
	}
	~StruckCantilever()
	{
		if (ball) w.world().removeRigidBody(ball.get());
		member.reset();
		w.world().removeRigidBody(&support);
	}
	// a ball of mass_kg at 0.3 m above the tip's top face, coming down at speed_m_s
	void throwBall(double mass_kg, double speed_m_s, const btVector3& tip_m)
	{
		if (ball) w.world().removeRigidBody(ball.get());
		btVector3 inertia;
		ballShape.calculateLocalInertia(btScalar(mass_kg), inertia);
		btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass_kg), nullptr, &ballShape, inertia);
		info.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), tip_m + btVector3(-0.1f, 0.45f, 0));
		ball = std::make_unique<btRigidBody>(info);
		ball->setLinearVelocity(btVector3(0, btScalar(-speed_m_s), 0));
		w.world().addRigidBody(ball.get());
	}
	btVector3 tip() const
	{
		const btRigidBody& last = *member->beam().segments().back();
		if (!member->whole()) return last.getCenterOfMassTransform() * btVector3(0, 0, btScalar(member->beam().segmentLength_m() / 2));
		// while whole, the last segment's place in the whole body
		const btCompoundShape& shape = *static_cast<const btCompoundShape*>(member->wholeBody()->getCollisionShape());
		return member->wholeBody()->getCenterOfMassTransform() * shape.getChildTransform(shape.getNumChildShapes() - 1) *
			   btVector3(0, 0, btScalar(member->beam().segmentLength_m() / 2));
	}
	void run(double seconds)
	{
		const double dt = w.settings().internal_step_s;
		for (int i = 0; i < int(std::lround(seconds / dt)); i++)
		{
			if (jit) member->subdivideIfThreatened(dt);
			w.stepOnce();
			if (jit) member->mergeIfAtRest();
		}
	}
};
}  // namespace

// Struck, the member subdivides before the ball reaches it, bends, comes to rest and merges with its bend; struck again it
// subdivides again and bends further. Its plastic work after each blow is the always-jointed member's within 5 %.
TEST(JitMember, ACantileverHitTwiceBendsAsTheJointedOne)
{
	for (JointMethod method : {JointMethod::PlasticHinge, JointMethod::ElasticPlastic2})
	{
		StruckCantilever jit(method, true), jointed(method, false);
		double workAfterFirst[2] = {0, 0};
		int k = 0;
		for (StruckCantilever* c : {&jit, &jointed})
		{
			c->throwBall(50, 10, c->tip());
			c->run(4.0);
			workAfterFirst[k++] = c->member->plasticWork_j();
		}
		const char* name = jointMethodName(method);
		EXPECT_EQ(jit.member->subdivisions(), 1) << name;
		EXPECT_EQ(jit.member->merges(), 1) << name << ": at rest and asleep after the blow";
		EXPECT_GT(workAfterFirst[1], 100.0) << name << ": the blow yields the jointed member";
		EXPECT_NEAR(workAfterFirst[0], workAfterFirst[1], 0.05 * workAfterFirst[1]) << name;
		// merged with its bend: the tip stays where the bent member put it
		const btVector3 bentTip = jit.tip();
		EXPECT_LT(bentTip.y(), -0.01) << name;
		jit.run(0.5);
		expectSameVector(jit.tip(), bentTip, 1e-4, "tip of the merged member");
		k = 0;
		double workAfterSecond[2] = {0, 0};
		for (StruckCantilever* c : {&jit, &jointed})
		{
			c->throwBall(50, 10, c->tip());
			c->run(4.0);
			workAfterSecond[k++] = c->member->plasticWork_j();
		}
		EXPECT_EQ(jit.member->subdivisions(), 2) << name;
		EXPECT_GT(workAfterSecond[1], workAfterFirst[1] + 100.0) << name;
		EXPECT_NEAR(workAfterSecond[0], workAfterSecond[1], 0.05 * workAfterSecond[1]) << name;
		EXPECT_GE(jit.member->mergeLoss_j(), 0.0);
		std::printf("[ info     ] %s: plastic work after the first blow %.1f J (jointed %.1f J), after the second %.1f J (%.1f J); "
					"%d subdivisions, %d merges, relative motion lost at merges %.3g J\n",
					name, workAfterFirst[0], workAfterFirst[1], workAfterSecond[0], workAfterSecond[1], jit.member->subdivisions(), jit.member->merges(),
					jit.member->mergeLoss_j());
	}
}

// A blow that cannot bring the joints' yield energy leaves the member one body: the member is supported, so the ball's own
// 1/2 m v^2 is what can reach it (64 % of the yield energy here). What that misses is printed, not asserted: the
// always-jointed member books part of the same blow, at 1/240 s (its joints rigid-plastic) and at 0.25 ms too (its bending
// springs elastic, but its shear and axial DOFs still too stiff for the step, so rigid-plastic, and the ball's impulse
// passes their caps in one step): the yield energy is not a bound for rigid-plastic DOFs (JitMember.h).
TEST(JitMember, ASlowBallDoesNotSubdivideIt)
{
	StruckCantilever c(JointMethod::ElasticPlastic2, true);
	const double blow_j = 0.64 * c.member->yieldEnergy_j();
	const double slow = std::sqrt(2 * blow_j / 50);
	c.throwBall(50, slow, c.tip());
	c.run(2.0);
	EXPECT_TRUE(c.member->whole());
	EXPECT_EQ(c.member->subdivisions(), 0);
	EXPECT_GT(c.ball->getLinearVelocity().y(), -0.9 * slow) << "the ball met the member";
	// a ball with a little more than the yield energy subdivides it
	StruckCantilever fast(JointMethod::ElasticPlastic2, true);
	fast.throwBall(50, std::sqrt(2 * 1.1 * c.member->yieldEnergy_j() / 50), fast.tip());
	fast.run(0.5);
	EXPECT_EQ(fast.member->subdivisions(), 1);
	StruckCantilever elastic(JointMethod::ElasticPlastic2, false, 2.5e-4), coarse(JointMethod::ElasticPlastic2, false);
	for (StruckCantilever* j : {&elastic, &coarse})
	{
		j->throwBall(50, slow, j->tip());
		j->run(1.0);
	}
	std::printf("[ info     ] yield energy %.1f J: a blow of %.1f J leaves it whole; jointed, the member books %.1f J at 0.25 ms and %.1f J at 1/240 s\n",
				c.member->yieldEnergy_j(), blow_j, elastic.member->plasticWork_j(), coarse.member->plasticWork_j());
}
