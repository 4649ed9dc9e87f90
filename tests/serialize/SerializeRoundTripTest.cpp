// .bullet files and the plastic constraints (patches 0013-0017): a world saved with btDefaultSerializer in the middle
// of a yield and loaded with btBulletWorldImporter into a fresh world continues bit for bit like the world that was
// never saved (motion and booking) for the plastic hinge and both elastic-plastic 6DOF constraints; a plain hinge keeps
// its locked-moment cap and a plain Spring2 constraint its row cap; a file written by unpatched Bullet loads.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "btBulletDynamicsCommon.h"
#include "LinearMath/btSerializer.h"
#include "btBulletFile.h"
#include "bDNA.h"
#include "btBulletWorldImporter.h"
#include "BulletDynamics/ConstraintSolver/bt6DofElasticPlastic2Constraint.h"
#include "BulletDynamics/ConstraintSolver/bt6DofElasticPlasticConstraint.h"

extern bool gDisableDeactivation;

namespace
{
const btScalar kStep = btScalar(1.) / btScalar(240.);
// an IPE 300's moment-axial shape (h 300, b 150, t_w 7.1, t_f 10.7 mm): the web's share of the area, the flanges' share
// of the plastic modulus
const btScalar kIpe300Web = btScalar(0.0071 * 0.2786 / (2 * 0.15 * 0.0107 + 0.0071 * 0.2786));
const btScalar kIpe300Flange = btScalar(0.15 * 0.0107 * 0.2893 / (0.15 * 0.0107 * 0.2893 + 0.0071 * 0.2786 * 0.2786 / 4));

struct World
{
	World()
		: dispatcher(&configuration), world(&dispatcher, &broadphase, &solver, &configuration)
	{
		world.setGravity(btVector3(0, btScalar(-9.81), 0));
	}
	~World()
	{
		for (int i = world.getNumConstraints() - 1; i >= 0; i--) world.removeConstraint(world.getConstraint(i));
		for (int i = world.getNumCollisionObjects() - 1; i >= 0; i--) world.removeCollisionObject(world.getCollisionObjectArray()[i]);
		if (importer) importer->deleteAllData();
	}
	void step(int n)
	{
		for (int i = 0; i < n; i++) world.stepSimulation(kStep, 1, kStep);
	}

	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher;
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver solver;
	btDiscreteDynamicsWorld world;
	// only for the world the test builds; the importer owns what it loads
	std::vector<std::unique_ptr<btCollisionShape>> shapes;
	std::vector<std::unique_ptr<btRigidBody>> bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> constraints;
	// owns what it loaded into the world
	std::unique_ptr<btBulletWorldImporter> importer;

	btRigidBody* addBox(const btVector3& halfExtents, btScalar mass, const btVector3& position)
	{
		shapes.push_back(std::make_unique<btBoxShape>(halfExtents));
		btVector3 inertia(0, 0, 0);
		if (mass > 0) shapes.back()->calculateLocalInertia(mass, inertia);
		btTransform t;
		t.setIdentity();
		t.setOrigin(position);
		btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shapes.back().get(), inertia);
		info.m_startWorldTransform = t;
		bodies.push_back(std::make_unique<btRigidBody>(info));
		world.addRigidBody(bodies.back().get());
		return bodies.back().get();
	}
	template <class T>
	T* add(T* constraint)
	{
		constraints.emplace_back(constraint);
		world.addConstraint(constraint, true);
		return constraint;
	}
};

