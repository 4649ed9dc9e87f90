// Jointed structures at game settings (four internal steps per 60 Hz frame, 1/240 s, Bullet's 10 iterations) with the
// toolkit's default solver settings (SolverSettings.h), against plastic analysis: a tip load P on a cantilever of 4 or
// 8 segments and on an L-frame (stronger column, hinge at the knee) collapses at P = Mp / L with one hinge, holds
// for seconds below it without creeping, and under a dead load of 1.05 Mp / L stops where the load's work equals
// Mp times the hinge's rotation (1.05 sin(theta) = theta). The same cases with Bullet's own defaults fail the
// targets, so these tests tell the settings apart.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plastic/BeamBuilder.h"
#include "plastic/EnergyLedger.h"
#include "StructureProbe.h"

using namespace plastic;

namespace
{
ProbeSetting toolkitDefault()
{
	ProbeSetting s;
	s.name = "toolkit default";
	return s;
}

ProbeSetting upstreamDefault()
{
	ProbeSetting s;
	s.name = "upstream";
	s.world = upstreamWorldSolverSettings();
	s.joint = upstreamJointSolverSettings();
	return s;
}

struct Param
{
	ProbeCase probe;
	JointMethod method;
};

std::string paramName(const ::testing::TestParamInfo<Param>& info)
{
	std::string n = (info.param.probe.structure == Structure::Cantilever ? "Cantilever" : "LFrame") + std::to_string(info.param.probe.segments) + "_" +
					jointMethodName(info.param.method);
	for (char& ch : n)
		if (ch == '-') ch = '_';
	return n;
}

class GameSettings : public ::testing::TestWithParam<Param>
{
};
}  // namespace

TEST(GameSettingsAnswers, RestRotationOfTheDeadLoadMechanism)
{
	// 1.05 sin(t) = t: t = 0.53841 rad (Python, bisection); the series t^2 = 6 (1 - 1/1.05) gives 0.5345 to first order
	EXPECT_NEAR(restRotation_rad(1.05), 0.53841, 1e-5);
	EXPECT_NEAR(1.05 * std::sin(restRotation_rad(1.05)), restRotation_rad(1.05), 1e-9);
	EXPECT_EQ(restRotation_rad(0.9), 0.0);
	// Mp / L: 400 MPa x 50 mm x (100 mm)^2 / 4 = 50 kN m over 2 m
	EXPECT_NEAR(collapseLoad_n(ProbeCase{}), 25e3, 1.0);
}

TEST_P(GameSettings, CollapseLoadWithinThreePercent)
{
	const Param p = GetParam();
	const double f = collapseFactor(p.probe, p.method, toolkitDefault());
	EXPECT_NEAR(f, 1.0, 0.03) << p.probe.name() << ", " << jointMethodName(p.method);
}

TEST_P(GameSettings, HoldsBelowCollapseForSecondsWithoutCreep)
{
	const Param p = GetParam();
	const ProbeRun r = runProbe(p.probe, p.method, toolkitDefault(), 0.9, 3.0);
	ASSERT_TRUE(r.finite);
	// elastic methods bend elastically: 0.9 Mp over EI / L_segment is 0.026 rad at most here
	const double elastic = (p.method == JointMethod::ElasticPlastic || p.method == JointMethod::ElasticPlastic2) ? 0.03 : 0.005;
	EXPECT_LT(r.hinge_rotation_rad, elastic) << p.probe.name();
	EXPECT_LT(r.max_other_rotation_rad, elastic) << p.probe.name();
	EXPECT_LT(std::fabs(r.max_rotation_rad - r.max_rotation_after_1s_rad), 1e-3) << p.probe.name() << ": creeps from 1 s to 3 s";
	EXPECT_EQ(r.plastic_j, 0.0) << p.probe.name() << ": nothing yields";
}

TEST_P(GameSettings, AboveCollapseTheOneHingeMechanismStopsWhereTheBooksBalance)
{
	const Param p = GetParam();
	const ProbeRun r = runProbe(p.probe, p.method, toolkitDefault(), 1.05, 1.0);
	ASSERT_TRUE(r.finite);
	EXPECT_NEAR(r.hinge_rotation_rad, restRotation_rad(1.05), 0.03 * restRotation_rad(1.05)) << p.probe.name();
	EXPECT_LT(r.max_other_rotation_rad, 0.02 * r.hinge_rotation_rad + 0.03) << p.probe.name() << ": the other joints stay locked";
	if (r.books)
	{
		// no energy gain: what the bodies and joints hold is not more than the load's work
		EXPECT_LE(r.kinetic_j + r.elastic_j + r.plastic_j, 1.005 * r.load_work_j) << p.probe.name();
		EXPECT_NEAR(r.plastic_j, r.load_work_j, 0.03 * r.load_work_j) << p.probe.name() << ": the work went into the hinge";
	}
}

