// The structure scenes at game settings: four internal steps per 60 Hz frame (1/240 s) and Bullet's 10 iterations,
// with the toolkit's default solver (btDirectJointSolver, plastic::WorldSolverSettings). Targets (issue 13):
// collapse loads within 3 % with the predicted mechanism, no flow and no creep below collapse (held at 0.9 of the
// collapse load for 3 s), no energy gain; for every joint method and the upstream hinge-motor stand-in. Measured
// (report/STRUCTURES.md): cantilever +0.3 %, portal -0.2 to +0.5 %, no fallback to sequential impulse. The same
// settings with upstream's sequential-impulse solver miss (the cantilever collapses at 0.03-0.04 Mp / L), and so
// does btMLCPSolver as upstream constructs it on the portal's closed loop (its Dantzig solve fails in most steps).
// The drop weight is not held to 3 % here: at 1/240 s every method and solver ends 11 % (simply supported) and
// 17 % (clamped) short, because the plastic phase lasts only 22 and 6 steps (see DropWeight* below).
#include <gtest/gtest.h>

#include <cmath>

#include "Cantilever.h"
#include "DropWeight.h"
#include "Portal.h"

using namespace structures;
using plastic::JointMethod;
using plastic::SolverKind;

namespace
{
const JointMethod kMethods[] = {JointMethod::HingeMotor, JointMethod::PlasticHinge, JointMethod::ElasticPlastic, JointMethod::ElasticPlastic2};
// the toolkit's default, btDirectJointSolver (patch 0019), which needs no setting
const SolverKind kSolvers[] = {SolverKind::DirectJoint};

// the toolkit's defaults: btDirectJointSolver, 10 iterations, 1/240 s
scene::SolverSettings game(JointMethod method, SolverKind solver = SolverKind::DirectJoint)
{
	scene::SolverSettings s;
	s.method = method;
	s.world.solver = solver;
	EXPECT_EQ(s.world.iterations, 10);
	EXPECT_DOUBLE_EQ(s.world.internal_step_s, 1.0 / 240);
	return s;
}

struct PortalCase
{
	const char* name;
	double horizontal_n, vertical_n, factor;
	std::vector<std::string> hinges;
};
const PortalCase kPortalCases[] = {
	{"combined", 50e3, 75e3, 1.0, {"base-left", "mid-span", "knee-right", "base-right"}},
	{"sway", 3.5 * 50e3 / 3, 25e3, 8.0 / 7.0, {"base-left", "knee-left", "knee-right", "base-right"}},
	{"beam", 50e3 / 3, 87.5e3, 8.0 / 7.0, {"knee-left", "mid-span", "knee-right"}},
};

PortalParameters portal(const PortalCase& c, const scene::SolverSettings& s)
{
	PortalParameters p;
	p.solver = s;
	p.horizontal_load_n = c.horizontal_n;
	p.vertical_load_n = c.vertical_n;
	return p;
}

std::vector<std::string> names(const PortalResult& r, const std::vector<int>& sites)
{
	std::vector<std::string> n;
	for (int i : sites) n.push_back(r.answer.sites[size_t(i)].name);
	return n;
}

std::string label(JointMethod m, const char* what = "", SolverKind k = SolverKind::MlcpDantzig) { return std::string(plastic::solverKindName(k)) + " " + plastic::jointMethodName(m) + " " + what; }
}  // namespace

TEST(GameSettingsCantilever, CollapsesAtMpOverLWithTheHingeAtTheRoot)
{
	for (SolverKind k : kSolvers)
		for (JointMethod m : kMethods)
		{
			CantileverParameters p;
			p.solver = game(m, k);
			p.ramp_rate_per_s = 0.02;
			const CantileverResult r = runCantilever(p);
			EXPECT_GT(r.collapse_ratio, 0.97) << label(m, "", k);
			EXPECT_LT(r.collapse_ratio, 1.03) << label(m, "", k);
			EXPECT_EQ(r.mechanism, std::vector<int>{0}) << label(m, "only the root turns", k);
			EXPECT_EQ(r.solver_fallbacks, 0) << label(m, "", k);
		}
}