// The scene: far apart in z, nothing touches. B hangs on a static base by a plastic hinge that yields under its
// weight and breaks after 0.8 rad; C hangs on B's tip by a softer plastic hinge (other lock parameters, no frame
// offset, split position correction); D hangs on the world by a single-body plastic hinge; E is a plain hinge locked
// at 0 with a locked-moment cap below its weight's moment, so it slips. F hangs on a static base by an
// elastic-plastic Spring2 constraint whose Z rotation is an elastic spring that yields; G on the world by one whose Z
// rotation is rigid-plastic; H on a static base by a plain Spring2 constraint whose locked Z rotation has a row cap;
// I and J like F and G, by elastic-plastic 6DOF spring constraints. K hangs on the world by an elastic-plastic
// Spring2 constraint whose frame is turned 45 degrees about the beam, so that its weight's moment bends it about both
// of the frame's bending axes (Y and Z) by 0.71 of the moment each: each cap (8 N m) alone would hold that, the
// circle they yield on together does not (9.8 N m > 8 N m).
void buildScene(World& w)
{
	const btVector3 beam(btScalar(0.5), btScalar(0.0625), btScalar(0.0625));
	const btVector3 z(0, 0, 1);
	btRigidBody* base = w.addBox(btVector3(btScalar(0.125), btScalar(0.125), btScalar(0.125)), 0, btVector3(0, 0, 0));
	btRigidBody* b = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 0));
	btRigidBody* c = w.addBox(btVector3(btScalar(0.25), btScalar(0.0625), btScalar(0.0625)), 1, btVector3(btScalar(1.25), 0, 0));
	btRigidBody* d = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 3));
	btRigidBody* e = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 6));

	btPlasticHingeConstraint* hb = w.add(new btPlasticHingeConstraint(*base, *b, btVector3(0, 0, 0), btVector3(btScalar(-0.5), 0, 0), z, z));
	hb->setPlasticMoment(6);
	hb->setMaxPlasticRotation(btScalar(0.8));

	btPlasticHingeConstraint* hc = w.add(new btPlasticHingeConstraint(*b, *c, btVector3(btScalar(0.5), 0, 0), btVector3(btScalar(-0.25), 0, 0), z, z));
	hc->setUseFrameOffset(false);
	hc->setLockParameters(btScalar(0.8), btScalar(0.4));
	hc->setSplitPositionCorrection(true);
	hc->setPlasticMoment(btScalar(0.25));
	hc->setYieldTolerance(btScalar(0.002));

	btPlasticHingeConstraint* hd = w.add(new btPlasticHingeConstraint(*d, btVector3(btScalar(-0.5), 0, 0), z));
	hd->setPlasticMoment(7);

	btHingeConstraint* he = w.add(new btHingeConstraint(*e, btVector3(btScalar(-0.5), 0, 0), z));
	he->setLimit(0, 0);
	he->setMaxLockedMoment(5);

	btTransform frameA, frameB;
	frameA.setIdentity();
	frameB.setIdentity();
	frameB.setOrigin(btVector3(btScalar(-0.5), 0, 0));
	btRigidBody* baseF = w.addBox(btVector3(btScalar(0.125), btScalar(0.125), btScalar(0.125)), 0, btVector3(0, 0, 9));
	btRigidBody* f = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 9));
	bt6DofElasticPlastic2Constraint* ef = w.add(new bt6DofElasticPlastic2Constraint(*baseF, *f, frameA, frameB));
	btRigidBody* g = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 12));
	bt6DofElasticPlastic2Constraint* eg = w.add(new bt6DofElasticPlastic2Constraint(*g, frameB));
	for (int i = 0; i < 6; i++)
	{
		for (bt6DofElasticPlastic2Constraint* c : {ef, eg})
		{
			c->setStiffness(i, 0, false);  // rigid-plastic
			c->setMaxForce(i, btScalar(1e6));
		}
	}
	ef->setStiffness(5, 50, false);  // elastic below the cap: 0.2 s period, about 50 steps
	ef->setMaxForce(5, 4);
	ef->setMaxPlasticRotation(btScalar(1.2));
	eg->setMaxForce(5, 6);

	btRigidBody* baseH = w.addBox(btVector3(btScalar(0.125), btScalar(0.125), btScalar(0.125)), 0, btVector3(0, 0, 15));
	btRigidBody* h = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 15));
	btGeneric6DofSpring2Constraint* sh = w.add(new btGeneric6DofSpring2Constraint(*baseH, *h, frameA, frameB));
	sh->setMaxRowForce(5, 5);

	btRigidBody* baseI = w.addBox(btVector3(btScalar(0.125), btScalar(0.125), btScalar(0.125)), 0, btVector3(0, 0, 18));
	btRigidBody* bi = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 18));
	bt6DofElasticPlasticConstraint* ei = w.add(new bt6DofElasticPlasticConstraint(*baseI, *bi, frameA, frameB, true));
	btRigidBody* bj = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 21));
	bt6DofElasticPlasticConstraint* ej = w.add(new bt6DofElasticPlasticConstraint(*bj, frameB, true));
	for (int i = 0; i < 6; i++)
	{
		for (bt6DofElasticPlasticConstraint* c : {ei, ej})
		{
			c->setStiffness(i, 0);  // rigid-plastic
			c->setMaxForce(i, btScalar(1e6));
		}
	}
	ei->setStiffness(5, 50);
	ei->setMaxForce(5, 4);
	ei->setMaxPlasticRotation(btScalar(1.2));
	ej->setMaxForce(5, 6);
	ej->setSplitPositionCorrection(true);

	btRigidBody* k = w.addBox(beam, 2, btVector3(btScalar(0.5), 0, 24));
	btTransform turned(btQuaternion(btVector3(1, 0, 0), SIMD_PI / 4), btVector3(btScalar(-0.5), 0, 0));
	bt6DofElasticPlastic2Constraint* ek = w.add(new bt6DofElasticPlastic2Constraint(*k, turned));
	for (int i = 0; i < 6; i++)
	{
		ek->setStiffness(i, 0, false);  // rigid-plastic
		ek->setMaxForce(i, btScalar(i == 4 || i == 5 ? 8 : 1e6));
	}
	ek->setYieldSurface(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5);
	ek->setYieldSurfaceISection(kIpe300Web, kIpe300Flange);  // kept, not used by the circle (patch 0027)
}

