// The drop weight against the rigid-plastic estimate, at converged settings (0.1 ms internal steps, 1000
// iterations: the impact lasts a few ms; at 1 ms the contact loses 4 % more). Tolerance 2 %: the estimate
// takes the impact as instantaneous and the ball as a point at mid-span; measured here, the ball keeps 0.3 % of the
// energy drifting off sideways and the mid-span rotation is 0.6-0.8 % below the estimate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "DropWeight.h"

using namespace structures;

namespace
{
DropWeightParameters converged(bool clamped)
{
	DropWeightParameters p;
	p.clamped = clamped;
	p.solver.world.internal_step_s = 1e-4;
	p.solver.world.solver = plastic::SolverKind::SequentialImpulse;  // the converged reference: upstream's solver
	p.solver.world.iterations = 1000;
	return p;
}

// the run to the beam's stop, and the same run on to 0.4 s (--full-duration)
std::pair<DropWeightResult, DropWeightResult> stoppedAndLater(DropWeightParameters p)
{
	const DropWeightResult stopped = runDropWeight(p);
	p.duration_s = 0.4;
	p.run_to_duration = true;
	return {stopped, runDropWeight(p)};
}
}  // namespace

// 1000 kg at 4.5 m/s on a 2 m, 50 x 100 mm beam of 78 kg in two segments; by hand: each half (39 kg, 1 m x 0.1 m)
// has I = 39 (1 + 0.01) / 12 + 39 x 0.5^2 = 13.0325 kg m^2 about its support, m_eff = 8 I / L^2 = 26.065 kg
TEST(DropWeightAnswer, ByHand)
{
	const DropWeightAnswer a = dropWeightAnswer(DropWeightParameters{});
	EXPECT_NEAR(a.effective_mass_kg, 26.065, 1e-9);
	EXPECT_NEAR(a.kinetic_after_impact_j, 10125.0 * 1000 / 1026.065, 1e-6);
	EXPECT_NEAR(a.midspan_rotation_rad, a.kinetic_after_impact_j / 50e3, 1e-12);  // Mp x 2 theta
	DropWeightParameters clamped;
	clamped.clamped = true;
	EXPECT_NEAR(dropWeightAnswer(clamped).support_rotation_rad, a.kinetic_after_impact_j / (4 * 50e3), 1e-12);  // Mp x 4 theta
}

TEST(DropWeightScene, SimplySupportedMidSpanRotation)
{
	const DropWeightResult r = runDropWeight(converged(false));
	const DropWeightAnswer& a = r.answer;
	EXPECT_NEAR(r.midspan_rotation_rad, a.midspan_rotation_rad, 0.02 * a.midspan_rotation_rad);
	// the pins turn with the halves: theta each, and the mid-span hinge twice that
	EXPECT_NEAR(r.left_support_rotation_rad, a.half_rotation_rad, 0.02 * a.half_rotation_rad);
	EXPECT_NEAR(r.right_support_rotation_rad, r.left_support_rotation_rad, 0.01 * r.left_support_rotation_rad);
	EXPECT_NEAR(r.kinetic_after_impact_j, a.kinetic_after_impact_j, 0.02 * a.kinetic_after_impact_j);
	EXPECT_NEAR(r.balance_error_pct, 0.0, 1.0);
	EXPECT_NEAR(r.booked_plastic_work_j, r.geometric_plastic_work_j, 0.005 * r.geometric_plastic_work_j);
}

TEST(DropWeightScene, ClampedThreeHinges)
{
	const DropWeightResult r = runDropWeight(converged(true));
	const DropWeightAnswer& a = r.answer;
	EXPECT_NEAR(r.midspan_rotation_rad, a.midspan_rotation_rad, 0.02 * a.midspan_rotation_rad);
	EXPECT_NEAR(r.left_support_rotation_rad, a.support_rotation_rad, 0.02 * a.support_rotation_rad);
	EXPECT_NEAR(r.right_support_rotation_rad, a.support_rotation_rad, 0.02 * a.support_rotation_rad);
	EXPECT_NEAR(r.geometric_plastic_work_j, a.kinetic_after_impact_j, 0.02 * a.kinetic_after_impact_j);
	EXPECT_NEAR(r.balance_error_pct, 0.0, 1.0);
}

