// A fast subset of the stability matrix (ci/stability.py, report/STABILITY.md) as regression tests:
// the new constraints stay finite, never gain energy and book no more plastic work than the energy
// lost in stiff and extreme cells, and the upstream failures the thesis describes are still reproduced
// and classified.
#include <gtest/gtest.h>

#include <string>

#include "CharpyRun.h"
#include "CharpyVerdict.h"

namespace
{
struct Cell
{
	const char* name;
	CharpyMethod method;
	void (*apply)(CharpyParameters&);
	CharpyVerdict expected;
	// Stable cells: the plastic work the joints book is at most this times the energy lost. The joints book
	// only what they did at their cap (the plastic hinge its limit row's impulse, the elastic-plastic classes
	// the forces read back from the solver), so with a converged solver it is a part of the loss.
	double maxWorkPerLoss = 1.02;
	// and the run's accuracy (classifyCharpyAccuracy) must be accurate: passed the anvils through the gap, no deep
	// penetration
	bool mustBeAccurate = false;
	// an explosion that crosses the blow-up and the energy-gain thresholds near the same time: either verdict, and the
	// energy must at least double
	bool eitherExplosion = false;
};

CharpyResult run(const Cell& cell, CharpyParameters& p)
{
	p.end_when_clear = false;  // the whole duration: a spring may explode after the specimen has passed
	p.method = cell.method;
	cell.apply(p);
	return runCharpy(p);
}

// the new method (report/STABILITY.md, "The new method on every case"): the direct solve, speculative contacts and the
// world's own contact steps within the smallest reach of the matrix (0.14 mm) in place of the runner's substeps
void newMethod(CharpyParameters& p)
{
	p.solver = plastic::SolverKind::DirectJoint;
	p.speculative_contacts = true;
	p.contact_substep_s = 0;
	p.world_contact_travel_m = 1.4e-4;
}

const Cell kCells[] = {
	{"fy800_plastic_hinge", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { p.yield_stress_pa = 800e6; }, CharpyVerdict::Stable},
	{"fy800_elastic_plastic", CharpyMethod::ElasticPlastic, [](CharpyParameters& p) { p.yield_stress_pa = 800e6; }, CharpyVerdict::Stable},
	{"fy800_elastic_plastic2", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { p.yield_stress_pa = 800e6; }, CharpyVerdict::Stable},
	{"fy2000_elastic_plastic2", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { p.yield_stress_pa = 2000e6; }, CharpyVerdict::Stable},
	{"dt60Hz_plastic_hinge", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { p.dt_s = 1.0 / 60; }, CharpyVerdict::Stable},
	{"dt60Hz_elastic_plastic2", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { p.dt_s = 1.0 / 60; }, CharpyVerdict::Stable},
	{"parts4_plastic_hinge", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { p.parts = 4; }, CharpyVerdict::Stable},
	// sequential impulse keeps its contacts' Baumgarte correction as velocity, energy no force paid for, and the joints
	// book the flow it makes: 8 parts book 15.9 J beyond the energy lost, one iteration 3.2 J (more than 1 % of E0, an
	// energy gain since the verdict counts the booked work; measured). The direct solve moves the correction to the
	// positions (patch 0038) and books its flow as far as the call's losses pay for it (patch 0041)
	{"parts8_elastic_plastic", CharpyMethod::ElasticPlastic, [](CharpyParameters& p) { p.parts = 8; }, CharpyVerdict::EnergyGain},
	// many light parts under the heavy hammer: the chain lets go in the solver, and the joints book no work for it
	{"parts32_plastic_hinge", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { p.parts = 32; }, CharpyVerdict::CameApart},
	{"dt1ms_nosub_elastic_plastic2", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { p.dt_s = 1e-3; p.contact_substep_s = 0; }, CharpyVerdict::CameApart},
	// the same two with the direct solve (btDirectJointSolver): the chain and the halves are held. At 1 ms steps its
	// contacts' correction turns the yielding joints: they booked 151.6 J for 143.7 J lost before patch 0041, 143.2 J now
	{"parts32_plastic_hinge_direct", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { p.parts = 32; p.solver = plastic::SolverKind::DirectJoint; }, CharpyVerdict::Stable},
	{"dt1ms_nosub_elastic_plastic2_direct", CharpyMethod::ElasticPlastic2,
	 [](CharpyParameters& p) { p.dt_s = 1e-3; p.contact_substep_s = 0; p.solver = plastic::SolverKind::DirectJoint; }, CharpyVerdict::Stable, 1.0},
	// direct solve with speculative contacts (patch 0036): 4 and 8 parts pass the anvils through the gap, where the
	// direct solve alone leaves 4 parts of elastic-plastic2 in front of them (report/STABILITY.md, direct-spec-*)
	{"parts4_elastic_plastic2_direct_spec", CharpyMethod::ElasticPlastic2,
	 [](CharpyParameters& p) { p.parts = 4; p.solver = plastic::SolverKind::DirectJoint; p.speculative_contacts = true; }, CharpyVerdict::Stable, 1.02, true},
	{"parts8_plastic_hinge_direct_spec", CharpyMethod::PlasticHinge,
	 [](CharpyParameters& p) { p.parts = 8; p.solver = plastic::SolverKind::DirectJoint; p.speculative_contacts = true; }, CharpyVerdict::Stable, 1.02, true},
	{"iterations1_elastic_plastic2", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { p.solver_iterations = 1; }, CharpyVerdict::EnergyGain},
	{"parts8_elastic_plastic_direct", CharpyMethod::ElasticPlastic, [](CharpyParameters& p) { p.parts = 8; p.solver = plastic::SolverKind::DirectJoint; }, CharpyVerdict::Stable, 1.0},
	// 16 parts of elastic-plastic under the direct solve booked 209.2 J for 165.2 J lost before patch 0041: the contacts'
	// correction turned the outer joints' shear, axial and torsion locks (160.9 J now). The specimen still goes over the
	// anvils (issue 25), so only the energy is checked here
	{"parts16_elastic_plastic_direct", CharpyMethod::ElasticPlastic, [](CharpyParameters& p) { p.parts = 16; p.solver = plastic::SolverKind::DirectJoint; }, CharpyVerdict::Stable, 1.0},
	// sequential impulse's failing cells under the new method: stable, through the gap, no more work booked than lost
	{"parts32_plastic_hinge_new", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { newMethod(p); p.parts = 32; }, CharpyVerdict::Stable, 1.0, true},
	{"parts32_elastic_plastic_new", CharpyMethod::ElasticPlastic, [](CharpyParameters& p) { newMethod(p); p.parts = 32; }, CharpyVerdict::Stable, 1.0, true},
	{"parts16_plastic_hinge_new", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { newMethod(p); p.parts = 16; }, CharpyVerdict::Stable, 1.0, true},
	{"parts8_elastic_plastic_new", CharpyMethod::ElasticPlastic, [](CharpyParameters& p) { newMethod(p); p.parts = 8; }, CharpyVerdict::Stable, 1.0, true},
	{"iterations1_elastic_plastic2_new", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { newMethod(p); p.solver_iterations = 1; }, CharpyVerdict::Stable, 1.0, true},
	{"dt1ms_plastic_hinge_new", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { newMethod(p); p.dt_s = 1e-3; }, CharpyVerdict::Stable, 1.0, true},
	{"dt60Hz_elastic_plastic2_new", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { newMethod(p); p.dt_s = 1.0 / 60; }, CharpyVerdict::Stable, 1.0, true},
	// the hammer is short of the energy the section needs: stable, in front of the anvils
	{"fy2000_plastic_hinge_new", CharpyMethod::PlasticHinge, [](CharpyParameters& p) { newMethod(p); p.yield_stress_pa = 2000e6; }, CharpyVerdict::Stable, 1.0},
	{"stiffE_elastic_plastic2", CharpyMethod::ElasticPlastic2, [](CharpyParameters& p) { p.youngs_modulus_pa = 2000e9; }, CharpyVerdict::Stable},
	// upstream, as it is: the spring explodes (thesis fig. 3.5), a rigid specimen tunnels at 1/60 s. The exploding
	// spring's fastest part reaches 98-173 m/s around the 100 m/s blow-up threshold (98 m/s with 800 J above E0 since
	// the contact substeps' near test takes the closing speed along the normal), so the steps decide between the two
	{"fy800_spring_upstream", CharpyMethod::Spring, [](CharpyParameters& p) { p.yield_stress_pa = 800e6; }, CharpyVerdict::BlowUp, 1.02, false, true},
	{"default_spring2_upstream", CharpyMethod::Spring2, [](CharpyParameters&) {}, CharpyVerdict::EnergyGain},
	{"dt60Hz_nosub_rigid_upstream", CharpyMethod::RigidBody, [](CharpyParameters& p) { p.dt_s = 1.0 / 60; p.contact_substep_s = 0; }, CharpyVerdict::Tunnelling},
};

class StabilityCell : public ::testing::TestWithParam<Cell>
{
};
}  // namespace

