// The portal frame against plastic analysis: the collapse factor and which hinges turn, for load ratios that make
// each of the three mechanisms govern, at converged settings (1 ms, 200 iterations; 1000 iterations move the
// factor by < 0.05 %). Tolerance: the quasi-static ramp (0.02 / s) sees the collapse +0.3 % late; the lower
// bound 0.5 % catches a frame that gives early.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "Portal.h"

using namespace structures;

namespace
{
PortalParameters converged(plastic::JointMethod method = plastic::JointMethod::PlasticHinge)
{
	PortalParameters p;
	p.solver.method = method;
	p.solver.world.internal_step_s = 1e-3;
	p.solver.world.solver = plastic::SolverKind::SequentialImpulse;  // the converged reference: upstream's solver
	p.solver.world.iterations = 200;
	return p;
}

std::vector<std::string> names(const PortalResult& r, const std::vector<int>& sites)
{
	std::vector<std::string> n;
	for (int i : sites) n.push_back(r.answer.sites[size_t(i)].name);
	return n;
}

void expectCollapse(const PortalParameters& p, double factor, const std::vector<std::string>& hinges, const char* what)
{
	const PortalResult r = runPortal(p);
	EXPECT_NEAR(r.answer.collapse_factor, factor, 1e-9 * factor) << what;
	EXPECT_EQ(names(r, r.answer.mechanism_sites), hinges) << what;
	EXPECT_GT(r.collapse_factor, 0.995 * factor) << what;
	EXPECT_LT(r.collapse_factor, 1.015 * factor) << what;
	EXPECT_EQ(names(r, r.mechanism_sites), hinges) << what;
	std::printf("[ info     ] %s, %s: collapse factor %.4f (plastic analysis %.4f), %.1f s simulated in %.2f s\n", what,
				plastic::jointMethodName(p.solver.method), r.collapse_factor, factor, r.simulated_s, r.wall_s);
}
}  // namespace

// Mp = 50 kN m, L = 4 m, h = 3 m: beam 8 Mp / (V L) ..., computed here by hand
TEST(PortalAnswer, ThreeMechanismsByHand)
{
	PortalParameters p;  // H = 50 kN, V = 75 kN
	const PortalAnswer a = portalAnswer(p);
	EXPECT_NEAR(a.beam_factor, 4 * 50e3 / (75e3 * 4 / 2), 1e-9);
	EXPECT_NEAR(a.sway_factor, 4 * 50e3 / (50e3 * 3), 1e-9);
	EXPECT_NEAR(a.combined_factor, 6 * 50e3 / (50e3 * 3 + 75e3 * 2), 1e-9);
	EXPECT_EQ(a.mechanism, "combined");
	// V only: the beam mechanism, whatever the columns
	p.horizontal_load_n = 0;
	EXPECT_EQ(portalAnswer(p).mechanism, "beam");
	EXPECT_NEAR(portalAnswer(p).collapse_factor, 4.0 / 3.0, 1e-9);
	// H only: sway
	p.horizontal_load_n = 50e3;
	p.vertical_load_n = 0;
	EXPECT_EQ(portalAnswer(p).mechanism, "sway");
}

TEST(PortalScene, CombinedMechanismGovernsEqualShares)
{
	expectCollapse(converged(), 1.0, {"base-left", "mid-span", "knee-right", "base-right"}, "H h = V L/2 = 3 Mp");
}

TEST(PortalScene, HingeMotorStandInCombined)
{
	expectCollapse(converged(plastic::JointMethod::HingeMotor), 1.0, {"base-left", "mid-span", "knee-right", "base-right"}, "H h = V L/2 = 3 Mp");
}

// Cases the issue does not list: other load ratios and another frame.
TEST(PortalScene, BeamMechanismGovernsMostlyVertical)
{
	PortalParameters p = converged();
	p.horizontal_load_n = 50e3 / 3;  // H h = 1 Mp
	p.vertical_load_n = 87.5e3;      // V L / 2 = 3.5 Mp: beam 8/7, combined 4/3, sway 4
	expectCollapse(p, 8.0 / 7.0, {"knee-left", "mid-span", "knee-right"}, "H h = Mp, V L/2 = 3.5 Mp");
}

