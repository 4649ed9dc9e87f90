// The Charpy test with btDirectJointSolver (--solver=direct, patch 0019) at internal steps without contact substeps,
// against the converged sequential-impulse run of the same geometry (0.1 ms frames, 0.01 ms contact substeps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "CharpyRun.h"
#include "CharpyScene.h"
#include "CharpyVerdict.h"

namespace
{
CharpyParameters geometry(bool standard)
{
	CharpyParameters p;
	if (standard)
	{
		applyStandardGeometry(p);
	}
	return p;
}

// The direct solve with speculative contacts, 1 ms frames.
CharpyParameters directSpeculative(bool standard)
{
	CharpyParameters p = geometry(standard);
	p.solver = plastic::SolverKind::DirectJoint;
	p.speculative_contacts = true;
	p.dt_s = 1e-3;
	return p;
}

// The coarse setting of issue 25: the direct solve, speculative contacts, 60 us contact substeps, 1 ms frames.
CharpyParameters coarseSpeculative()
{
	CharpyParameters p = directSpeculative(false);
	p.contact_substep_s = 6e-5;
	return p;
}

// One internal step per frame: no contact substeps.
CharpyResult runWithoutSubsteps(bool standard, plastic::SolverKind solver, double step_s)
{
	CharpyParameters p = geometry(standard);
	p.solver = solver;
	p.dt_s = step_s;
	p.contact_substep_s = 0;
	return runCharpy(p);
}
}  // namespace

// The 21 g halves lie between the 19.5 kg hammer and the anvils. Sequential impulse moves each by its mass over the
// hammer's per iteration, so at 0.1 ms steps and more its 10 iterations let the hammer push the specimen through the
// anvils nearly straight. The direct solve holds the specimen at every step up to 1 ms: it folds far enough to fit the
// gap. Without substeps the halves sink into the nose and the anvils, and the contacts' correction turns the yielding
// hinge; since patch 0041 the hinge books that flow only as far as the losses of the call pay for it, so its plastic
// work is no more than the energy lost. Measured (thesis geometry, plastic hinge): plastic work 120.7, 112.4, 104.0,
// 114.5, 143.2 J for 129.6, 119.8, 107.1, 115.4, 143.8 J lost at 0.05, 0.1, 0.2, 0.5, 1 ms, against the converged
// 128.9 J of 132.7 J (before patch 0041 it booked 127.4, 130.6, 126.8, 130.0, 151.6 J: up to 27 J beyond the loss);
// sequential impulse 100.9, 12.5, 0, 0, 0 J.
TEST(CharpyDirectSolve, HoldsTheSpecimenWithoutSubstepsAtEveryStepUpToOneMillisecond)
{
	const CharpyResult converged = runCharpy(geometry(false));
	ASSERT_TRUE(converged.passed_anvils && !converged.tunnelled);
	for (double step : {5e-5, 1e-4, 2e-4, 5e-4, 1e-3})
	{
		const CharpyResult direct = runWithoutSubsteps(false, plastic::SolverKind::DirectJoint, step);
		EXPECT_EQ(direct.solver, "direct");
		EXPECT_TRUE(direct.finite) << step;
		EXPECT_TRUE(direct.passed_anvils) << step;
		EXPECT_FALSE(direct.tunnelled) << step;
		EXPECT_GE(direct.max_bend_rad, direct.min_pass_bend_rad) << step << ": it passed the anvils bent too little to fit the gap";
		EXPECT_LE(direct.max_energy_gain_J, 0.01 * direct.E0_J) << step;
		EXPECT_LE(direct.max_booked_excess_J, 0.01 * direct.E0_J) << step << ": plastic work beyond the energy lost";
		EXPECT_GT(direct.plastic_work_J, 0.75 * converged.plastic_work_J) << step;
		if (step >= 1e-4)
		{
			const CharpyResult sequential = runWithoutSubsteps(false, plastic::SolverKind::SequentialImpulse, step);
			EXPECT_LT(sequential.plastic_work_J, 0.5 * converged.plastic_work_J)
				<< step << ": sequential impulse held the specimen too; this test no longer shows what the direct solve adds";
		}
	}
}

// The standard striker (a 2 mm edge at mid-span, 5.2 m/s) at 0.05 and 0.1 ms steps without substeps or speculative
// contacts: the halves sink 0.5 and 1.7 mm into the anvils, and the position correction that moves them out (without
// momentum since patch 0038) also turns the yielding hinge. Before patch 0041 the joints booked that flow, which no
// energy paid for: 124.6 and 126.9 J of plastic work for 111.9 and 100.0 J lost (converged 120.0 J). Now they book it
// only as far as the losses of the call pay for it: 105.5 and 93.2 J, and at 0.1 ms the halves get behind the anvils
// bent 0.48 rad more than the hinge booked, which the verdict calls a specimen that came apart (measured; sequential
// impulse books 103.1 and 41.5 J).
TEST(CharpyDirectSolve, StandardStrikerWithoutSubstepsBooksNoPlasticWorkBeyondItsLoss)
{
	const CharpyResult converged = runCharpy(geometry(true));
	for (double step : {5e-5, 1e-4})
	{
		const CharpyResult direct = runWithoutSubsteps(true, plastic::SolverKind::DirectJoint, step);
		EXPECT_TRUE(direct.passed_anvils) << step;
		EXPECT_FALSE(direct.tunnelled) << step;
		EXPECT_LE(direct.plastic_work_J, direct.energy_loss_J) << step;
		EXPECT_LE(direct.max_booked_excess_J, 0.01 * direct.E0_J) << step;
		EXPECT_GT(direct.plastic_work_J, 0.7 * converged.plastic_work_J) << step;
		const CharpyResult sequential = runWithoutSubsteps(true, plastic::SolverKind::SequentialImpulse, step);
		EXPECT_LT(sequential.plastic_work_J, 0.9 * converged.plastic_work_J) << step;
	}
	std::string why;
	EXPECT_EQ(charpyVerdictName(classifyCharpyRun(runWithoutSubsteps(true, plastic::SolverKind::DirectJoint, 1e-4), &why)), "came-apart") << why;
}