// Everything the continuation depends on or books, as raw numbers: every body's pose, velocities, mass and
// inertia; every constraint's state and booking.
std::vector<btScalar> snapshot(btDiscreteDynamicsWorld& world)
{
	std::vector<btScalar> s;
	auto put = [&s](const btVector3& v)
	{ s.insert(s.end(), {v.x(), v.y(), v.z()}); };
	for (int i = 0; i < world.getNumCollisionObjects(); i++)
	{
		btRigidBody* body = btRigidBody::upcast(world.getCollisionObjectArray()[i]);
		const btTransform& t = body->getWorldTransform();
		put(t.getOrigin());
		for (int r = 0; r < 3; r++) put(t.getBasis()[r]);
		put(body->getLinearVelocity());
		put(body->getAngularVelocity());
		put(body->getInvInertiaDiagLocal());
		s.push_back(body->getInvMass());
	}
	for (int i = 0; i < world.getNumConstraints(); i++)
	{
		btTypedConstraint* c = world.getConstraint(i);
		s.push_back(btScalar(c->getConstraintType()));
		s.push_back(c->isEnabled() ? 1 : 0);
		s.push_back(c->getSplitPositionCorrection() ? 1 : 0);
		if (btHingeConstraint* hinge = dynamic_cast<btHingeConstraint*>(c))
		{
			s.push_back(hinge->getHingeAngle());
			s.push_back(hinge->getLowerLimit());
			s.push_back(hinge->getUpperLimit());
			s.push_back(hinge->getMaxLockedMoment());
			s.push_back(hinge->getUseFrameOffset() ? 1 : 0);
			put(hinge->getBFrame().getOrigin());
			for (int r = 0; r < 3; r++) put(hinge->getBFrame().getBasis()[r]);
		}
		if (btGeneric6DofSpring2Constraint* dof = dynamic_cast<btGeneric6DofSpring2Constraint*>(c))
		{
			for (int k = 0; k < 6; k++) s.push_back(dof->getMaxRowForce(k));
			put(dof->getTranslationalLimitMotor()->m_equilibriumPoint);
			put(dof->getTranslationalLimitMotor()->m_springStiffness);
			for (int k = 0; k < 3; k++)
			{
				const btRotationalLimitMotor2* motor = dof->getRotationalLimitMotor(k);
				s.insert(s.end(), {motor->m_equilibriumPoint, motor->m_springStiffness, motor->m_loLimit, motor->m_hiLimit});
			}
			put(dof->getFrameOffsetA().getOrigin());
			for (int r = 0; r < 3; r++) put(dof->getFrameOffsetA().getBasis()[r]);
		}
		if (bt6DofElasticPlasticConstraint* ep = dynamic_cast<bt6DofElasticPlasticConstraint*>(c))
		{
			const btPlasticConstraintState& p = ep->getPlasticState();
			for (int k = 0; k < 6; k++) s.insert(s.end(), {ep->getMaxForce(k), ep->getEquilibriumPoint(k)});
			s.insert(s.end(), {p.getCurrentPlasticRotation(), p.getCurrentPlasticDisplacement(), p.getAbsorbedEnergy(), p.getElasticEnergy(),
							   p.getMaxPlasticRotation(), p.getMaxPlasticDisplacement(), p.getYieldTolerance(), p.getMinStepsPerPeriod(),
							   btScalar(ep->getUseFrameOffset() ? 1 : 0)});
			put(ep->getFrameOffsetA().getOrigin());
			for (int r = 0; r < 3; r++) put(ep->getFrameOffsetA().getBasis()[r]);
		}
		if (bt6DofElasticPlastic2Constraint* ep2 = dynamic_cast<bt6DofElasticPlastic2Constraint*>(c))
		{
			const btPlasticConstraintState& p = ep2->getPlasticState();
			s.insert(s.end(), {p.getCurrentPlasticRotation(), p.getCurrentPlasticDisplacement(), p.getAbsorbedEnergy(), p.getElasticEnergy(),
							   p.getMaxPlasticRotation(), p.getMaxPlasticDisplacement(), p.getYieldTolerance(), p.getMinStepsPerPeriod(),
							   btScalar(ep2->getYieldSurface()), btScalar(ep2->getYieldSurfaceDof(0)), btScalar(ep2->getYieldSurfaceDof(1))});
		}
		if (btPlasticHingeConstraint* plastic = dynamic_cast<btPlasticHingeConstraint*>(c))
		{
			const btPlasticConstraintState& p = plastic->getPlasticState();
			s.insert(s.end(), {plastic->getLockAngle(), plastic->getCurrentPlasticRotation(), plastic->getAbsorbedEnergy(),
							   p.getMaxPlasticRotation(), p.getMaxPlasticDisplacement(), p.getYieldTolerance(), p.getMinStepsPerPeriod(),
							   p.getCurrentPlasticDisplacement(), p.getElasticEnergy()});
		}
	}
	return s;
}

void expectBitIdentical(const std::vector<btScalar>& expected, const std::vector<btScalar>& actual, const std::string& what)
{
	ASSERT_EQ(expected.size(), actual.size()) << what;
	for (size_t i = 0; i < expected.size(); i++)
	{
		ASSERT_EQ(0, std::memcmp(&expected[i], &actual[i], sizeof(btScalar))) << what << ": value " << i << " is " << actual[i] << ", expected " << expected[i];
	}
}

std::vector<char> save(btDiscreteDynamicsWorld& world)
{
	btDefaultSerializer serializer;
	world.serialize(&serializer);
	const char* data = reinterpret_cast<const char*>(serializer.getBufferPointer());
	return std::vector<char>(data, data + serializer.getCurrentBufferSize());
}

// Loads a saved world into w. btBulletWorldImporter does not restore body velocities and damping (upstream, for every
// file): they are set here from the file's own btRigidBodyData, in the order the importer made the bodies. Nor does it
// turn a body's world inertia to the orientation it sets (createRigidBody calls setWorldTransform after the
// constructor, so the first step uses the inertia of the identity orientation): updateInertiaTensor here. Bodies that
// turn about a principal axis with equal inertias across it (B to J) do not see it; K, bent about two axes, does.
void load(std::vector<char> buffer, World& w, bool restoreVelocities = true)
{
	bParse::btBulletFile file(buffer.data(), int(buffer.size()));
	w.importer = std::make_unique<btBulletWorldImporter>(&w.world);
	btBulletWorldImporter& importer = *w.importer;
	ASSERT_TRUE(importer.loadFileFromMemory(&file));
	ASSERT_EQ(file.m_rigidBodies.size(), importer.getNumRigidBodies());
	for (int i = 0; restoreVelocities && i < file.m_rigidBodies.size(); i++)
	{
		btRigidBody* body = btRigidBody::upcast(importer.getRigidBodyByIndex(i));
		btVector3 linear, angular;
		if (file.getFlags() & bParse::FD_DOUBLE_PRECISION)
		{
			btRigidBodyDoubleData* data = reinterpret_cast<btRigidBodyDoubleData*>(file.m_rigidBodies[i]);
			linear.deSerializeDouble(data->m_linearVelocity);
			angular.deSerializeDouble(data->m_angularVelocity);
			body->setDamping(btScalar(data->m_linearDamping), btScalar(data->m_angularDamping));
		}
		else
		{
			btRigidBodyFloatData* data = reinterpret_cast<btRigidBodyFloatData*>(file.m_rigidBodies[i]);
			linear.deSerializeFloat(data->m_linearVelocity);
			angular.deSerializeFloat(data->m_angularVelocity);
			body->setDamping(btScalar(data->m_linearDamping), btScalar(data->m_angularDamping));
		}
		body->setLinearVelocity(linear);
		body->setAngularVelocity(angular);
		body->updateInertiaTensor();
	}
}