// Not in the issue: a lighter, faster ball on a longer, deeper beam (the beam's share of the impact is larger:
// m_eff / G = 0.4) and the hinge-motor stand-in.
TEST(DropWeightScene, LighterFasterBallOnAnotherBeam)
{
	for (plastic::JointMethod m : {plastic::JointMethod::PlasticHinge, plastic::JointMethod::HingeMotor})
	{
		DropWeightParameters p = converged(true);
		p.solver.method = m;
		p.span_m = 3;
		p.section_width_m = 0.06;
		p.section_depth_m = 0.12;
		p.weight_mass_kg = 140;
		p.impact_speed_m_s = 15;
		const DropWeightResult r = runDropWeight(p);
		const DropWeightAnswer& a = r.answer;
		EXPECT_NEAR(a.effective_mass_kg / p.weight_mass_kg, 0.4, 0.03);
		EXPECT_NEAR(r.midspan_rotation_rad, a.midspan_rotation_rad, 0.03 * a.midspan_rotation_rad) << plastic::jointMethodName(m);
		EXPECT_NEAR(r.geometric_plastic_work_j, a.kinetic_after_impact_j, 0.03 * a.kinetic_after_impact_j) << plastic::jointMethodName(m);
	}
}

// Elastic-plastic joints at 1/3840 s are elastic springs (enough steps per elastic period, patch 0047), k = E I / l
// for a segment of length l: 8.33e5 N m / rad here, Mp / k = 0.06 rad and Mp^2 / 2k = 1500 J at the cap. The energy
// after the impact goes into the plastic work, the springs and what still moves: the balance counts the springs'
// elastic energy (it counted Mp times the whole rotation: -13.7 %, the spring's rotation priced at Mp and its energy
// left out). The mid-span hinge peaks at its plastic rotation plus its spring's, (E - Mp^2 / 2k - K_end) / Mp + Mp / k,
// 14.5 % past the rigid-plastic answer (measured 0.2260 against 0.2261 rad).
TEST(DropWeightScene, ElasticJointsBalanceTheirSpringsAndPeakAtTheElasticPlasticRotation)
{
	DropWeightParameters p;
	p.solver.method = plastic::JointMethod::ElasticPlastic;
	p.solver.world.internal_step_s = 1.0 / 3840;
	const DropWeightResult r = runDropWeight(p);
	const double mp = r.answer.plastic_moment_nm;
	const double k = p.youngs_modulus_pa * p.section_width_m * std::pow(p.section_depth_m, 3) / 12 / (p.span_m / p.segments);
	ASSERT_NEAR(r.elastic_end_j, mp * mp / (2 * k), 0.01 * mp * mp / (2 * k)) << "the springs are elastic and at their cap";
	EXPECT_NEAR(r.balance_error_pct, 0.0, 0.5);
	EXPECT_NEAR(r.kinetic_after_impact_j, r.answer.kinetic_after_impact_j, 0.01 * r.answer.kinetic_after_impact_j);
	const double peak = (r.answer.kinetic_after_impact_j - mp * mp / (2 * k) - r.kinetic_end_j) / mp + mp / k;
	EXPECT_NEAR(r.midspan_rotation_rad, peak, 0.01 * peak);
}