// Where the direct solve is not yet enough: without substeps or speculative contacts the halves sink 0.4 to 2.1 mm into
// the anvils and the nose, and the position correction that moves them out (without momentum since patch 0038) also
// turns the yielding hinge, for nothing: the loss is 2 to 19 % under the converged loss between 0.05 and 0.5 ms
// (measured 129.6, 119.8, 107.1, 115.4 J at 0.05, 0.1, 0.2, 0.5 ms against 132.7 J; issue 25). Before patch 0041 the
// joints booked that flow, and the loss fell below the booked plastic work; now they book it as far as the losses of
// the call pay for it (120.7, 112.4, 104.0, 114.5 J). This pins that the booked work never exceeds the loss, and that
// the loss keeps four fifths of the converged loss.
TEST(CharpyDirectSolve, AtCoarseStepsThePlasticWorkIsNoMoreThanTheLossAndTheLossFourFifthsOfConverged)
{
	const CharpyResult converged = runCharpy(geometry(false));
	for (double step : {5e-5, 1e-4, 2e-4})
	{
		const CharpyResult direct = runWithoutSubsteps(false, plastic::SolverKind::DirectJoint, step);
		EXPECT_LE(direct.plastic_work_J, direct.energy_loss_J) << step;
		EXPECT_GT(direct.energy_loss_J, 0.8 * converged.energy_loss_J) << step;
	}
}

// max_booked_excess_J (CharpyScene::maxBookedExcess_j): the largest excess over a run of the plastic work booked over
// the energy lost. Every other loss is >= 0, so an excess is flow no force paid for (it is a lower bound of that flow:
// the run's other losses can hide some). Standard striker, ISO anvils, friction 0.1, 5.2 m/s, 60 us substeps in 1 ms
// frames: without speculative contacts the halves sink into the anvils' rounded edges and the striker, and the
// contacts' position correction turns the yielding hinge: the joint books 3.17 J the hammer never gave (measured).
// With them, 0.0 J: since patch 0040 a compound's children get speculative contacts too, and the ISO anvils (a capsule
// edge and boxes) and the hammer (its striker) are compounds. Before it a child got its contacts only once its box
// overlapped a half's, and the runs booked up to 7.2 J so (2.96 J in this one; 20 of the 25 ISO runs at friction
// 0.05-0.25 and 5.1-5.3 m/s over 0.1 J, mostly at the anvils' edges: a review's split left at most 0.10 J with the
// anvils' children alone and 2.78 J with the hammer's alone), and the same runs with the sharp anvils (boxes) 0.0 to
// 0.1 J. At 10 us there is nothing to correct (0.0 J). Since patch 0041 the joints book the correction's flow only as
// far as the losses of the call pay for it: the run without speculative contacts books no excess (0.00 J), and its
// hinge got behind the anvils bent 0.064 rad more than it booked (measured), where with them the two agree within
// 1e-5 rad.
TEST(CharpyDirectSolve, SpeculativeContactsOfCompoundChildrenLeaveNoFlowThatNoForcePaidFor)
{
	auto run = [](double anvilRadius_m, double substep_s, bool speculative) {
		CharpyParameters p = coarseSpeculative();
		applyStandardGeometry(p);
		p.friction = 0.1;
		p.impact_speed_m_s = 5.2;
		if (anvilRadius_m > 0)
		{
			p.anvil_radius_m = anvilRadius_m;
			p.anvil_taper_rad = 0.192;
		}
		p.contact_substep_s = substep_s;
		p.speculative_contacts = speculative;
		return runCharpy(p);
	};
	// the bend the hinge made beyond the rotation it booked, when the specimen got behind the anvils
	auto unbooked = [](const CharpyResult& r) { return r.pass_end_bend_angle_rad - r.pass_plastic_rotation_rad; };
	const CharpyResult without = run(0.001, 6e-5, false);
	EXPECT_GT(unbooked(without), 0.03) << "the correction's flow without speculative contacts";
	EXPECT_LT(without.max_booked_excess_J, 0.1) << "patch 0041: not booked beyond the loss";
	for (const CharpyResult& with : {run(0.001, 6e-5, true), run(0, 6e-5, true), run(0.001, 1e-5, true)})
	{
		EXPECT_LT(with.max_booked_excess_J, 0.1);
		EXPECT_LT(std::fabs(unbooked(with)), 1e-3);
	}
}