INSTANTIATE_TEST_SUITE_P(
	FourStepsPerFrameTenIterations, GameSettings,
	::testing::Values(Param{{Structure::Cantilever, 4}, JointMethod::PlasticHinge}, Param{{Structure::Cantilever, 8}, JointMethod::PlasticHinge},
					  Param{{Structure::LFrame, 4}, JointMethod::PlasticHinge}, Param{{Structure::Cantilever, 4}, JointMethod::HingeMotor},
					  Param{{Structure::Cantilever, 8}, JointMethod::HingeMotor}, Param{{Structure::LFrame, 4}, JointMethod::HingeMotor},
					  Param{{Structure::Cantilever, 4}, JointMethod::ElasticPlastic2}, Param{{Structure::Cantilever, 8}, JointMethod::ElasticPlastic2},
					  Param{{Structure::LFrame, 4}, JointMethod::ElasticPlastic2}, Param{{Structure::Cantilever, 4}, JointMethod::ElasticPlastic},
					  Param{{Structure::LFrame, 4}, JointMethod::ElasticPlastic}),
	paramName);

// Bullet's own defaults at the same steps and iterations do not hold the chain: the targets above separate them.
TEST(GameSettingsUpstream, TheSequentialImpulseSolverAtTenIterationsCollapsesEarly)
{
	const ProbeCase c{Structure::Cantilever, 4};
	EXPECT_LT(collapseFactor(c, JointMethod::PlasticHinge, upstreamDefault()), 0.9);
	const ProbeRun below = runProbe(c, JointMethod::PlasticHinge, upstreamDefault(), 0.9, 3.0);
	EXPECT_GT(below.hinge_rotation_rad, 0.05);
}

// Patch 0020: warm-started joint rows carry a steady load that rows starting from zero do not, at 10 iterations with
// the sequential impulse solver: at half the collapse load the inner joints of the cantilever stay nearly straight.
TEST(JointWarmStarting, WarmStartedRowsCarryASteadyLoadAtTenIterations)
{
	const ProbeCase c{Structure::Cantilever, 4};
	ProbeSetting cold = upstreamDefault();
	ProbeSetting warm = cold;
	warm.warm_starting_factor = 1.0;
	const ProbeRun without = runProbe(c, JointMethod::PlasticHinge, cold, 0.5, 1.0);
	const ProbeRun with = runProbe(c, JointMethod::PlasticHinge, warm, 0.5, 1.0);
	std::printf("[ info     ] inner joints at 0.5 Mp/L, 10 iterations: %.4f rad cold, %.4f rad warm started\n", without.max_other_rotation_rad,
				with.max_other_rotation_rad);
	EXPECT_LT(with.max_other_rotation_rad, 0.25 * without.max_other_rotation_rad);
}

// The toolkit throws nothing (issue 22): a world whose settings validate refuses is not configured and does not step,
// and says why; a joint's settings likewise.
TEST(SolverSettings, BadValuesAreRefusedByName)
{
	auto refused = [](const WorldSolverSettings& w, const char* name)
	{
		StructureWorld s(w);
		ASSERT_EQ(1u, s.errors().size()) << name;
		EXPECT_NE(s.errors().front().find(name), std::string::npos) << s.errors().front();
		EXPECT_EQ(0, s.stepFrame(1.0 / 60.0));
		EXPECT_FALSE(configureWorld(s.world(), w));
	};
	WorldSolverSettings w;
	w.iterations = 0;
	refused(w, "iterations");
	w = WorldSolverSettings();
	w.erp = 0;
	refused(w, "erp");
	w = WorldSolverSettings();
	w.internal_step_s = 0;
	refused(w, "internal step");
	StructureWorld world;
	EXPECT_TRUE(world.errors().empty());
	EXPECT_EQ(4, world.stepFrame(1.0 / 60.0));
	btBoxShape shape(btVector3(1, 1, 1));
	btRigidBody a(btRigidBody::btRigidBodyConstructionInfo(1, nullptr, &shape));
	btHingeConstraint h(a, btVector3(0, 0, 0), btVector3(0, 0, 1));
	JointSolverSettings j;
	j.override_iterations = -1;
	ASSERT_EQ(1u, validate(j).size());
	EXPECT_NE(validate(j).front().find("override iterations"), std::string::npos);
	EXPECT_FALSE(configureJoint(h, j, true));
	EXPECT_EQ(-1, h.getOverrideNumSolverIterations());
}

TEST(SolverSettings, StructureWorldStepsFramesInFixedInternalSteps)
{
	StructureWorld world;  // 1/240 s
	int steps = 0;
	for (int frame = 0; frame < 60; frame++) steps += world.stepFrame(1.0 / 60.0);
	EXPECT_NEAR(steps, 240, 1);
}