class SerializeRoundTrip : public ::testing::Test
{
protected:
	void SetUp() override { gDisableDeactivation = true; }
	void TearDown() override { gDisableDeactivation = false; }
};

}  // namespace

// The plastic hinges come back as plastic hinges with their booking, and the capped hinge with its cap.
TEST_F(SerializeRoundTrip, PlasticHingeAndCapSurviveSaveAndLoad)
{
	World original;
	buildScene(original);
	original.step(60);
	btPlasticHingeConstraint* hb = dynamic_cast<btPlasticHingeConstraint*>(original.world.getConstraint(0));
	ASSERT_GT(hb->getCurrentPlasticRotation(), btScalar(0.05)) << "the save must be mid-yield";
	ASSERT_TRUE(hb->isEnabled());

	World loaded;
	load(save(original.world), loaded);
	ASSERT_EQ(10, loaded.world.getNumConstraints());
	for (int i = 0; i < 3; i++)
	{
		btTypedConstraint* c = loaded.world.getConstraint(i);
		btPlasticHingeConstraint* plastic = dynamic_cast<btPlasticHingeConstraint*>(c);
		ASSERT_NE(nullptr, plastic) << "constraint " << i << " came back as a plain hinge";
		EXPECT_EQ(HINGE_CONSTRAINT_TYPE, c->getConstraintType());
		const btPlasticHingeConstraint* was = dynamic_cast<btPlasticHingeConstraint*>(original.world.getConstraint(i));
		EXPECT_EQ(was->getPlasticMoment(), plastic->getPlasticMoment());
		EXPECT_EQ(was->getCurrentPlasticRotation(), plastic->getCurrentPlasticRotation());
		EXPECT_EQ(was->getAbsorbedEnergy(), plastic->getAbsorbedEnergy());
		EXPECT_EQ(was->getLockAngle(), plastic->getLockAngle());
	}
	btPlasticHingeConstraint* hc = dynamic_cast<btPlasticHingeConstraint*>(loaded.world.getConstraint(1));
	EXPECT_FALSE(hc->getUseFrameOffset());
	EXPECT_TRUE(hc->getSplitPositionCorrection());
	EXPECT_EQ(btScalar(0.002), hc->getPlasticState().getYieldTolerance());
	EXPECT_EQ(SIMD_INFINITY, hc->getMaxPlasticRotation());
	EXPECT_EQ(btScalar(0.8), dynamic_cast<btPlasticHingeConstraint*>(loaded.world.getConstraint(0))->getMaxPlasticRotation());

	btTypedConstraint* e = loaded.world.getConstraint(3);
	ASSERT_EQ(nullptr, dynamic_cast<btPlasticHingeConstraint*>(e));
	btHingeConstraint* he = dynamic_cast<btHingeConstraint*>(e);
	ASSERT_NE(nullptr, he);
	EXPECT_EQ(btScalar(5), he->getMaxLockedMoment());
	EXPECT_TRUE(he->hasCappedLockedLimit());

	for (int i = 4; i < 6; i++)
	{
		btTypedConstraint* c = loaded.world.getConstraint(i);
		bt6DofElasticPlastic2Constraint* ep2 = dynamic_cast<bt6DofElasticPlastic2Constraint*>(c);
		ASSERT_NE(nullptr, ep2) << "constraint " << i << " came back as a plain Spring2 constraint";
		EXPECT_EQ(D6_SPRING_2_CONSTRAINT_TYPE, c->getConstraintType());
		bt6DofElasticPlastic2Constraint* was = dynamic_cast<bt6DofElasticPlastic2Constraint*>(original.world.getConstraint(i));
		for (int k = 0; k < 6; k++) EXPECT_EQ(was->getMaxForce(k), ep2->getMaxForce(k)) << k;
		EXPECT_EQ(was->getCurrentPlasticRotation(), ep2->getCurrentPlasticRotation());
		EXPECT_EQ(was->getAbsorbedEnergy(), ep2->getAbsorbedEnergy());
		EXPECT_EQ(was->getMaxPlasticRotation(), ep2->getMaxPlasticRotation());
		EXPECT_EQ(was->getRotationalLimitMotor(2)->m_equilibriumPoint, ep2->getRotationalLimitMotor(2)->m_equilibriumPoint);
	}
	EXPECT_GT(dynamic_cast<bt6DofElasticPlastic2Constraint*>(original.world.getConstraint(4))->getAbsorbedEnergy(), btScalar(0)) << "F must be mid-yield";
	btTypedConstraint* hc6 = loaded.world.getConstraint(6);
	ASSERT_EQ(nullptr, dynamic_cast<bt6DofElasticPlastic2Constraint*>(hc6));
	btGeneric6DofSpring2Constraint* sh = dynamic_cast<btGeneric6DofSpring2Constraint*>(hc6);
	ASSERT_NE(nullptr, sh);
	EXPECT_EQ(btScalar(5), sh->getMaxRowForce(5));
	EXPECT_EQ(SIMD_INFINITY, sh->getMaxRowForce(2));
	EXPECT_TRUE(sh->hasMaxRowForce());

	for (int i = 7; i < 9; i++)
	{
		btTypedConstraint* c = loaded.world.getConstraint(i);
		bt6DofElasticPlasticConstraint* ep = dynamic_cast<bt6DofElasticPlasticConstraint*>(c);
		ASSERT_NE(nullptr, ep) << "constraint " << i << " came back as a plain 6DOF spring constraint";
		EXPECT_EQ(D6_SPRING_CONSTRAINT_TYPE, c->getConstraintType());
		bt6DofElasticPlasticConstraint* was = dynamic_cast<bt6DofElasticPlasticConstraint*>(original.world.getConstraint(i));
		for (int k = 0; k < 6; k++) EXPECT_EQ(was->getMaxForce(k), ep->getMaxForce(k)) << k;
		EXPECT_EQ(was->getCurrentPlasticRotation(), ep->getCurrentPlasticRotation());
		EXPECT_EQ(was->getAbsorbedEnergy(), ep->getAbsorbedEnergy());
		EXPECT_EQ(was->getEquilibriumPoint(5), ep->getEquilibriumPoint(5));
		EXPECT_EQ(was->getSplitPositionCorrection(), ep->getSplitPositionCorrection());
	}
	EXPECT_GT(dynamic_cast<bt6DofElasticPlasticConstraint*>(original.world.getConstraint(7))->getAbsorbedEnergy(), btScalar(0)) << "I must be mid-yield";

	// K comes back with its yield surface (patch 0023; before, a loaded constraint had none and each DOF held alone)
	bt6DofElasticPlastic2Constraint* ek = dynamic_cast<bt6DofElasticPlastic2Constraint*>(loaded.world.getConstraint(9));
	ASSERT_NE(nullptr, ek);
	EXPECT_EQ(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, ek->getYieldSurface());
	EXPECT_EQ(4, ek->getYieldSurfaceDof(0));
	EXPECT_EQ(5, ek->getYieldSurfaceDof(1));
	EXPECT_EQ(kIpe300Web, ek->getWebAxialFraction()) << "the I section's shape comes back (patch 0027)";
	EXPECT_EQ(kIpe300Flange, ek->getFlangeMomentFraction());
	EXPECT_GT(dynamic_cast<bt6DofElasticPlastic2Constraint*>(original.world.getConstraint(9))->getAbsorbedEnergy(), btScalar(0)) << "K must be mid-yield";
}