// 0.9 Mp / L for 3 s: nothing turns (the plastic joints hold to 1e-4 rad); the hinge-motor stand-in, a motor at
// target velocity 0 with no angle to return to, creeps about 0.5 mrad/s.
TEST(GameSettingsCantilever, HoldsBelowCollapseWithoutCreep)
{
	for (SolverKind k : kSolvers)
		for (JointMethod m : kMethods)
		{
			CantileverParameters p;
			p.solver = game(m, k);
			p.load_ratio = 0.9;
			p.duration_s = 3;
			const CantileverResult r = runCantilever(p);
			const double limit = m == JointMethod::HingeMotor ? 5e-3 : 1e-4;
			EXPECT_LT(r.max_root_rotation_rad, limit) << label(m, "", k);
			EXPECT_LT(r.max_inner_rotation_rad, limit) << label(m, "", k);
			EXPECT_LT(r.creep_rad, limit) << label(m, "rotation from 1 s to 3 s", k);
		}
}

// 1.5 Mp / L dead load: it stops where the load's work equals Mp theta (within 1 %, measured -0.46 %); no energy
// is gained: the load's work is at least the kinetic energy plus Mp times the rotations measured on the bodies.
TEST(GameSettingsCantilever, DeadLoadStopsWithoutEnergyGain)
{
	for (SolverKind k : kSolvers)
		for (JointMethod m : kMethods)
		{
			CantileverParameters p;
			p.solver = game(m, k);
			p.load_ratio = 1.5;
			const CantileverResult r = runCantilever(p);
			EXPECT_NEAR(r.stop_rotation_rad, r.answer.stop_rotation_rad, 0.01 * r.answer.stop_rotation_rad) << label(m, "", k);
			EXPECT_GT(r.energy_balance_error_pct, -0.1) << label(m, "energy gained", k);
			EXPECT_LT(r.energy_balance_error_pct, 1.0) << label(m, "", k);
			EXPECT_LT(r.max_inner_rotation_rad, 1e-3) << label(m, "", k);
		}
}

TEST(GameSettingsPortal, ThreeMechanismsWithinThreePercent)
{
	for (SolverKind k : kSolvers)
		for (const PortalCase& c : kPortalCases)
			for (JointMethod m : kMethods)
			{
				const PortalResult r = runPortal(portal(c, game(m, k)));
				ASSERT_NEAR(r.answer.collapse_factor, c.factor, 1e-9) << c.name;
				EXPECT_GT(r.collapse_factor, 0.97 * c.factor) << label(m, c.name, k);
				EXPECT_LT(r.collapse_factor, 1.03 * c.factor) << label(m, c.name, k);
				EXPECT_EQ(names(r, r.mechanism_sites), c.hinges) << label(m, c.name, k);
				EXPECT_EQ(r.solver_fallbacks, 0) << label(m, c.name, k);
				// no energy gain: the loads' work covers the kinetic energy and Mp times the rotations measured on the
				// bodies (the hinge-motor stand-in dissipates less than Mp where it turns below its cap: not checked)
				if (m != JointMethod::HingeMotor)
				{
					EXPECT_LT(r.kinetic_j + r.geometric_plastic_work_j, 1.005 * r.load_work_j) << label(m, c.name, k);
				}
			}
}

TEST(GameSettingsPortal, HoldsAtNineTenthsOfCollapseWithoutCreep)
{
	for (SolverKind k : kSolvers)
		for (const PortalCase& c : kPortalCases)
			for (JointMethod m : kMethods)
			{
				PortalParameters p = portal(c, game(m, k));
				p.ramp_rate_per_s = 0;
				p.load_factor = 0.9 * c.factor;
				p.duration_s = 3;
				const PortalResult r = runPortal(p);
				const double limit = m == JointMethod::HingeMotor ? 5e-3 : 1e-3;
				EXPECT_LT(r.max_rotation_rad, limit) << label(m, c.name, k);
				EXPECT_LT(r.creep_rad, m == JointMethod::HingeMotor ? 5e-3 : 1e-4) << label(m, c.name, k);
			}
}