TEST(PortalScene, SwayMechanismGovernsMostlyHorizontal)
{
	PortalParameters p = converged();
	p.horizontal_load_n = 3.5 * 50e3 / 3;  // H h = 3.5 Mp: sway 8/7
	p.vertical_load_n = 25e3;              // V L / 2 = 1 Mp: combined 4/3, beam 4
	expectCollapse(p, 8.0 / 7.0, {"base-left", "knee-left", "knee-right", "base-right"}, "H h = 3.5 Mp, V L/2 = Mp");
}

// A wider, lower frame of a deeper section, three segments per column and four in the beam: the inner column
// joints and the quarter points of the beam are hinge sites that must stay locked.
TEST(PortalScene, OtherFrameWithMoreJoints)
{
	PortalParameters p = converged();
	p.span_m = 6;
	p.height_m = 2.5;
	p.column_segments = 3;
	p.beam_segments = 4;
	p.section_width_m = 0.08;
	p.section_depth_m = 0.16;     // Mp = 400e6 x 0.08 x 0.0256 / 4 = 204.8 kN m
	p.horizontal_load_n = 150e3;  // H h = 375 kN m
	p.vertical_load_n = 150e3;    // V L / 2 = 450 kN m: combined 6 Mp / 825 kN m = 1.4894
	const double mp = 400e6 * 0.08 * 0.16 * 0.16 / 4;
	expectCollapse(p, 6 * mp / (150e3 * 2.5 + 150e3 * 3), {"base-left", "mid-span", "knee-right", "base-right"}, "6 m x 2.5 m frame");
}

// elastic-plastic2 at 1 ms bends elastically (EI/L joints, about 0.1 rad before the collapse with this slender
// steel section) and the frame gives at 0.91: the first-order answer leaves out what the displaced loads do. Ten
// times stiffer, it collapses at the plastic-analysis load.
TEST(PortalScene, ElasticPlastic2StiffFrameCollapsesAtTheFirstOrderLoad)
{
	PortalParameters p = converged(plastic::JointMethod::ElasticPlastic2);
	p.youngs_modulus_pa = 2e12;
	expectCollapse(p, 1.0, {"base-left", "mid-span", "knee-right", "base-right"}, "E = 2000 GPa");
}

// The loads' work, measured at their points, goes into the joints' booked plastic work, their springs and what still
// moves. At 1/3840 s the elastic-plastic joints are elastic springs (patch 0047) that hold 9776 J at the end beside
// 10813 J of plastic work; Mp times the rotations counts the springs' rotation at Mp too (32346 J), so only the
// rigid-plastic run's geometric work agrees with its booked work.
TEST(PortalScene, TheLoadsWorkBalancesTheJointsPlasticWorkAndSprings)
{
	for (const double step_s : {1.0 / 240, 1.0 / 3840})
	{
		PortalParameters p;
		p.solver.method = plastic::JointMethod::ElasticPlastic;
		p.solver.world.internal_step_s = step_s;
		p.ramp_rate_per_s = 0.02;
		const PortalResult r = runPortal(p);
		const std::string what = "elastic-plastic at " + std::to_string(step_s) + " s";
		ASSERT_TRUE(r.finite) << what;
		ASSERT_GT(r.load_work_j, 0.0) << what;
		EXPECT_NEAR(r.energy_balance_error_pct, 0.0, 0.5) << what << ": load work " << r.load_work_j << " J, kinetic " << r.kinetic_j
														<< " J, booked " << r.booked_plastic_work_j << " J, elastic " << r.elastic_j << " J";
		if (step_s > 1e-3)
		{
			EXPECT_EQ(r.elastic_j, 0.0) << what << ": rigid-plastic DOFs at this step";
			EXPECT_NEAR(r.geometric_plastic_work_j, r.booked_plastic_work_j, 0.001 * r.booked_plastic_work_j) << what;
		}
		else
		{
			EXPECT_GT(r.elastic_j, 0.2 * r.load_work_j) << what << ": the springs hold energy";
		}
	}
}