// Speculative box-box contacts (patch 0036, --speculative-contacts): the specimen's halves, the sharp anvils and the flat
// nose are boxes, which get contacts before they overlap (within the contact breaking threshold, 0.3 mm here), so at
// contact steps over which the hammer closes well within that (4.4 m/s x 30 us = 0.13 mm) no half sinks into an
// anvil; with them a part's edge across a face touches it at both ends (patch 0042) and the world is stepped to the
// nose's touch (plastic::timeToTouch_s), so the contact's first step starts touching. The reference is the same scene
// converged: 2 us contact steps, checked against the sequential-impulse solver at 2 us (129.28 and 129.1 J, measured).
// In contact the world steps at the contact substep on a clock of its own whose ticks are the multiples of the substep
// from the touch (plastic::ContactSubstepPolicy), so the frame step changes only the steps before the first tick:
// measured (build/bin/charpy --solver=direct --speculative-contacts --contact-substep=S --dt=F, frames from 0.1 ms to
// 1/60 s, --free-step=5e-3, against 129.24 J at 2 us) +0.2 % at 10 us in 260 internal steps, +1.0 % at 30 us in
// 89, +2.5 % at 60 us in 48, +2.3 % at 80 us in 38-39; the frame step moves the loss by at most 0.01 %. Out of
// contact the frames are gathered into steps of up to the 5 ms free step (ContactSubstepSettings::free_step_s): without
// it a frame was at least one step, and 0.1 ms frames took the most (90-110 at 30 us: after the pass 22 frames went
// by before the halves were clear of the anvils). The test ends at the internal step that leaves the specimen clear,
// not at the frame's end (a 1/60 s frame took it on to 16.7 ms, 0.03 % more loss at 30 us). No yielding joint is turned by the contacts' correction (max_booked_excess_J 0 at every one). At 100 us,
// past the reach (the nose closes 0.44 mm in a step; the runner warns), +2.9 % in 39 steps. A step within which a half
// runs off an anvil's edge ends there (plastic::timeToRelease_s); before, the bend ran on past the pass angle to the
// step's end: +1.5 / +4.5 / +7.9 % at 30 / 60 / 100 us (2.037 rad against 1.991 at 60 us). Before the step to the
// touch and patch 0042: +1.0 /
// +2.0 / +4.1 / +7.8 / +4.2 % at 10 / 30 / 60 / 80 / 100 us, the striker's contact met within a step carrying the
// bend's load across the gap, and the halves sinking into the anvils' edges at 100 us, whose correction offset part of
// the loss. Without speculative contacts, 125.2 J at 50 us with the halves 0.6 mm deep in the anvils.
TEST(CharpyDirectSolve, SpeculativeContactsKeepTheLossWithinThreePercentOfConvergedAtThirtyMicrosecondsAndFiveAtSixtyAndEightyInAHundredSteps)
{
	CharpyParameters p = geometry(false);
	p.solver = plastic::SolverKind::DirectJoint;
	p.speculative_contacts = true;
	p.contact_substep_s = 2e-6;
	const CharpyResult converged = runCharpy(p);
	CharpyParameters sequential = p;
	sequential.solver = plastic::SolverKind::SequentialImpulse;
	EXPECT_NEAR(runCharpy(sequential).energy_loss_J, converged.energy_loss_J, 0.005 * converged.energy_loss_J)
		<< "the converged loss depends on the solver";
	for (double substep : {1e-5, 3e-5, 6e-5, 8e-5})
	{
		double least = 1e300, most = -1e300;
		long fewest = 1L << 30, mostSteps = 0;
		for (double frame : {1e-4, 2e-4, 5e-4, 1e-3, 1.0 / 60})
		{
			p.contact_substep_s = substep;
			p.dt_s = frame;
			p.free_step_s = 5e-3;
			const CharpyResult r = runCharpy(p);
			least = std::min(least, r.energy_loss_J);
			most = std::max(most, r.energy_loss_J);
			const double tolerance = substep <= 3e-5 ? 0.03 : 0.05;
			EXPECT_NEAR(r.energy_loss_J, converged.energy_loss_J, tolerance * converged.energy_loss_J) << substep << " s in " << frame << " s frames";
			EXPECT_LT(r.max_booked_excess_J, 0.001 * r.E0_J) << substep << " s in " << frame << " s frames";
			// measured at most 5 um at 10 us, 40 um at 30 us, 0.12 mm at 60 us, 0.14 mm at 80 us
			EXPECT_LT(r.max_penetration_m, substep <= 3e-5 ? 0.0001 : 0.0003) << substep << " s in " << frame << " s frames";
			// issue 25's budget, the whole test in at most 100 internal steps, met at 30 us (89), 60 us (48) and 80
			// us (38-39) at every frame step (with the near test's 1 mm allowance 152, 79 and 52 at 30, 60 and 100 us)
			const int budget = substep == 3e-5 ? 100 : substep == 6e-5 ? 55 : substep == 8e-5 ? 45 : 300;
			EXPECT_LE(r.internal_steps, budget) << substep << " s in " << frame << " s frames";
			// the test ends at the internal step that leaves the specimen clear, not at the frame's end (measured 3.9-8.1
			// ms; at 1/60 s it ran on to 16.7 ms)
			EXPECT_LT(r.end_time_s, 0.012) << substep << " s in " << frame << " s frames";
			fewest = std::min(fewest, r.internal_steps);
			mostSteps = std::max(mostSteps, r.internal_steps);
		}
		EXPECT_LT(most - least, 0.005 * converged.energy_loss_J) << "the frame step changes the loss at " << substep << " s substeps";
		// with the free step and the end at the internal step that leaves the specimen clear, the frame step no longer
		// changes the steps (measured 260, 89, 48, 38-39 steps at 10, 30, 60, 80 us; 90-110 at 30 us before, the most in 0.1 ms frames)
		EXPECT_LE(mostSteps - fewest, 2) << "the frame step changes the internal steps at " << substep << " s substeps";
	}
	p.contact_substep_s = 5e-5;
	p.dt_s = 1e-4;
	p.speculative_contacts = false;
	const CharpyResult without = runCharpy(p);
	EXPECT_GT(without.max_penetration_m, 0.0004) << "without speculative contacts the halves sink into the anvils";
}