// Save mid-yield, load into a fresh world, continue: every step of the loaded world is bit-identical to the world that
// was never saved, through the breaks of B, F and I and the continued yield of C, D, F, G, I and J.
TEST_F(SerializeRoundTrip, LoadedWorldContinuesBitIdentical)
{
	World original;
	buildScene(original);
	original.step(60);
	std::vector<char> file = save(original.world);
	ASSERT_TRUE(original.world.getConstraint(4)->isEnabled()) << "F must break after the save";
	ASSERT_TRUE(original.world.getConstraint(7)->isEnabled()) << "I must break after the save";
	std::vector<std::vector<btScalar>> expected;
	expected.push_back(snapshot(original.world));
	for (int i = 0; i < 240; i++)
	{
		original.step(1);
		expected.push_back(snapshot(original.world));
	}
	btPlasticHingeConstraint* hb = dynamic_cast<btPlasticHingeConstraint*>(original.world.getConstraint(0));
	btPlasticHingeConstraint* hc = dynamic_cast<btPlasticHingeConstraint*>(original.world.getConstraint(1));
	btPlasticHingeConstraint* hd = dynamic_cast<btPlasticHingeConstraint*>(original.world.getConstraint(2));
	for (int i = 0; i < 3; i++)
	{
		btPlasticHingeConstraint* h = dynamic_cast<btPlasticHingeConstraint*>(original.world.getConstraint(i));
		std::printf("hinge %d: %.4f rad, %.4f J, enabled %d\n", i, double(h->getCurrentPlasticRotation()), double(h->getAbsorbedEnergy()), int(h->isEnabled()));
	}
	for (int i = 4; i < 6; i++)
	{
		bt6DofElasticPlastic2Constraint* e = dynamic_cast<bt6DofElasticPlastic2Constraint*>(original.world.getConstraint(i));
		std::printf("elastic-plastic2 %d: %.4f rad, %.4f J plastic, %.4f J elastic, enabled %d\n", i, double(e->getCurrentPlasticRotation()),
					double(e->getAbsorbedEnergy()), double(e->getElasticEnergy()), int(e->isEnabled()));
	}
	for (int i = 7; i < 9; i++)
	{
		bt6DofElasticPlasticConstraint* e = dynamic_cast<bt6DofElasticPlasticConstraint*>(original.world.getConstraint(i));
		std::printf("elastic-plastic %d: %.4f rad, %.4f J plastic, %.4f J elastic, enabled %d\n", i, double(e->getCurrentPlasticRotation()),
					double(e->getAbsorbedEnergy()), double(e->getElasticEnergy()), int(e->isEnabled()));
	}
	ASSERT_FALSE(hb->isEnabled()) << "B must break after the save";
	ASSERT_GT(hc->getAbsorbedEnergy(), btScalar(0)) << "C must yield";
	ASSERT_GT(hd->getAbsorbedEnergy(), btScalar(0)) << "D must yield";
	ASSERT_FALSE(original.world.getConstraint(4)->isEnabled()) << "F must break after the save";
	ASSERT_FALSE(original.world.getConstraint(7)->isEnabled()) << "I must break after the save";
	const bt6DofElasticPlastic2Constraint* ek = dynamic_cast<bt6DofElasticPlastic2Constraint*>(original.world.getConstraint(9));
	std::printf("elastic-plastic2 on a circle 9: %.4f rad, %.4f J plastic, enabled %d\n", double(ek->getCurrentPlasticRotation()),
				double(ek->getAbsorbedEnergy()), int(ek->isEnabled()));
	ASSERT_GT(ek->getCurrentPlasticRotation(), btScalar(0.1)) << "K must go on yielding on its surface after the save";

	World loaded;
	load(file, loaded);
	expectBitIdentical(expected[0], snapshot(loaded.world), "right after loading");
	for (int i = 1; i <= 240; i++)
	{
		loaded.step(1);
		expectBitIdentical(expected[i], snapshot(loaded.world), "step " + std::to_string(i) + " after loading");
		if (::testing::Test::HasFatalFailure()) return;
	}

	// the comparison sees a difference: the same file without the bodies' velocities does not continue the same way
	World still;
	load(file, still, false);
	still.step(1);
	EXPECT_NE(expected[1], snapshot(still.world));
}