TEST(PortalScene, BadParametersAreNamed)
{
	PortalParameters p;
	p.beam_segments = 3;
	p.horizontal_load_n = -5;
	const std::vector<std::string> e = validatePortalParameters(p);
	ASSERT_EQ(e.size(), 2u);
	EXPECT_EQ(e[0], "beam-segments: 3 is not an even number in [2, 100]");
	EXPECT_EQ(e[1].rfind("horizontal-load: -5 is not in [0, ", 0), 0u) << e[1];
}

// Large displacements (issue 23): gravity on the knees and a sway pushover. The answers come from statics, not from
// the scene: with the four hinges of the sway mechanism at Mp and the knees moved by d h along x (and down by
// h (1 - cos theta)), virtual work gives H h cos(theta) + P h sin(theta) = 4 Mp, P = both knees' loads; a first-order
// analysis says H h = 4 Mp at every drift.
namespace
{
double secondOrderByHand(double mp, double h, double kneeLoad_n, double d) { return (4 * mp - 2 * kneeLoad_n * h * d) / (h * std::sqrt(1 - d * d)) * h / (4 * mp); }

PortalParameters swayPushover(plastic::JointMethod method, double kneeLoad_n, std::vector<double> drifts)
{
	PortalParameters p;
	p.solver.method = method;
	p.knee_load_n = kneeLoad_n;
	p.sway_drifts = std::move(drifts);
	return p;
}
}  // namespace

// The rigid-plastic frame at game settings (1/240 s): 100 kN on each knee take 15 % of the sway capacity per 0.1 of
// drift; the load before each drift is the second-order one within 0.05 %, and the loads' work is what the hinges
// booked.
TEST(PortalPDelta, TheSwayMechanismCarriesTheSecondOrderLoad)
{
	const PortalParameters p = swayPushover(plastic::JointMethod::PlasticHinge, 100e3, {0.05, 0.1, 0.2});
	const PortalResult r = runPortal(p);
	const double mp = 400e6 * 0.05 * 0.1 * 0.1 / 4;
	ASSERT_EQ(r.sway_load_ratios.size(), 3u);
	for (size_t k = 0; k < 3; k++)
	{
		const double d = r.sway_measured_drifts[k];
		EXPECT_NEAR(d, p.sway_drifts[k], 0.002) << k;
		const double answer = secondOrderByHand(mp, p.height_m, p.knee_load_n, d);
		EXPECT_NEAR(r.sway_load_ratios[k], answer, 5e-4 * answer) << "drift " << d;
		EXPECT_NEAR(r.second_order_load_ratios[k], answer, 1e-9) << "the runner's answer";
		std::printf("[ info     ] drift %.4f: H h / 4 Mp %.5f, second order %.5f, first order 1\n", d, r.sway_load_ratios[k], answer);
	}
	EXPECT_LT(r.sway_load_ratios[1], 0.9);  // the first-order answer is far off
	EXPECT_NEAR(r.sway_load_ratios[2], 0.41, 0.01);
	// the actuator's and the knee loads' work went into the hinges
	EXPECT_GT(r.booked_plastic_work_j, 0.3 * 4 * mp * 0.2);
	EXPECT_NEAR(r.booked_plastic_work_j, r.load_work_j, 0.002 * r.load_work_j);
	EXPECT_LT(r.kinetic_j, 1e-3);
	// without the knee loads, the lever's 1 / cos(theta) alone
	const PortalResult free = runPortal(swayPushover(plastic::JointMethod::PlasticHinge, 0, {0.2}));
	EXPECT_NEAR(free.sway_load_ratios[0], 1 / std::sqrt(1 - free.sway_measured_drifts[0] * free.sway_measured_drifts[0]), 5e-4);
}