// Patch 0036 removes a speculative point whose end has left the other box (the detection no longer reports it): at the
// striker's corners such points outlived their feature and bent the joints near the anvils of a specimen of 32 parts
// (163.7 J at 2 us, against 130.1 J without speculative contacts). The same specimen with and without them at 3 us
// contact substeps: measured 136.6 and 130.1 J. With them the loss scatters with the step: 134.5 / 132.0 / 136.3 /
// 136.6 / 132.3 J at 2 / 2.5 / 2.94 / 3 / 4 us, +2.3 to +5.9 % over the 130.0-131.3 J without them (build/bin/charpy
// --solver=direct --parts=32 --contact-substep=S --dt=1e-4, with and without --speculative-contacts).
TEST(CharpyDirectSolve, SpeculativeContactsOfAManyPartSpecimenAgreeWithoutThemAtFineSteps)
{
	for (int parts : {32})
	{
		CharpyParameters p = geometry(false);
		p.parts = parts;
		p.solver = plastic::SolverKind::DirectJoint;
		p.contact_substep_s = 3e-6;
		const CharpyResult without = runCharpy(p);
		p.speculative_contacts = true;
		const CharpyResult with = runCharpy(p);
		EXPECT_TRUE(without.passed_anvils && with.passed_anvils) << parts;
		EXPECT_NEAR(with.energy_loss_J, without.energy_loss_J, 0.07 * without.energy_loss_J) << parts << " parts";
		EXPECT_NEAR(with.plastic_work_J, without.plastic_work_J, 0.07 * without.plastic_work_J) << parts << " parts";
	}
}

TEST(CharpyDirectSolve, ManyPartSpecimensAtFineStepsPassTheAnvilsAsTheHalvesDo)
{
	// Elastic-plastic specimens in parts stayed in front of the anvils where the halves pass, each time a nose caught
	// on a seam between parts (plastic::JoinedFaces):
	// - 4 parts at 1-2.5 us, 234 J: the nose's edge caught on a seam, and the side joint slipped at its shear and axial
	//   caps (127 J for 0.035 rad of rotation);
	// - 8 parts at 5 us, 219 J: the flat nose's corner caught on the end part's corner, 8 um out of line with the next
	//   part, through a box-box contact whose normal lay 49.5 degrees from the end face; the end part was wedged
	//   between the nose and the anvil and its joint sheared at its cap (88 J);
	// - 16 parts at 5 us, 201 J: the end joint's shear at the pinch made a 0.16 mm step first, more than the 69 um that
	//   4 % of the part's half length gave the seam.
	struct Case
	{
		double substep_s;
		std::vector<int> parts;
		double tolerance;  // of the halves' loss
	};
	for (const Case& c : {Case{2e-6, {4}, 0.02}, Case{5e-6, {8, 16}, 0.06}})
	{
		CharpyParameters p = coarseSpeculative();
		p.method = CharpyMethod::ElasticPlastic;
		p.contact_substep_s = c.substep_s;
		const CharpyResult halves = runCharpy(p);
		for (int parts : c.parts)
		{
			p.parts = parts;
			const CharpyResult many = runCharpy(p);
			EXPECT_TRUE(many.passed_anvils && !many.over_the_top) << parts << " parts";
			EXPECT_NEAR(many.energy_loss_J, halves.energy_loss_J, c.tolerance * halves.energy_loss_J) << parts << " parts";
		}
	}
}

// Frames shorter than the contact substep (20 us frames, 60 us substeps): in contact the world steps every third
// frame and owes the rest, far from contact it steps every frame. The run is the one of 1 ms frames (the same steps
// in contact), and its history moves forward: a row per frame that moved the world, from the first step on.
TEST(CharpyDirectSolve, FramesShorterThanTheSubstepGiveTheSameLossAndAHistoryThatMovesForward)
{
	CharpyParameters p = coarseSpeculative();
	const CharpyResult coarse = runCharpy(p);
	p.dt_s = 2e-5;
	std::ostringstream history;
	const CharpyResult fine = runCharpy(p, &history);
	EXPECT_NEAR(fine.energy_loss_J, coarse.energy_loss_J, 0.002 * coarse.energy_loss_J);
	EXPECT_GT(fine.frames, fine.internal_steps) << "in contact, some 20 us frames step nothing";
	std::istringstream lines(history.str());
	std::string line;
	std::getline(lines, line);  // the header
	double previous = 0;
	int rows = 0;
	while (std::getline(lines, line))
	{
		const double t = std::stod(line.substr(0, line.find(',')));
		EXPECT_GT(t, previous) << "row " << rows;
		previous = t;
		rows++;
	}
	EXPECT_GT(rows, 0);
	EXPECT_LT(rows, fine.frames);
	EXPECT_NEAR(previous, fine.end_time_s, 1e-12);
}