// The same settings with upstream's solver: the chain sags and the cantilever "collapses" at a few percent of
// Mp / L, or never confirms a collapse while it flows; the portal gives early (plastic hinge -9 %, motor -59 %).
TEST(GameSettingsSequentialImpulse, MissesTheTargets)
{
	for (JointMethod m : kMethods)
	{
		CantileverParameters p;
		p.solver = game(m, SolverKind::SequentialImpulse);
		p.ramp_rate_per_s = 0.02;
		const CantileverResult r = runCantilever(p);
		EXPECT_FALSE(r.collapse_ratio > 0.97 && r.mechanism == std::vector<int>{0}) << label(m) << ": collapse ratio " << r.collapse_ratio;
	}
	for (JointMethod m : {JointMethod::HingeMotor, JointMethod::PlasticHinge})
	{
		const PortalResult r = runPortal(portal(kPortalCases[0], game(m, SolverKind::SequentialImpulse)));
		EXPECT_LT(r.collapse_factor, 0.95) << label(m);
	}
}

// btMLCPSolver as upstream constructs it: the portal's closed loop has redundant rows, the Dantzig solve fails in
// most steps and each falls back to 10 sequential-impulse iterations: it gives far early.
TEST(GameSettingsDantzigAsUpstream, FallsBackOnTheClosedLoop)
{
	scene::SolverSettings s = game(JointMethod::PlasticHinge, SolverKind::MlcpDantzig);
	const PortalResult r = runPortal(portal(kPortalCases[0], s));
	EXPECT_GT(r.solver_fallbacks, 100);
	EXPECT_LT(r.collapse_factor, 0.9);
}

// The drop weight at 1/240 s: the plastic phase after the impact lasts 22 steps (simply supported) or 6 (clamped),
// and Bullet's semi-implicit Euler moves each step with the velocity at its end: the rotations end 11 % and 17 %
// short for every method, the hinge-motor stand-in and the plastic hinge alike (a property of the step, not of the
// solver or the joint). What holds at game settings: no energy gain, both supports turn alike, and the error is
// first order in the step (half at 1/480 s).
TEST(GameSettingsDropWeight, NoEnergyGainAndAFirstOrderStepError)
{
	for (bool clamped : {false, true})
		for (JointMethod m : {JointMethod::HingeMotor, JointMethod::PlasticHinge})
		{
			DropWeightParameters p;
			p.clamped = clamped;
			p.solver = game(m);
			const DropWeightResult r = runDropWeight(p);
			const char* what = clamped ? "clamped" : "simply supported";
			EXPECT_GT(r.balance_error_pct, 0.0) << label(m, what) << ": energy gained";
			EXPECT_EQ(r.solver_fallbacks, 0) << label(m, what);
			EXPECT_LT(r.midspan_error_pct, -5) << label(m, what);
			EXPECT_GT(r.midspan_error_pct, -20) << label(m, what);
			p.solver.world.internal_step_s = 1.0 / 480;
			const DropWeightResult half = runDropWeight(p);
			EXPECT_GT(half.midspan_error_pct, 0.7 * r.midspan_error_pct) << label(m, what);
			EXPECT_LT(half.midspan_error_pct, 0.3 * r.midspan_error_pct) << label(m, what);
		}
}

// What it takes to reach the estimate within 3 % with the default solver: 1/960 s is not enough (-3.7 % simply
// supported, -4.6 % clamped), 1/2880 s is at the edge (-2.2 %, -3.0 %), 1/3840 s (64 internal steps per 60 Hz frame)
// -2.0 % and -2.8 % for the rigid-plastic methods (the elastic-plastic ones turn elastic at such steps and overshoot,
// see report/STRUCTURES.md).
TEST(GameSettingsDropWeight, WithinThreePercentAtSmallSteps)
{
	for (bool clamped : {false, true})
	{
		DropWeightParameters p;
		p.clamped = clamped;
		p.solver = game(JointMethod::PlasticHinge);
		p.solver.world.internal_step_s = 1.0 / 3840;
		const DropWeightResult r = runDropWeight(p);
		const DropWeightAnswer& a = r.answer;
		EXPECT_NEAR(r.midspan_rotation_rad, a.midspan_rotation_rad, 0.03 * a.midspan_rotation_rad) << clamped;
		EXPECT_GT(r.balance_error_pct, 0.0) << clamped;
	}
}