TEST_P(StabilityCell, HasTheExpectedVerdict)
{
	CharpyParameters p;
	const CharpyResult r = run(GetParam(), p);
	std::string why;
	const CharpyVerdict verdict = classifyCharpyRun(r, &why);
	if (GetParam().eitherExplosion)
	{
		EXPECT_TRUE(verdict == CharpyVerdict::BlowUp || verdict == CharpyVerdict::EnergyGain) << why;
		EXPECT_GT(r.max_energy_gain_J, r.E0_J) << why;
	}
	else
	{
		EXPECT_EQ(charpyVerdictName(verdict), charpyVerdictName(GetParam().expected)) << why;
	}
	if (GetParam().expected == CharpyVerdict::Stable)
	{
		EXPECT_TRUE(r.finite);
		EXPECT_LE(r.max_energy_gain_J, 0.01 * r.E0_J) << "energy gain";
		EXPECT_GT(r.plastic_work_J, 0.05 * r.analytic_J) << "no plastic work: the hammer went through";
		EXPECT_LE(r.plastic_work_J, r.energy_loss_J * GetParam().maxWorkPerLoss) << "more plastic work than energy lost";
	}
	if (GetParam().mustBeAccurate)
	{
		std::string accuracyWhy;
		EXPECT_EQ(charpyAccuracyName(classifyCharpyAccuracy(r, &accuracyWhy)), "accurate") << accuracyWhy;
	}
}