// With speculative contacts, a run whose internal step in contact lets the hammer close more than the contacts' reach
// says so before it runs, and names a substep that does not (the runner prints it and reports it in --json). Such
// steps are where the cases off the sweep fail: 7 m/s at 60 us is +7.9 to +10.5 % (README).
TEST(CharpyDirectSolve, ARunWhoseStepClosesPastTheSpeculativeReachSaysSoBeforeItRuns)
{
	CharpyParameters p = coarseSpeculative();
	EXPECT_EQ("", CharpyScene(p).speculativeReachWarning()) << "4.4 m/s closes 0.26 mm in 60 us";
	p.impact_speed_m_s = 7.0;
	const CharpyScene scene(p);
	const std::string warning = scene.speculativeReachWarning();
	EXPECT_NE(std::string::npos, warning.find("--contact-substep of at most")) << warning;
	// the advice holds: at the substep it names, no warning
	p.contact_substep_s = 0.99 * scene.speculativeReach_m() / scene.impactSpeed_m_s();
	EXPECT_EQ("", CharpyScene(p).speculativeReachWarning());
	// smaller parts reach less (their breaking threshold follows their size): 32 parts warn at 60 us and 4.4 m/s
	p = coarseSpeculative();
	p.parts = 32;
	EXPECT_NE("", CharpyScene(p).speculativeReachWarning());
	// no speculative contacts, no reach to warn about
	p.speculative_contacts = false;
	EXPECT_EQ("", CharpyScene(p).speculativeReachWarning());
	// without substeps the step in contact is the frame
	p = coarseSpeculative();
	p.contact_substep_s = 0;
	EXPECT_NE("", CharpyScene(p).speculativeReachWarning());
	// a contact travel longer than the reach (0.31 mm for the halves) is told, with the reach to use
	p = coarseSpeculative();
	p.contact_travel_m = 3e-4;
	EXPECT_EQ("", CharpyScene(p).speculativeReachWarning());
	p.contact_travel_m = 5e-4;
	const std::string travel = CharpyScene(p).speculativeReachWarning();
	EXPECT_NE(std::string::npos, travel.find("the 0.500 mm contact travel")) << travel;
	EXPECT_NE(std::string::npos, travel.find("--contact-travel of at most 0.000309")) << travel;
	p.parts = 32;
	p.contact_substep_s = 2e-5;
	p.contact_travel_m = 3e-4;
	EXPECT_NE(std::string::npos, CharpyScene(p).speculativeReachWarning().find("--contact-travel of at most"));
}

// Patch 0042 (btDispatcherInfo::m_boxBoxEdgesAcrossFaces, the runner's --box-edges-across-faces). Plastic analysis puts
// the Charpy loss at Mp * theta_pass (127.4 J) for any number of parts; the specimen in two halves folds between the
// anvils under the direct solve at 131.5 J (elastic-plastic). In 16 parts, with upstream's box-box contacts, the
// hammer's edge (the hammer swings about the specimen's axis) loads one end of a part's face, the joints twist and
// shear at their caps, and the specimen goes over the anvils at 165.2 J; with an edge across a face held at both ends,
// 136.9 J (measured).
TEST(CharpyDirectSolve, AnElasticPlasticSpecimenInSixteenPartsFoldsAsTheHalvesDoWhenBoxEdgesTouchAcrossFaces)
{
	CharpyParameters p;
	p.method = CharpyMethod::ElasticPlastic;
	p.solver = plastic::SolverKind::DirectJoint;
	p.box_edges_across_faces = true;
	const CharpyResult halves = runCharpy(p);
	p.parts = 16;
	const CharpyResult parts = runCharpy(p);
	std::string why;
	EXPECT_EQ(charpyVerdictName(classifyCharpyRun(parts, &why)), "stable") << why;
	EXPECT_EQ(charpyAccuracyName(classifyCharpyAccuracy(parts, &why)), "accurate") << why;
	EXPECT_NEAR(halves.energy_loss_J, parts.energy_loss_J, 0.05 * halves.energy_loss_J);
	EXPECT_LE(parts.plastic_work_J, parts.energy_loss_J);
	EXPECT_NEAR(parts.analytic_J, parts.plastic_work_J, 0.06 * parts.analytic_J) << "Mp * theta_pass";

	p.box_edges_across_faces = false;
	const CharpyResult upstream = runCharpy(p);
	EXPECT_GT(upstream.energy_loss_J, 1.2 * halves.energy_loss_J) << "the control: upstream's contacts twist the parts";
}

// The standard striker at 3 m/s (friction 0.1, speculative contacts, 0.07 ms substeps, frames gathered into free steps
// of 5 ms) has too little energy to break through: it stalls in the folded specimen, which rests pressed on the anvils
// for the rest of the 60 ms run. Held at the substep that rest took 871 steps (sharp anvils, 1 ms frames). With a
// contact travel of the speculative reach (0.3 mm), a contact whose pairs move less than that in a longer step is
// stepped that far (not while the joint flows), and its frames are gathered: the same loss (114.13 J at 2 us
// substeps) in 174-183 steps at 0.1 ms, 1 ms and 1/60 s frames (60 ms runs; the test runs 30 ms), and the ISO
// anvils' contacts as shallow as in substeps (3 um; 0.11-0.2 mm when the travel stepped the slow end of the fold). At
// 3.5 m/s the hammer breaks through: its loss is the substeps' (143.30 J with the ISO anvils at each frame step)
// within 0.4 % (0.02 % before patch 0051; with it 143.80 J in substeps, 143.34 and 143.77 J with the travel in 0.1 ms
// and 1/60 s frames, each within 0.25 % of 143.47 J at 10 us substeps).