// The elastic-plastic frame at steps where its joints are elastic (0.25 ms): the rigid segments carry the frame's P-Delta
// exactly: the elastic sway stiffness falls by the knee loads over h (K(P) = K(0) - 2 P / h), and once the mechanism
// has formed the load is the second-order rigid-plastic one. A square section: the default 50 mm wide columns buckle
// out of the plane under the knee loads (a two-segment cantilever with EI/a joints: 0.382 EI_weak / a^2 = 35 kN).
TEST(PortalPDelta, ElasticFrameLosesStiffnessByPOverH)
{
	std::vector<double> stiffness_n_m;
	for (double P : {0.0, 100e3})
	{
		PortalParameters p = swayPushover(plastic::JointMethod::ElasticPlastic2, P, {0.005, 0.01});
		p.section_width_m = 0.1;
		p.solver.world.internal_step_s = 2.5e-4;
		p.settle_s = 0;
		const PortalResult r = runPortal(p);
		ASSERT_EQ(r.sway_load_ratios.size(), 2u);
		const double mp = 400e6 * 0.1 * 0.1 * 0.1 / 4;
		const double H1 = r.sway_load_ratios[0] * 4 * mp / p.height_m, H2 = r.sway_load_ratios[1] * 4 * mp / p.height_m;
		stiffness_n_m.push_back((H2 - H1) / ((r.sway_measured_drifts[1] - r.sway_measured_drifts[0]) * p.height_m));
		EXPECT_EQ(r.booked_plastic_work_j, 0.0) << "elastic";
	}
	const double drop_n_m = 2 * 100e3 / 3.0;
	std::printf("[ info     ] sway stiffness %.0f N/m, with 100 kN on each knee %.0f N/m (2 P / h = %.0f N/m)\n", stiffness_n_m[0], stiffness_n_m[1], drop_n_m);
	EXPECT_NEAR(stiffness_n_m[0] - stiffness_n_m[1], drop_n_m, 0.03 * drop_n_m);
}

TEST(PortalPDelta, ElasticPlasticFrameReachesTheSecondOrderMechanism)
{
	for (plastic::JointMethod method : {plastic::JointMethod::ElasticPlastic, plastic::JointMethod::ElasticPlastic2})
	{
		PortalParameters p = swayPushover(method, 100e3, {0.2});
		p.section_width_m = 0.1;
		p.solver.world.internal_step_s = 2.5e-4;
		p.drift_rate_per_s = 0.05;
		p.settle_s = 0;
		const PortalResult r = runPortal(p);
		const double mp = 400e6 * 0.1 * 0.1 * 0.1 / 4;
		const double answer = secondOrderByHand(mp, p.height_m, p.knee_load_n, r.sway_measured_drifts[0]);
		EXPECT_NEAR(r.sway_load_ratios[0], answer, 1e-3 * answer) << plastic::jointMethodName(method);
		EXPECT_GT(r.booked_plastic_work_j, 0.0);
		std::printf("[ info     ] %s: drift %.4f: H h / 4 Mp %.5f, second order %.5f\n", plastic::jointMethodName(method), r.sway_measured_drifts[0],
					r.sway_load_ratios[0], answer);
	}
}

TEST(PortalPDelta, BadSwayParametersAreNamed)
{
	PortalParameters p;
	p.sway_drifts = {0.1, 0.7};
	p.knee_load_n = -1;
	const std::vector<std::string> e = validatePortalParameters(p);
	ASSERT_EQ(e.size(), 2u);
	EXPECT_EQ(e[0].rfind("knee-load: -1 is not in [0, ", 0), 0u) << e[0];
	EXPECT_EQ(e[1], "sway-drifts: drift 2 (0.7) is not in [-0.5, 0.5] (of h) or is the drift before it");
}