namespace
{
struct DropOutcome
{
	double initial_j, final_j, plastic_j, rootRotation_rad;
	int fallbacks;
};

// A 1000 kg box dropped at 6 m/s onto the tip of the 4-segment plastic-hinge cantilever, gravity on, 1 s of 60 Hz
// frames: contacts and joints in the same solve.
DropOutcome dropWeight(const WorldSolverSettings& settings)
{
	StructureWorld structure(settings);
	btDiscreteDynamicsWorld& world = structure.world();
	world.setGravity(btVector3(0, -9.81f, 0));
	btBoxShape supportShape(btVector3(0.1, 0.1, 0.1));
	btRigidBody support(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &supportShape));
	support.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(-0.1, 0, 0)));
	world.addRigidBody(&support, 0, 0);
	DropOutcome o{};
	{
		BeamSpec spec;
		spec.end_m = btVector3(2, 0, 0);
		spec.segments = 4;
		spec.joint.section = rectangle(0.05, 0.10);
		spec.joint.material = steel();
		spec.joint.method = JointMethod::PlasticHinge;
		Beam beam(world, spec, &support);
		btBoxShape boxShape(btVector3(0.2f, 0.2f, 0.2f));
		btVector3 inertia;
		boxShape.calculateLocalInertia(1000, inertia);
		btRigidBody::btRigidBodyConstructionInfo info(1000, nullptr, &boxShape, inertia);
		info.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), btVector3(1.75f, 0.27f, 0));
		btRigidBody box(info);
		box.setLinearVelocity(btVector3(0, -6, 0));
		box.setActivationState(DISABLE_DEACTIVATION);
		world.addRigidBody(&box);
		EnergyLedger ledger(world.getGravity());
		ledger.addBody(box);
		for (btRigidBody* b : beam.segments()) ledger.addBody(*b);
		for (const Joint& j : beam.joints()) ledger.addJoint(j);
		const Energies start = ledger.measure();
		o.initial_j = start.mechanical_j();
		for (int frame = 0; frame < 60; frame++) structure.stepFrame(1.0 / 60.0);
		const Energies end = ledger.measure();
		o.final_j = end.mechanical_j();
		o.plastic_j = end.plastic_j;
		const btVector3 x = beam.segments().front()->getWorldTransform().getBasis() * btVector3(0, 0, 1);
		o.rootRotation_rad = std::atan2(-double(x.y()), double(x.x()));
		world.removeRigidBody(&box);
	}
	o.fallbacks = structure.solverFallbacks();
	world.removeRigidBody(&support);
	return o;
}
}  // namespace

// An impact at game settings: the toolkit default (btDirectJointSolver, contacts solved with the joints) gains no
// energy and books plastic work, with no step left to sequential impulse (btMLCPSolver + Dantzig, the former
// default, fell back in 4 of 240 steps: the box rests on the tip with four contact points and friction).
TEST(GameSettingsImpact, DropWeightOnACantileverGainsNoEnergy)
{
	const DropOutcome d = dropWeight(WorldSolverSettings());
	const DropOutcome u = dropWeight(upstreamWorldSolverSettings());
	std::printf("[ info     ] drop weight, 18 kJ: toolkit default: plastic %.0f J, root %.3f rad, final %.0f J of %.0f J, %d SI fallbacks; "
				"upstream SI: plastic %.0f J, root %.3f rad, final %.0f J\n",
				d.plastic_j, d.rootRotation_rad, d.final_j, d.initial_j, d.fallbacks, u.plastic_j, u.rootRotation_rad, u.final_j);
	EXPECT_LE(d.final_j + d.plastic_j, d.initial_j + 0.01 * 18e3);
	EXPECT_GT(d.plastic_j, 0.3 * 18e3) << "most of the impact goes into the hinge";
	EXPECT_GT(d.rootRotation_rad, 0.05);
	EXPECT_EQ(d.fallbacks, 0) << "of 240 steps";
}

// One check of a WorldSolverSettings (issue 22): a message per bad field, naming it, and the runners' flag name
// for the internal step; the bounds are accepted and just past them refused.
TEST(ToolkitSolverSettings, OneValidationNamesEveryBadField)
{
	EXPECT_TRUE(validate(WorldSolverSettings()).empty());
	WorldSolverSettings w;
	w.internal_step_s = 1e-6;
	w.iterations = 100000;
	w.erp = 1;
	EXPECT_TRUE(validate(w).empty());
	w.internal_step_s = 0.0501;
	w.iterations = 0;
	w.erp = 0;
	const std::vector<std::string> errors = validate(w, "dt");
	ASSERT_EQ(errors.size(), 3u);
	EXPECT_EQ(errors[0].rfind("dt: ", 0), 0u) << errors[0];
	EXPECT_EQ(errors[1].rfind("iterations: ", 0), 0u) << errors[1];
	EXPECT_EQ(errors[2].rfind("erp: ", 0), 0u) << errors[2];
	w = WorldSolverSettings();
	w.internal_step_s = std::nan("");
	EXPECT_EQ(validate(w).size(), 1u);
}