TEST(CharpyDirectSolve, AHammerStalledInTheSpecimenIsSteppedAsFarAsItsContactsMove)
{
	CharpyParameters p = geometry(true);
	p.impact_speed_m_s = 3.0;
	p.friction = 0.1;
	p.solver = plastic::SolverKind::DirectJoint;
	p.speculative_contacts = true;
	p.contact_substep_s = 7e-5;
	p.free_step_s = 5e-3;
	p.duration_s = 0.03;  // the hammer has stalled by 13 ms; half the run's 60 ms keeps the test short under ASan
	for (const bool iso : {false, true})
	{
		p.anvil_radius_m = iso ? 1e-3 : 0;
		p.anvil_taper_rad = iso ? 0.192 : 0;
		p.contact_travel_m = 0;
		p.dt_s = 1e-3;
		const CharpyResult substeps = runCharpy(p);
		ASSERT_FALSE(substeps.passed_anvils) << iso;  // the control: it stalls, and the substep holds
		EXPECT_GT(substeps.internal_steps, 350) << iso;
		p.contact_travel_m = 3e-4;
		// (the ISO anvils at one frame step: each run costs a second, ten under the sanitizers)
		for (const double frame_s : iso ? std::vector<double>{1.0 / 60.0} : std::vector<double>{1e-4, 1e-3, 1.0 / 60.0})
		{
			p.dt_s = frame_s;
			const CharpyResult travelled = runCharpy(p);
			EXPECT_FALSE(travelled.passed_anvils) << iso << " " << frame_s;
			EXPECT_NEAR(travelled.energy_loss_J, substeps.energy_loss_J, 1e-3 * substeps.energy_loss_J) << iso << " " << frame_s;
			EXPECT_LT(travelled.internal_steps, 0.5 * substeps.internal_steps) << iso << " " << frame_s;
			EXPECT_LT(travelled.max_penetration_m, 1e-5) << iso << " " << frame_s;
			EXPECT_LE(travelled.max_booked_excess_J, 1e-3 * substeps.E0_J) << iso << " " << frame_s;
		}
	}
	p.duration_s = CharpyParameters().duration_s;
	// breaking through, at 3.5 m/s with the ISO anvils: the loss of the substep run
	p.impact_speed_m_s = 3.5;
	p.contact_travel_m = 0;
	p.dt_s = 1e-3;
	const CharpyResult through = runCharpy(p);
	ASSERT_TRUE(through.passed_anvils);
	p.contact_travel_m = 3e-4;
	for (const double frame_s : {1e-4, 1.0 / 60.0})
	{
		p.dt_s = frame_s;
		const CharpyResult travelled = runCharpy(p);
		EXPECT_TRUE(travelled.passed_anvils) << frame_s;
		EXPECT_NEAR(travelled.energy_loss_J, through.energy_loss_J, 0.004 * through.energy_loss_J) << frame_s;
		EXPECT_LE(travelled.internal_steps, through.internal_steps) << frame_s;
	}
}

// Patch 0048: a joint's split correction does not pass through another joint's capped rows. The standard striker on
// the sharp anvils at friction 0.1, 10 and 20 us substeps lengthened where the contacts move slowly
// (--contact-travel=3e-4): the 490 us step the travel takes while the specimen rests on the anvils made the hammer's
// pivot split its correction for the next 490 us (patch 0044), which pushed through the striker's contacts and turned
// the halves about the yielding hinge's capped lock, 0.07 mrad of drift that the lock pushed back with the plastic
// moment after the fold, pressing the legs on the walls (3 kN a leg) while the hammer dragged them through the gap:
// 168.43 and 162.56 J lost, in 708 and 479 internal steps. The same runs without the longer steps lose 142.86 and
// 142.85 J; 2 us substeps 142.74 J; the rigid-plastic friction model (ci/models/charpy_friction_model.py) 142.17 J.
TEST(CharpyDirectSolve, APivotsSplitCorrectionDoesNotPressTheFoldedSpecimenOnTheAnvilWalls)
{
	CharpyParameters p = directSpeculative(true);
	p.friction = 0.1;
	p.free_step_s = 5e-3;
	for (const double substep_s : {1e-5, 2e-5})
	{
		p.contact_substep_s = substep_s;
		p.contact_travel_m = 0;
		const CharpyResult substeps = runCharpy(p);
		ASSERT_TRUE(substeps.passed_anvils) << substep_s;
		p.contact_travel_m = 3e-4;
		const CharpyResult travelled = runCharpy(p);
		EXPECT_TRUE(travelled.passed_anvils) << substep_s;
		EXPECT_NEAR(travelled.energy_loss_J, substeps.energy_loss_J, 0.01 * substeps.energy_loss_J) << substep_s;
		EXPECT_LE(travelled.internal_steps, substeps.internal_steps) << substep_s;
	}
}

// Patch 0047: the elastic-plastic joints choose their rigid and elastic DOFs by the step being set up. At 3 us substeps
// with the hammer stalled at 3 m/s (thesis nose) the joint rings elastic; once its elastic energy is spent the policy
// takes a long step. Chosen by the 3 us step before it, the bending DOF was an explicit spring in a 2.5 ms step, 160
// times too stiff for it: 29 J (elastic-plastic) and 48 J (elastic-plastic2) of plastic work booked beyond the energy
// lost, verdict energy-gain (root cause by helper-52). Now none, and the loss is the plastic hinge's (113.32 J).
TEST(CharpyDirectSolve, ElasticPlasticJointsAfterFineSubstepsBookNoWorkTheLossDidNotPay)
{
	CharpyParameters p = directSpeculative(false);
	p.impact_speed_m_s = 3.0;
	p.contact_substep_s = 3e-6;
	p.free_step_s = 5e-3;
	p.duration_s = 0.025;  // the ringing ends and the long steps begin at 13.5 ms
	const CharpyResult hinge = runCharpy(p);
	// (elastic-plastic2 the same: both classes are held to it in ElasticPlasticTest.cpp)
	p.method = CharpyMethod::ElasticPlastic;
	const CharpyResult r = runCharpy(p);
	EXPECT_LE(r.max_booked_excess_J, 0.01 * r.E0_J) << toJson(r);
	EXPECT_EQ(classifyCharpyRun(r), CharpyVerdict::Stable) << toJson(r);
	EXPECT_NEAR(r.energy_loss_J, hinge.energy_loss_J, 0.01 * hinge.energy_loss_J) << toJson(r);
}