// A hinge without a cap is written exactly as before (btHingeConstraintData, HINGE_CONSTRAINT_TYPE).
TEST(SerializeFormat, UncappedHingeWritesTheUpstreamStructure)
{
	World w;
	btRigidBody* body = w.addBox(btVector3(1, 1, 1), 1, btVector3(0, 0, 0));
	btHingeConstraint hinge(*body, btVector3(0, 0, 0), btVector3(0, 0, 1));
	EXPECT_EQ(int(sizeof(btHingeConstraintData)), hinge.calculateSerializeBufferSize());
	btDefaultSerializer serializer;
	std::vector<char> buffer(hinge.calculateSerializeBufferSize());
	serializer.startSerialization();
	EXPECT_STREQ(btHingeConstraintDataName, hinge.serialize(buffer.data(), &serializer));
	EXPECT_EQ(HINGE_CONSTRAINT_TYPE, reinterpret_cast<btHingeConstraintData*>(buffer.data())->m_typeConstraintData.m_objectType);

	hinge.setMaxLockedMoment(3);
	EXPECT_EQ(int(sizeof(btCappedHingeConstraintData)), hinge.calculateSerializeBufferSize());
	buffer.assign(hinge.calculateSerializeBufferSize(), 0);
	EXPECT_STREQ(btCappedHingeConstraintDataName, hinge.serialize(buffer.data(), &serializer));
	EXPECT_EQ(CAPPED_HINGE_CONSTRAINT_TYPE, reinterpret_cast<btCappedHingeConstraintData*>(buffer.data())->m_hingeData.m_typeConstraintData.m_objectType);
	EXPECT_EQ(3, reinterpret_cast<btCappedHingeConstraintData*>(buffer.data())->m_maxLockedMoment);
	serializer.finishSerialization();
}

// A constraint's structure as serialize writes it, in a buffer of its own (no file), and the constraint restored from
// it in the build's precision.
template <class C>
std::vector<char> serializeAlone(const C& constraint, const char* expectedName)
{
	btDefaultSerializer serializer;
	std::vector<char> buffer(constraint.calculateSerializeBufferSize());
	serializer.startSerialization();
	EXPECT_STREQ(expectedName, constraint.serialize(buffer.data(), &serializer));
	serializer.finishSerialization();
	return buffer;
}

template <class C, class Data>
void deSerializeAlone(C& constraint, const Data& data)
{
#ifdef BT_USE_DOUBLE_PRECISION
	constraint.deSerializeDouble(data);
#else
	constraint.deSerializeFloat(data);
#endif
}

// The settings come back whole through btPlasticConstraintSettings::isValid: a hinge's structure with a yield
// tolerance out of [0, 1) (a damaged file) restores the hinge's cap and booking but keeps its settings, and the same
// structure undamaged restores them too.
TEST(SerializeFormat, SettingsOutOfTheirRangeAreNotRestored)
{
	World w;
	btRigidBody* body = w.addBox(btVector3(1, 1, 1), 1, btVector3(0, 0, 0));
	btPlasticHingeConstraint saved(*body, btVector3(0, 0, 0), btVector3(0, 0, 1));
	saved.setPlasticMoment(btScalar(3));
	saved.setMaxPlasticRotation(btScalar(0.7));
	saved.setYieldTolerance(btScalar(0.004));
	std::vector<char> buffer = serializeAlone(saved, btPlasticHingeConstraintDataName);
	btPlasticHingeConstraintData& data = *reinterpret_cast<btPlasticHingeConstraintData*>(buffer.data());
	for (bool damaged : {true, false})
	{
		data.m_plasticState.m_yieldTolerance = damaged ? 2 : btScalar(0.004);
		btPlasticHingeConstraint loaded(*body, btVector3(0, 0, 0), btVector3(0, 0, 1));
		deSerializeAlone(loaded, data);
		EXPECT_EQ(btScalar(3), loaded.getPlasticMoment()) << damaged;
		EXPECT_EQ(damaged ? SIMD_INFINITY : btScalar(0.7), loaded.getMaxPlasticRotation()) << damaged;
		EXPECT_EQ(damaged ? btPlasticConstraintSettings().m_yieldTolerance : btScalar(0.004), loaded.getYieldTolerance()) << damaged;
	}
}