INSTANTIATE_TEST_SUITE_P(Matrix, StabilityCell, ::testing::ValuesIn(kCells),
						 [](const ::testing::TestParamInfo<Cell>& info) { return std::string(info.param.name); });

// The new method's cells of numerics only (parts, frames, iterations) lose what its default case loses, within 5 %:
// the case changes how the same test is computed, not the test
TEST(StabilityNewMethod, NumericCasesLoseWhatTheDefaultCaseLoses)
{
	CharpyParameters base;
	base.end_when_clear = false;
	base.method = CharpyMethod::ElasticPlastic;
	newMethod(base);
	const CharpyResult reference = runCharpy(base);
	ASSERT_EQ(classifyCharpyRun(reference), CharpyVerdict::Stable);
	for (void (*apply)(CharpyParameters&) : {+[](CharpyParameters& p) { p.parts = 32; }, +[](CharpyParameters& p) { p.parts = 8; },
											  +[](CharpyParameters& p) { p.dt_s = 1.0 / 60; }, +[](CharpyParameters& p) { p.dt_s = 0.033; },
											  +[](CharpyParameters& p) { p.solver_iterations = 1; }})
	{
		CharpyParameters p = base;
		apply(p);
		const CharpyResult r = runCharpy(p);
		EXPECT_NEAR(r.energy_loss_J, reference.energy_loss_J, 0.05 * reference.energy_loss_J) << toJson(r);
	}
}

// At 54 m/s a half is thrown from between the striker and an anvil at about 400 m/s, 24 m in the 60 ms, in the
// converged run (2 us substeps, the contact rows' turn prediction of patch 0055: 401 / 407 / 412 m/s at 2 / 1 / 0.5 us;
// 365 m/s, 21.7 m without it) as in the new method's: not a blow-up (the speed limit is 20 x 54 m/s), though a fixed
// 20 m distance limit called it one. The new method's throw is within 10 % of the converged run's.
TEST(StabilityNewMethod, AHalfThrownAt54MetresPerSecondIsNotABlowUpAndFliesAsInTheConvergedRun)
{
	CharpyParameters p;
	p.end_when_clear = false;
	p.method = CharpyMethod::PlasticHinge;
	p.initial_energy_j = 283.048663 * (50 / 4.41358004) * (50 / 4.41358004);  // ci/stability.py's v50
	CharpyParameters converged = p;
	converged.solver = plastic::SolverKind::DirectJoint;
	converged.speculative_contacts = true;
	converged.contact_substep_s = 2e-6;
	converged.contact_turn_prediction = true;  // as the world's contact stepping has it
	newMethod(p);
	const CharpyResult r = runCharpy(p);
	const CharpyResult c = runCharpy(converged);
	std::string why;
	EXPECT_EQ(charpyVerdictName(classifyCharpyRun(r, &why)), "stable") << why;
	EXPECT_EQ(charpyVerdictName(classifyCharpyRun(c, &why)), "stable") << why;
	EXPECT_GT(c.max_distance_m, 20.0) << "the converged run no longer throws a half past the old limit";
	EXPECT_NEAR(r.max_speed_m_s, c.max_speed_m_s, 0.1 * c.max_speed_m_s);
	EXPECT_NEAR(r.max_distance_m, c.max_distance_m, 0.1 * c.max_distance_m);
	EXPECT_LE(r.max_energy_gain_J, 0.01 * r.E0_J);
}