// Without the runner's contact substeps the striker closes 4.4 mm in a 1 ms frame and 74 mm in 1/60 s: the halves sank
// 3.7 mm into the anvils at 1 ms (145.2 J), and at 1/60 s the specimen was still in front of them when the hammer had
// passed (7.2 J). The world's contact stepping (patch 0053, --world-contact-travel at the speculative reach) cuts the
// frame itself where a pair in or near contact would move more than that, against 129.24 J at 2 us substeps: measured
// 131.20 J in 85 internal steps at 1 ms and 129.67 J in 84 at 1/60 s; 0.1 ms frames gathered into the world's fixed
// 1/60 s steps (--world-step, upstream's fixed-step stepSimulation) take the 1/60 s frames' steps (each 0.1 ms frame
// a step of its own took 100: the test's frames). Before the bound took a compound's children, the points of one near
// the other, the closing along the boxes' axes and the spin a body lost: 125 and 207 steps. 32 parts (their own
// converged run, 33 s, is 130.41 J): 131.51 J in 102 steps at 1 ms (192 before the closer look, 120 before the step
// search took geometric means).
TEST(CharpyDirectSolve, TheWorldsContactSteppingHoldsTheSpecimenWithinTwoPercentOfConvergedInAHundredStepsAndManyPartsWithinFive)
{
	CharpyParameters p = directSpeculative(false);
	p.contact_substep_s = 2e-6;
	const CharpyResult converged = runCharpy(p);
	for (int parts : {2, 32})
	{
		for (double frame : {1e-4, 1e-3, 1.0 / 60})
		{
			if (parts == 32 && frame != 1e-3) continue;
			CharpyParameters coarse = directSpeculative(false);
			coarse.parts = parts;
			coarse.dt_s = frame;
			coarse.contact_substep_s = 0;
			const CharpyResult whole = runCharpy(coarse);
			coarse.world_contact_travel_m = parts == 2 ? 3e-4 : 1.4e-4;
			if (frame < 1e-3) coarse.world_step_s = 1.0 / 60;
			const CharpyResult cut = runCharpy(coarse);
			std::ostringstream where;
			where << parts << " parts, " << frame << " s frames";
			if (frame >= 1e-3)
			{
				EXPECT_TRUE(whole.max_penetration_m > 0.001 || !whole.passed_anvils)
					<< where.str() << ": without the world's stepping the halves sink in or stay in front of the anvils";
			}
			if (parts == 2)
			{
				EXPECT_LE(cut.internal_steps, 100) << where.str();
			}
			EXPECT_TRUE(cut.passed_anvils && !cut.over_the_top && !cut.tunnelled) << where.str();
			EXPECT_NEAR(cut.energy_loss_J, converged.energy_loss_J, (parts == 2 ? 0.02 : 0.05) * converged.energy_loss_J) << where.str();
			EXPECT_LT(cut.max_penetration_m, parts == 2 ? coarse.world_contact_travel_m : 0.1 * coarse.specimen_width_m) << where.str();
			EXPECT_LT(cut.max_booked_excess_J, 0.001 * cut.E0_J) << where.str();
			EXPECT_LT(cut.max_energy_gain_J, 0.001 * cut.E0_J) << where.str();
			EXPECT_TRUE(cut.step_warning.empty()) << where.str() << ": " << cut.step_warning;
		}
	}
}

// The world's contact stepping takes a frame whole (stepSimulation): after the step that leaves the specimen clear it
// steps on to the frame's end in steps as long as no pair near contact limits, where the hammer's hinge loses energy
// (a pendulum's velocity projection: the 12 m/s hammer lost 25 J in each 1/60 s frame of 5.8 ms steps, none in
// 1 ms frames). That is no part of the test: its loss is read at the step that left the specimen clear, as the
// runner's own substeps end there. The standard striker at 12 m/s, friction 0.1, 1/60 s frames, against its converged
// run (2 us substeps, 144.2 J): 162.9 J (+13 %) read at the frame's end, 145.9 J (+1.2 %) at that step.
TEST(CharpyDirectSolve, AWorldSteppedFrameReadsTheTestWhereTheSpecimenWasClearNotAtTheFramesEnd)
{
	CharpyParameters p = directSpeculative(true);
	p.friction = 0.1;
	p.impact_speed_m_s = 12.0;
	p.dt_s = 1e-4;
	p.contact_substep_s = 2e-6;
	const CharpyResult converged = runCharpy(p);
	p.dt_s = 1.0 / 60;
	p.contact_substep_s = 0;
	p.world_contact_travel_m = 3e-4;
	const CharpyResult frame = runCharpy(p);
	EXPECT_TRUE(frame.passed_anvils && !frame.over_the_top && !frame.tunnelled) << toJson(frame);
	EXPECT_LT(frame.end_time_s, 0.5 * p.dt_s) << toJson(frame);
	EXPECT_NEAR(frame.energy_loss_J, converged.energy_loss_J, 0.03 * converged.energy_loss_J) << toJson(frame) << "\n" << toJson(converged);
	p.end_when_clear = false;
	p.duration_s = p.dt_s;
	const CharpyResult whole = runCharpy(p);  // read at the frame's end: the hammer's long steps are in it
	EXPECT_GT(whole.energy_loss_J, frame.energy_loss_J + 5.0) << toJson(whole);
}