// The fatigue settings are not in the file (patch 0031): a loaded hinge keeps the ones it was given before it loads,
// and takes the file's four settings beside them.
TEST(SerializeFormat, ALoadedConstraintKeepsItsFatigueSettings)
{
	World w;
	btRigidBody* body = w.addBox(btVector3(1, 1, 1), 1, btVector3(0, 0, 0));
	btPlasticHingeConstraint saved(*body, btVector3(0, 0, 0), btVector3(0, 0, 1));
	saved.setPlasticMoment(btScalar(3));
	saved.setMaxPlasticRotation(btScalar(0.7));
	std::vector<char> buffer = serializeAlone(saved, btPlasticHingeConstraintDataName);
	const btPlasticHingeConstraintData& data = *reinterpret_cast<const btPlasticHingeConstraintData*>(buffer.data());
	btPlasticHingeConstraint loaded(*body, btVector3(0, 0, 0), btVector3(0, 0, 1));
	btPlasticConstraintSettings fatigue = loaded.getPlasticSettings();
	fatigue.m_fatigueDuctilityRotation = btScalar(0.5);
	fatigue.m_fatigueDuctilityExponent = btScalar(-0.5);
	ASSERT_TRUE(loaded.setPlasticSettings(fatigue));
	deSerializeAlone(loaded, data);
	EXPECT_EQ(btScalar(0.7), loaded.getMaxPlasticRotation());
	EXPECT_EQ(btScalar(0.5), loaded.getPlasticSettings().m_fatigueDuctilityRotation);
	EXPECT_EQ(btScalar(-0.5), loaded.getPlasticSettings().m_fatigueDuctilityExponent);
}

// The yield surface comes back only as setYieldSurface would take it (patch 0023): a structure naming a surface that
// does not exist, or the same DOF twice (a damaged file), loads without a surface, as a file written before the
// surface was serialized does (its fields read as 0, YIELD_BOX); the undamaged structure restores it.
TEST(SerializeFormat, AYieldSurfaceOutOfItsRangeIsNotRestored)
{
	World w;
	btRigidBody* body = w.addBox(btVector3(1, 1, 1), 1, btVector3(0, 0, 0));
	bt6DofElasticPlastic2Constraint saved(*body, btTransform::getIdentity());
	saved.setMaxForce(4, 8);
	saved.setMaxForce(5, 8);
	saved.setYieldSurface(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, 5, 4);
	std::vector<char> buffer = serializeAlone(saved, bt6DofElasticPlastic2ConstraintDataName);
	bt6DofElasticPlastic2ConstraintData& data = *reinterpret_cast<bt6DofElasticPlastic2ConstraintData*>(buffer.data());
	struct Case
	{
		int surface, dof0, dof1;
		bool restored;
	};
	const Case cases[] = {{bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, 5, 4, true},
						  {bt6DofElasticPlastic2Constraint::YIELD_SURFACE_COUNT, 5, 4, false},
						  {-1, 5, 4, false},
						  {bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 4, false},
						  {bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 6, false},
						  {0, 0, 0, false}};
	for (const Case& c : cases)
	{
		data.m_yieldSurface = c.surface;
		data.m_surfaceDof[0] = c.dof0;
		data.m_surfaceDof[1] = c.dof1;
		bt6DofElasticPlastic2Constraint loaded(*body, btTransform::getIdentity());
		deSerializeAlone(loaded, data);
		const std::string what = std::to_string(c.surface) + " on " + std::to_string(c.dof0) + ", " + std::to_string(c.dof1);
		EXPECT_EQ(btScalar(8), loaded.getMaxForce(4)) << what;
		EXPECT_EQ(c.restored ? bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL : bt6DofElasticPlastic2Constraint::YIELD_BOX, loaded.getYieldSurface())
			<< what;
		EXPECT_EQ(c.restored ? 5 : -1, loaded.getYieldSurfaceDof(0)) << what;
		EXPECT_EQ(c.restored ? 4 : -1, loaded.getYieldSurfaceDof(1)) << what;
	}
}

// The I section's shape comes back only as setYieldSurfaceISection would take it (patch 0027): a file written before the
// shape was serialized reads it as (0, 0), and a damaged one may hold any pair; both load with the rectangle's (1, 0).
TEST(SerializeFormat, AnISectionShapeOutOfItsRangeIsNotRestored)
{
	World w;
	btRigidBody* body = w.addBox(btVector3(1, 1, 1), 1, btVector3(0, 0, 0));
	bt6DofElasticPlastic2Constraint saved(*body, btTransform::getIdentity());
	saved.setMaxForce(4, 8);
	saved.setMaxForce(0, 80);
	saved.setYieldSurfaceISection(kIpe300Web, kIpe300Flange);
	saved.setYieldSurface(bt6DofElasticPlastic2Constraint::YIELD_I_SECTION_AXIAL, 4, 0);
	std::vector<char> buffer = serializeAlone(saved, bt6DofElasticPlastic2ConstraintDataName);
	bt6DofElasticPlastic2ConstraintData& data = *reinterpret_cast<bt6DofElasticPlastic2ConstraintData*>(buffer.data());
	const double cases[][2] = {{kIpe300Web, kIpe300Flange}, {0, 0}, {1, 0.5}, {0.5, 0}, {0.2, 0.2}, {-1, 0.5}, {std::nan(""), 0.5}};
	for (const auto& c : cases)
	{
		data.m_surfaceShape[0] = c[0];
		data.m_surfaceShape[1] = c[1];
		bt6DofElasticPlastic2Constraint loaded(*body, btTransform::getIdentity());
		deSerializeAlone(loaded, data);
		const bool restored = c[0] == double(kIpe300Web);
		const std::string what = std::to_string(c[0]) + ", " + std::to_string(c[1]);
		EXPECT_EQ(bt6DofElasticPlastic2Constraint::YIELD_I_SECTION_AXIAL, loaded.getYieldSurface()) << what;
		EXPECT_EQ(restored ? kIpe300Web : btScalar(1), loaded.getWebAxialFraction()) << what;
		EXPECT_EQ(restored ? kIpe300Flange : btScalar(0), loaded.getFlangeMomentFraction()) << what;
		// on the rectangle's curve, M = 0.64 Mp with N = 0.6 Np is on the surface; on the IPE 300's it is outside
		EXPECT_NEAR(restored ? 1.1086 : 1.0, double(loaded.getYieldSurfaceGauge(btScalar(0.64), btScalar(0.6))), 0.001) << what;
	}
}