// Once the beam has stopped, its joints book no work its bodies do not lose. The beam, its two pins and the carriage's
// slide are a closed loop whose redundant rows keep Baumgarte's bias (the pins are upstream hinges); their targets
// disagree by the rounding of the bodies' transforms, and the direct solve met them by holding the mid-span joint's
// out-of-plane shear lock at its cap (1.15 MN), which then moved at the disagreement's velocity every step: from the
// stop to 0.4 s the joints booked +39.5 J (1/3840 s), +54.1 J (1/1920 s) and +10.6 J (elastic-plastic2) while the
// bodies' kinetic and elastic energy fell 1.9 J or stayed (patch 0049: the booking leaves the loops' corrections out;
// now +0.04, 0.00 and +0.07 J).
TEST(DropWeightScene, AStoppedBeamBooksNoWorkItsBodiesDoNotLose)
{
	const std::pair<plastic::JointMethod, double> cases[] = {{plastic::JointMethod::ElasticPlastic, 1.0 / 3840},
															 {plastic::JointMethod::ElasticPlastic, 1.0 / 1920},
															 {plastic::JointMethod::ElasticPlastic2, 1.0 / 3840}};
	for (const auto& c : cases)
	{
		DropWeightParameters p;
		p.solver.method = c.first;
		p.solver.world.internal_step_s = c.second;
		const auto [stopped, later] = stoppedAndLater(p);
		const std::string what = plastic::jointMethodName(c.first) + std::string(" at ") + std::to_string(c.second) + " s";
		ASSERT_LT(stopped.simulated_s, 0.1) << what;
		ASSERT_NEAR(later.simulated_s, 0.4, c.second) << what;
		const double booked = later.booked_plastic_work_j - stopped.booked_plastic_work_j;
		const double lost = stopped.kinetic_end_j + stopped.elastic_end_j - later.kinetic_end_j - later.elastic_end_j;
		EXPECT_GE(lost, -0.5) << what << ": the bodies gained energy";
		EXPECT_LT(booked, std::max(lost, 0.0) + 0.5) << what << ": booked " << booked << " J for " << lost << " J lost";
	}
}

// Clamped by elastic-plastic2 joints at steps that make some of their DOFs elastic springs, the beam keeps its energy
// once it has stopped. Patch 0048 held the springs' rows (bounds equal: a force) in the split correction like capped
// locks, so the left and mid-span joints were rigid there and the right clamp's split errors had no consistent
// correction: its weak-axis lock drifted mrads a step, rode its cap and pumped an out-of-plane mode; by 0.4 s the run
// had 1.26 MJ of kinetic energy (1/3840 s) or 5.6 kJ (1/1920 s) from the ball's 10.1 kJ (root cause by helper-61).
TEST(DropWeightScene, ClampedByElasticPlastic2JointsKeepsItsEnergyAfterItStops)
{
	for (const double step_s : {1.0 / 3840, 1.0 / 1920})
	{
		DropWeightParameters p;
		p.clamped = true;
		p.solver.method = plastic::JointMethod::ElasticPlastic2;
		p.solver.world.internal_step_s = step_s;
		const auto [stopped, later] = stoppedAndLater(p);
		const std::string what = "elastic-plastic2, clamped, at " + std::to_string(step_s) + " s";
		ASSERT_TRUE(later.finite) << what;
		const double energyStopped = stopped.kinetic_end_j + stopped.elastic_end_j + stopped.booked_plastic_work_j;
		const double energyLater = later.kinetic_end_j + later.elastic_end_j + later.booked_plastic_work_j;
		EXPECT_LT(energyLater, energyStopped + 0.005 * energyStopped) << what << ": " << energyStopped << " J -> " << energyLater << " J";
		EXPECT_NEAR(later.balance_error_pct, stopped.balance_error_pct, 1.0) << what;
		EXPECT_NEAR(later.midspan_rotation_rad, stopped.midspan_rotation_rad, 0.5 * stopped.midspan_rotation_rad) << what;
	}
}

TEST(DropWeightScene, BadParametersAreNamed)
{
	DropWeightParameters p;
	p.segments = 3;
	p.impact_speed_m_s = 0;
	const std::vector<std::string> e = validateDropWeightParameters(p);
	ASSERT_EQ(e.size(), 2u);
	EXPECT_EQ(e[0], "segments: 3 is not an even number in [2, 1000]");
	EXPECT_EQ(e[1].rfind("impact-speed: 0 is not in [0.001, 1000] m/s", 0), 0u) << e[1];
}