// Issue 25's targets for the standard striker in the world's own steps (no substeps, the world's contact travel at the
// speculative reach): frictionless and at friction 0.1, sharp and ISO anvils, at 0.1 ms frames gathered into the world's
// 1/60 s steps, 1 ms and 1/60 s frames, the test in at most 100 internal steps and within 5 % of the direct solve's
// own run at 10 us substeps. The frictionless runs go over the anvils' top as their converged runs do. Measured: 61-91
// steps to the test's end; frictionless 137 and 131 steps at 1/60 s before the step search took geometric means.
TEST(CharpyDirectSolve, TheStandardStrikerInTheWorldsOwnStepsTakesAtMostAHundredStepsWithAndWithoutFriction)
{
	for (double friction : {0.0, 0.1})
	{
		for (bool iso : {false, true})
		{
			CharpyParameters p = directSpeculative(true);
			p.friction = friction;
			if (iso)
			{
				p.anvil_radius_m = 0.001;
				p.anvil_taper_rad = 0.192;
			}
			p.dt_s = 1e-4;
			const CharpyResult converged = runCharpy(p);
			for (double frame : {1e-4, 1e-3, 1.0 / 60})
			{
				CharpyParameters world = p;
				world.dt_s = frame;
				world.contact_substep_s = 0;
				world.world_contact_travel_m = 3e-4;
				if (frame < 1e-3) world.world_step_s = 1.0 / 60;
				const CharpyResult r = runCharpy(world);
				std::ostringstream where;
				where << "friction " << friction << (iso ? ", ISO anvils, " : ", sharp anvils, ") << frame << " s frames\n"
					  << toJson(r) << "\n"
					  << toJson(converged);
				EXPECT_EQ(classifyCharpyRun(r), CharpyVerdict::Stable) << where.str();
				EXPECT_EQ(r.over_the_top, converged.over_the_top) << where.str();
				EXPECT_LE(r.test_steps, 100) << where.str();
				EXPECT_NEAR(r.energy_loss_J, converged.energy_loss_J, 0.05 * converged.energy_loss_J) << where.str();
				EXPECT_LT(r.max_booked_excess_J, 0.001 * r.E0_J) << where.str();
			}
		}
	}
}

// Patch 0055: a half sliding along the thesis striker's flat nose while it spins (a 3 mm notch, 12 m/s: 60-80 m/s,
// about 1800 rad/s) ends each step with its normal speed at zero; the face then turns and the next step starts
// closing at about a h, stopped inelastically: 1/2 m (a h)^2 lost a step. With the rows' turn prediction the fixed
// substeps converge (10 / 2 / 0.5 us: 115.7 / 113.0 / 113.5 J; without it 133.8 / 118.8 / 114.5 J) and the world's
// own steps read 118.8 J (1 ms frames, +5.1 %) and 115.3 J (1/60 s, +2.0 %) where they read 125.8 and 126.7 J (+11
// and +12 %) without it; the rest of the 1 ms run's excess is not this loss (ci/charpy_world_check.py marks it).
TEST(CharpyDirectSolve, AHalfSlidingOnTheNoseWhileItSpinsLosesNoEnergyToTheStepsTurnsWithTheTurnPrediction)
{
	CharpyParameters p = directSpeculative(false);
	p.impact_speed_m_s = 12.0;
	p.notch_depth_m = 0.003;
	p.dt_s = 1e-4;
	p.contact_substep_s = 2e-6;
	p.contact_turn_prediction = true;
	const CharpyResult converged = runCharpy(p);
	EXPECT_TRUE(converged.contact_turn_prediction);
	p.contact_substep_s = 1e-5;
	const CharpyResult coarse = runCharpy(p);
	EXPECT_NEAR(coarse.energy_loss_J, converged.energy_loss_J, 0.03 * converged.energy_loss_J) << toJson(coarse) << "\n" << toJson(converged);
	p.contact_turn_prediction = false;
	const CharpyResult without = runCharpy(p);
	EXPECT_GT(without.energy_loss_J, 1.1 * converged.energy_loss_J) << "the control: the turns' loss at 10 us substeps\n" << toJson(without);
	for (double frame : {1e-3, 1.0 / 60})
	{
		CharpyParameters world = p;  // the prediction off here: the world's contact stepping turns it on
		world.dt_s = frame;
		world.contact_substep_s = 0;
		world.world_contact_travel_m = 3e-4;
		const CharpyResult r = runCharpy(world);
		EXPECT_TRUE(r.contact_turn_prediction);
		EXPECT_EQ(classifyCharpyRun(r), CharpyVerdict::Stable) << toJson(r);
		EXPECT_LE(r.test_steps, 100) << toJson(r);
		EXPECT_NEAR(r.energy_loss_J, converged.energy_loss_J, 0.08 * converged.energy_loss_J) << frame << " s frames\n" << toJson(r) << "\n" << toJson(converged);
	}
}