// tests/serialize/data/upstream-326.bullet was written by unpatched Bullet (make_old_file.cpp, pybullet 3.2.7 src/,
// single precision, 64-bit): it has no plastic structures in its DNA and loads with every value make_old_file set
// (compared as the floats the file holds, so that a double-precision build checks the same).
TEST_F(SerializeRoundTrip, OldFileLoads)
{
	bParse::btBulletFile file(BP_SERIALIZE_DATA_DIR "/upstream-326.bullet");
	ASSERT_TRUE(file.getFlags() & bParse::FD_OK);
	World w;
	w.importer = std::make_unique<btBulletWorldImporter>(&w.world);
	ASSERT_TRUE(w.importer->loadFileFromMemory(&file));
	EXPECT_EQ(-1, file.getFileDNA()->getReverseType("btPlasticHingeConstraintFloatData")) << "not an old file";
	EXPECT_NE(-1, file.getFileDNA()->getReverseType("btHingeConstraintFloatData"));
	EXPECT_EQ(326, file.getVersion());

	ASSERT_EQ(5, w.world.getNumCollisionObjects());
	ASSERT_EQ(4, w.world.getNumConstraints());
	EXPECT_EQ(-9.81f, float(w.world.getGravity().y()));
	EXPECT_EQ(btScalar(0.5), btRigidBody::upcast(w.world.getCollisionObjectArray()[1])->getInvMass());

	btHingeConstraint* hinge = dynamic_cast<btHingeConstraint*>(w.world.getConstraint(0));
	ASSERT_NE(nullptr, hinge);
	EXPECT_EQ(nullptr, dynamic_cast<btPlasticHingeConstraint*>(hinge));
	EXPECT_EQ(HINGE_CONSTRAINT_TYPE, hinge->getConstraintType());
	EXPECT_FLOAT_EQ(-0.5f, float(hinge->getLowerLimit()));  // the limit is kept as centre and half range
	EXPECT_FLOAT_EQ(0.7f, float(hinge->getUpperLimit()));
	EXPECT_FLOAT_EQ(0.8f, float(hinge->getLimitSoftness()));
	EXPECT_FLOAT_EQ(0.25f, float(hinge->getLimitBiasFactor()));
	EXPECT_FLOAT_EQ(0.5f, float(hinge->getLimitRelaxationFactor()));
	EXPECT_TRUE(hinge->getEnableAngularMotor());
	EXPECT_EQ(btScalar(1.5), hinge->getMotorTargetVelocity());
	EXPECT_EQ(btScalar(2.0), hinge->getMaxMotorImpulse());
	EXPECT_EQ(SIMD_INFINITY, hinge->getMaxLockedMoment());

	btPoint2PointConstraint* p2p = dynamic_cast<btPoint2PointConstraint*>(w.world.getConstraint(1));
	ASSERT_NE(nullptr, p2p);
	EXPECT_EQ(btVector3(btScalar(0.5), 0, 0), p2p->getPivotInA());
	EXPECT_EQ(btVector3(btScalar(-0.5), 0, 0), p2p->getPivotInB());

	btGeneric6DofSpring2Constraint* spring2 = dynamic_cast<btGeneric6DofSpring2Constraint*>(w.world.getConstraint(2));
	ASSERT_NE(nullptr, spring2);
	btVector3 lower, upper;
	spring2->getLinearLowerLimit(lower);
	spring2->getLinearUpperLimit(upper);
	EXPECT_EQ(-0.1f, float(lower.y()));
	EXPECT_EQ(0.1f, float(upper.y()));
	spring2->getAngularLowerLimit(lower);
	spring2->getAngularUpperLimit(upper);
	EXPECT_EQ(-0.3f, float(lower.z()));
	EXPECT_EQ(0.4f, float(upper.z()));
	EXPECT_TRUE(spring2->getTranslationalLimitMotor()->m_enableSpring[1]);
	EXPECT_EQ(btScalar(100), spring2->getTranslationalLimitMotor()->m_springStiffness[1]);
	EXPECT_EQ(btScalar(0.5), spring2->getTranslationalLimitMotor()->m_springDamping[1]);
	EXPECT_EQ(0.02f, float(spring2->getTranslationalLimitMotor()->m_equilibriumPoint[1]));
	EXPECT_EQ(SIMD_INFINITY, spring2->getMaxRowForce(1));

	btHingeConstraint* locked = dynamic_cast<btHingeConstraint*>(w.world.getConstraint(3));
	ASSERT_NE(nullptr, locked);
	EXPECT_EQ(btScalar(0.25), locked->getLowerLimit());
	EXPECT_EQ(btScalar(0.25), locked->getUpperLimit());
	EXPECT_FALSE(locked->hasCappedLockedLimit());

	w.step(10);  // and it runs
	EXPECT_FALSE(w.world.getCollisionObjectArray()[1]->getWorldTransform().getOrigin().fuzzyZero());
}
