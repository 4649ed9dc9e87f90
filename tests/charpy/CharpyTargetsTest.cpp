// The Charpy scene against the analytic energy loss and the thesis' qualitative results, on fast configurations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "CharpyRun.h"
#include "CharpyScene.h"
#include "CharpySection.h"
#include "CharpyVerdict.h"

namespace
{
CharpyResult run(CharpyMethod method, double dt, bool autoDt = false)
{
	CharpyParameters p;
	p.method = method;
	p.dt_s = dt;
	p.auto_dt = autoDt;
	return runCharpy(p);
}
}  // namespace

TEST(CharpySection, DefaultSectionAndPassAngle)
{
	CharpySection s = computeCharpySection(CharpyParameters{});
	EXPECT_NEAR(s.plastic_moment_nm, 64.0, 1e-9);        // 400 MPa * 0.01 * 0.008^2 / 4
	EXPECT_NEAR(s.theta_pass_rad, 1.99, 0.01);           // hinge at mid-ligament, 6 mm from the back
	CharpyParameters centre;
	centre.notch_depth_m = 0.0;                          // hinge at the section centre, 5 mm from the back
	EXPECT_NEAR(computeCharpySection(centre).theta_pass_rad, 1.907, 0.002);
}

TEST(CharpyTargets, PlasticMethodsWithinFivePercentAtEveryFrameStep)
{
	for (CharpyMethod m : {CharpyMethod::HingeMotor, CharpyMethod::PlasticHinge, CharpyMethod::ElasticPlastic, CharpyMethod::ElasticPlastic2})
	{
		for (double dt : {1e-5, 5e-5, 1e-4, 1e-3})
		{
			CharpyResult r = run(m, dt);
			EXPECT_TRUE(r.finite) << r.method;
			EXPECT_TRUE(r.passed_anvils) << r.method << " dt " << dt;
			EXPECT_LT(std::fabs(r.error_pct), 5.0) << r.method << " dt " << dt << ": loss " << r.energy_loss_J << " J vs " << r.analytic_J;
			EXPECT_LE(r.max_energy_gain_J, 0.01 * r.E0_J) << r.method;
		}
	}
}

TEST(CharpyTargets, LossConvergesAsTheInternalStepShrinks)
{
	// the contact substep is the internal step in contact: 10 and 5 us are two different discretisations
	// (measured: plastic hinge 132.7 and 132.1 J, elastic-plastic2 132.8 and 130.9 J; 20 us is 4 % off)
	for (CharpyMethod m : {CharpyMethod::PlasticHinge, CharpyMethod::ElasticPlastic2})
	{
		CharpyParameters p;
		p.method = m;
		p.contact_substep_s = 1e-5;
		const CharpyResult coarse = runCharpy(p);
		p.contact_substep_s = 5e-6;
		const CharpyResult fine = runCharpy(p);
		ASSERT_GT(fine.internal_steps, coarse.internal_steps * 6 / 5) << "the runs must not share their internal step";
		EXPECT_NEAR(coarse.energy_loss_J, fine.energy_loss_J, 0.02 * fine.energy_loss_J) << coarse.method;
	}
}

TEST(CharpyTargets, PlasticHingeWithinFivePercentWithAutomaticStepping)
{
	CharpyResult r = run(CharpyMethod::PlasticHinge, 1e-4, true);
	EXPECT_LT(std::fabs(r.error_pct), 5.0) << r.energy_loss_J;
	EXPECT_TRUE(r.passed_anvils);
}

TEST(CharpyTargets, AutomaticSteppingEndsAtTheDuration)
{
	// the coarse frames --auto-dt takes far from contact are the scene's, not the user's: the last one ends at the
	// duration (it used to run on to 61.6 ms of 60, 62.9 ms with 60 us substeps); a fixed frame step keeps whole frames
	const auto autoToTheEnd = [](double duration, double substep) {
		CharpyParameters p;
		p.auto_dt = true;
		p.end_when_clear = false;
		p.duration_s = duration;
		p.contact_substep_s = substep;
		return p;
	};
	for (double duration : {0.06, 0.0123})
	{
		for (double substep : {1e-5, 6e-5})
		{
			const CharpyResult r = runCharpy(autoToTheEnd(duration, substep));
			EXPECT_NEAR(r.end_time_s, duration, 1e-9) << "duration " << duration << " s, substep " << substep << " s";
			// frames gathered out of contact (the free step) are stepped whole at the last frame, not gathered past the
			// duration with frames after it (a 0.1 ms frame run went on to 63.9 ms of 60), with --auto-dt or without
			for (bool automatic : {true, false})
			{
				CharpyParameters gathered = autoToTheEnd(duration, substep);
				gathered.auto_dt = automatic;
				gathered.free_step_s = 5e-3;
				gathered.solver = plastic::SolverKind::DirectJoint;
				gathered.speculative_contacts = true;
				const CharpyResult g = runCharpy(gathered);
				EXPECT_NEAR(g.end_time_s, duration, 1e-9) << "free step, duration " << duration << " s, substep " << substep << " s, auto " << automatic;
			}
		}
	}
	// less than a frame step left: the last frame is one frame step, as with fixed frames
	const CharpyParameters p = autoToTheEnd(0.01234, CharpyParameters{}.contact_substep_s);
	const CharpyResult r = runCharpy(p);
	EXPECT_GE(r.end_time_s, p.duration_s - 1e-12);
	EXPECT_LT(r.end_time_s, p.duration_s + p.dt_s);
}

TEST(CharpyTargets, AutomaticSteppingTakesTheLongestHalfOfTheCoarseFrameThatReachesNoContact)
{
	// the standard striker at 5.1 m/s, friction 0.05, 0.1 ms frames: after the fold its halves ride on the hammer's
	// nose for about 8 ms, near it within a 5 ms frame but not within a millisecond. Frames of dt_s there took it to
	// 99 internal steps; the halves of the coarse frame that reach no contact take the same test in 92
	CharpyParameters p;
	applyStandardGeometry(p);
	p.friction = 0.05;
	p.impact_speed_m_s = 5.1;
	p.solver = plastic::SolverKind::DirectJoint;
	p.speculative_contacts = true;
	p.contact_substep_s = 6e-5;
	p.dt_s = 1e-4;
	p.auto_dt = true;
	CharpyScene scene(p);
	int halved = 0;
	while (!scene.clear() && scene.time_s() < 0.03)
	{
		scene.step();
		const double frame = scene.lastFrameStep_s();
		if (frame > p.dt_s * (1 + 1e-9) && frame < p.auto_dt_coarse_s * (1 - 1e-9))
		{
			halved++;
		}
	}
	EXPECT_TRUE(scene.clear());
	EXPECT_GT(halved, 0) << "no frame between dt_s and the coarse frame";
	// the frames change what is drawn and how the time out of contact is cut, not the physics: the same test in
	// frames of dt_s loses the same energy, in more internal steps
	const CharpyResult automatic = runCharpy(p);
	p.auto_dt = false;
	const CharpyResult fixed = runCharpy(p);
	EXPECT_NEAR(automatic.energy_loss_J, fixed.energy_loss_J, 0.01 * fixed.energy_loss_J);
	EXPECT_LT(automatic.internal_steps, fixed.internal_steps);
	EXPECT_LE(automatic.internal_steps, 100);
}

TEST(CharpyTargets, BulletsContinuousCollisionDetectionReachesTheParts)
{
	// 1 ms steps without substeps: the halves, struck, move 4-9 mm a step. With Bullet's CCD on them their sweeps
	// stop them at what they would hit (with Bullet's allowed CCD penetration of 0.04 m, four specimen widths, no hit
	// ever counted and the run was the same bit for bit); STABILITY.md's ccd cases measure what that changes
	CharpyParameters p;
	p.method = CharpyMethod::HingeMotor;
	p.dt_s = 1e-3;
	p.contact_substep_s = 0;
	const CharpyResult without = runCharpy(p);
	p.ccd_motion_threshold_m = 1e-3;
	p.ccd_swept_sphere_radius_m = 4e-3;
	const CharpyResult with = runCharpy(p);
	EXPECT_GT(std::fabs(with.max_penetration_m - without.max_penetration_m), 1e-4)
		<< "penetration " << with.max_penetration_m << " m with CCD, " << without.max_penetration_m << " m without";
}

TEST(CharpyTargets, ASpecimenInFourPartsPassesTheAnvilsAsTheHalvesDo)
{
	// STABILITY.md's parts4 row: the flat nose's edge caught on the seam between two parts, pinned the outer part on
	// the anvil and pushed the next, and the specimen stayed in front of the anvils (219.5 J, bent 2.1 rad, with the
	// plastic hinge). The parts' joined end faces are no surface while their joints hold (plastic::JoinedFaces)
	for (CharpyMethod m : {CharpyMethod::PlasticHinge, CharpyMethod::ElasticPlastic2})
	{
		CharpyParameters p;
		p.method = m;
		const CharpyResult halves = runCharpy(p);
		p.parts = 4;
		const CharpyResult four = runCharpy(p);
		EXPECT_TRUE(four.passed_anvils && !four.over_the_top) << four.method;
		EXPECT_NEAR(four.energy_loss_J, halves.energy_loss_J, 0.03 * halves.energy_loss_J) << four.method;
	}
}

TEST(CharpyTargets, PlasticHingeLossIsMostlyPlasticWork)
{
	CharpyResult r = run(CharpyMethod::PlasticHinge, 1e-4);
	// The rest of the loss is the inelastic impact on the 20 g halves and contact work.
	EXPECT_GE(r.plastic_work_J, 0.97 * r.energy_loss_J);
	EXPECT_GT(r.plastic_rotation_rad, 0.9 * r.theta_pass_rad);
}

TEST(CharpyTargets, HalvingYieldStressHalvesPlasticWork)
{
	CharpyParameters p;
	p.method = CharpyMethod::PlasticHinge;
	CharpyResult full = runCharpy(p);
	p.yield_stress_pa /= 2;
	CharpyResult half = runCharpy(p);
	EXPECT_NEAR(half.plastic_work_J, full.plastic_work_J / 2, 0.05 * full.plastic_work_J / 2);
}

TEST(CharpyTargets, TunnellingIsToldFromTheBendNotFromTheMethod)
{
	// a rigid 55 mm specimen at 1/60 s without substeps gets past the 40 mm gap unbent: through the anvils
	CharpyParameters p;
	p.method = CharpyMethod::RigidBody;
	p.dt_s = 0.017;
	p.contact_substep_s = 0;
	p.duration_s = 0.2;
	CharpyResult rigid = runCharpy(p);
	ASSERT_TRUE(rigid.passed_anvils);
	EXPECT_LT(rigid.max_bend_rad, 1e-6);
	EXPECT_TRUE(rigid.tunnelled);
	EXPECT_NEAR(rigid.min_pass_bend_rad, 2 * std::acos(40.0 / 55.0), 1e-12);
	// a plastic hinge folds until it fits: it passes without tunnelling
	CharpyResult plastic = run(CharpyMethod::PlasticHinge, 1e-4);
	ASSERT_TRUE(plastic.passed_anvils);
	EXPECT_GT(plastic.max_bend_rad, plastic.min_pass_bend_rad);
	EXPECT_FALSE(plastic.tunnelled);
}

TEST(CharpyTargets, ABendNoJointYieldedForIsAChainThatCameApart)
{
	// the direct solve at 2 ms frames without substeps: the halves get behind the anvils bent 2.82 rad end to end while
	// their joint has booked 1.58 rad (it let go in the solver for the rest); bent more than half of theta_pass, with
	// plastic work for most of the loss, the verdict said stable before it compared the two
	CharpyParameters p;
	p.method = CharpyMethod::PlasticHinge;
	p.dt_s = 2e-3;
	p.contact_substep_s = 0;
	p.solver = plastic::SolverKind::DirectJoint;
	std::string why;
	const CharpyResult r = runCharpy(p);
	ASSERT_TRUE(r.passed_anvils && !r.broken);
	EXPECT_GT(r.end_bend_angle_rad, 0.5 * r.theta_pass_rad) << "bent enough for the older test";
	EXPECT_GT(r.plastic_work_J, 0.5 * r.energy_loss_J) << "booked enough for the older test";
	EXPECT_GT(r.pass_end_bend_angle_rad - r.pass_plastic_rotation_rad, 0.25 * r.theta_pass_rad);
	EXPECT_EQ(charpyVerdictName(classifyCharpyRun(r, &why)), "came-apart") << why;
	// the halves at the default settings bend as much as their joint yields: stable
	const CharpyResult halves = runCharpy(CharpyParameters());
	EXPECT_EQ(charpyVerdictName(classifyCharpyRun(halves, &why)), "stable") << why;
	EXPECT_NEAR(halves.pass_end_bend_angle_rad, halves.pass_plastic_rotation_rad, 0.1) << why;
	// 8 parts under the standard striker at 1 ms frames book 1.39 rad; flying on after the test to 15-60 ms, the
	// chain's end-to-end bend swings between 1.40 and 2.16 rad at its drifting joints. The bend is taken when the
	// specimen got behind the anvils, so the verdict does not depend on when the run stops
	CharpyParameters q;
	applyStandardGeometry(q);
	q.parts = 8;
	q.dt_s = 1e-3;
	q.end_when_clear = false;
	for (double duration_s : {0.015, 0.03, 0.06})
	{
		q.duration_s = duration_s;
		const CharpyResult r = runCharpy(q);
		EXPECT_EQ(charpyVerdictName(classifyCharpyRun(r, &why)), "stable") << duration_s << " s: " << why;
	}
}

TEST(CharpyTargets, BrittleJointBreaksBeforeItBends)
{
	CharpyResult r = run(CharpyMethod::BrittleZeroLimits, 1e-4);
	EXPECT_TRUE(r.broken);
	EXPECT_TRUE(r.passed_anvils);
	// the halves go through the gap apart, never folded: brittle, not ductile (thesis fig. 3.3)
	EXPECT_LT(r.max_bend_rad, 0.5 * r.min_pass_bend_rad) << r.max_bend_rad;
}

TEST(CharpyTargets, SameInputsGiveBitIdenticalResults)
{
	CharpyResult a = run(CharpyMethod::ElasticPlastic2, 1e-4);
	CharpyResult b = run(CharpyMethod::ElasticPlastic2, 1e-4);
	a.wall_s = b.wall_s = 0;
	EXPECT_EQ(toJson(a), toJson(b));
}

TEST(CharpyParameters, InvalidValuesAreRejectedNamingTheParameter)
{
	CharpyParameters p;
	p.yield_stress_pa = -1;
	p.parts = 3;
	p.dt_s = NAN;
	try
	{
		runCharpy(p);
		FAIL() << "expected std::invalid_argument";
	}
	catch (const std::invalid_argument& e)
	{
		std::string text = e.what();
		EXPECT_NE(text.find("fy:"), std::string::npos) << text;
		EXPECT_NE(text.find("parts:"), std::string::npos) << text;
		EXPECT_NE(text.find("dt:"), std::string::npos) << text;
	}
	// the contact travel: a length in [1e-7, 1] m, or 0; it needs contact substeps, speculative contacts and the
	// direct solve
	for (const double travel_m : {-1e-3, double(NAN), 2.0})
	{
		CharpyParameters q;
		q.solver = plastic::SolverKind::DirectJoint;
		q.speculative_contacts = true;
		q.contact_travel_m = travel_m;
		const std::vector<std::string> errors = validateCharpyParameters(q);
		ASSERT_EQ(errors.size(), 1u) << travel_m;
		EXPECT_NE(errors[0].find("contact-travel: "), std::string::npos) << errors[0];
		EXPECT_NE(errors[0].find("is not in [1e-07, 1] m"), std::string::npos) << errors[0];
	}
	CharpyParameters q;
	q.solver = plastic::SolverKind::DirectJoint;
	q.speculative_contacts = true;
	q.contact_travel_m = 3e-4;
	EXPECT_TRUE(validateCharpyParameters(q).empty());
	q.contact_substep_s = 0;
	std::vector<std::string> errors = validateCharpyParameters(q);
	ASSERT_EQ(errors.size(), 1u);
	EXPECT_NE(errors[0].find("contact-travel: 0.0003 needs contact substeps"), std::string::npos) << errors[0];
	for (const bool direct : {false, true})
	{
		q = CharpyParameters();
		q.contact_travel_m = 3e-4;
		q.solver = direct ? plastic::SolverKind::DirectJoint : plastic::SolverKind::SequentialImpulse;
		q.speculative_contacts = !direct;
		errors = validateCharpyParameters(q);
		ASSERT_EQ(errors.size(), 1u) << direct;
		EXPECT_NE(errors[0].find("contact-travel: 0.0003 needs --speculative-contacts and --solver=direct"), std::string::npos) << errors[0];
	}
}

TEST(CharpyTargets, SixtyHertzFramesCostNoMoreInternalStepsThanMillisecondFrames)
{
	// only the part of a frame in or near contact is substepped, so a 1/60 s frame costs what 1 ms frames cost
	for (CharpyMethod m : {CharpyMethod::HingeMotor, CharpyMethod::PlasticHinge, CharpyMethod::ElasticPlastic, CharpyMethod::ElasticPlastic2})
	{
		const CharpyResult ms = run(m, 1e-3);
		const CharpyResult game = run(m, 1.0 / 60.0);
		EXPECT_LE(game.internal_steps, 3 * ms.internal_steps / 2) << game.method << ": " << game.internal_steps << " vs " << ms.internal_steps;
		EXPECT_LT(std::fabs(game.error_pct), 5.0) << game.method;
		EXPECT_TRUE(game.passed_anvils && !game.tunnelled) << game.method;
	}
}

TEST(CharpyAccuracy, StableRunsThatAreNotAccurateAreToldApart)
{
	CharpyParameters p;
	std::string why;
	EXPECT_EQ(charpyAccuracyName(classifyCharpyAccuracy(runCharpy(p), &why)), "accurate") << why;
	{
		// the thesis' own step without contact substeps: the specimen is pushed through unbent (-68 %)
		CharpyParameters q = p;
		q.contact_substep_s = 0;
		const CharpyResult r = runCharpy(q);
		EXPECT_NE(charpyVerdictName(classifyCharpyRun(r)), "stable") << r.energy_loss_J;
		EXPECT_EQ(charpyAccuracyName(classifyCharpyAccuracy(r)), "unstable");
	}
	{
		// the standard striker without friction: the folded specimen leaves over the anvils instead of through the gap
		CharpyParameters q = p;
		applyStandardGeometry(q);
		const CharpyResult r = runCharpy(q);
		EXPECT_TRUE(r.over_the_top);
		EXPECT_EQ(charpyAccuracyName(classifyCharpyAccuracy(r, &why)), "over-the-top") << why;
	}
	{
		// friction jams the specimen against the flat striker (issue 14): it never passes
		CharpyParameters q = p;
		q.friction = 0.25;
		const CharpyResult r = runCharpy(q);
		EXPECT_FALSE(r.passed_anvils);
		EXPECT_EQ(charpyAccuracyName(classifyCharpyAccuracy(r, &why)), "did-not-pass") << why;
	}
}

// The thesis' flat nose self-locks with friction (issue 25): the runner says so before the run, for that nose only,
// and the prediction holds: above the threshold the specimen stays in front of the anvils and the hammer gives up
// more than 80 % of its energy (measured by the run, not by the warning); below it, it passes.
TEST(CharpyFriction, FlatNoseSelfLockingIsPredictedBeforeTheRun)
{
	CharpyParameters p;
	p.friction = 0.06;
	EXPECT_NE(charpySelfLockWarning(p).find("--geometry=standard"), std::string::npos);
	const CharpyResult locked = runCharpy(p);
	EXPECT_FALSE(locked.warning.empty());
	EXPECT_FALSE(locked.passed_anvils);
	EXPECT_GT(locked.energy_loss_J, 0.8 * locked.E0_J);
	p.friction = 0.03;
	EXPECT_TRUE(charpySelfLockWarning(p).empty());
	const CharpyResult free = runCharpy(p);
	EXPECT_TRUE(free.passed_anvils);
	CharpyParameters standard;
	applyStandardGeometry(standard);
	standard.friction = 0.25;
	EXPECT_TRUE(charpySelfLockWarning(standard).empty());
}

// The test ends once every part is behind the anvils and none can touch an anvil within a frame (CharpyScene::clear).
// The parts may still meet the hammer then (kinetic_against_hammer_J: what one such collision could dissipate).
// Checked against the same runs taken to the full duration (60 ms): the loss within 0.5 %, no more plastic work.
// Measured: 0.005-0.01 %, and 0.47 % at 1/60 s frames (a contact in the frame after the one judged clear).
TEST(CharpyTargets, TheLossAtTheClearEndIsTheFullRunsWithinHalfAPercent)
{
	struct Case
	{
		const char* name;
		void (*apply)(CharpyParameters&);
	};
	const Case cases[] = {
		{"thesis", [](CharpyParameters&) {}},
		{"thesis, 1/60 s frames", [](CharpyParameters& p) { p.dt_s = 1.0 / 60; }},
		{"standard", [](CharpyParameters& p) { applyStandardGeometry(p); }},
		{"standard, friction 0.1", [](CharpyParameters& p) {
			 applyStandardGeometry(p);
			 p.friction = 0.1;
		 }},
		{"standard, ISO anvils, friction 0.25, direct, speculative, 0.05 ms", [](CharpyParameters& p) {
			 applyStandardGeometry(p);
			 p.anvil_radius_m = 0.001;
			 p.anvil_taper_rad = 0.192;
			 p.friction = 0.25;
			 p.solver = plastic::SolverKind::DirectJoint;
			 p.speculative_contacts = true;
			 p.contact_substep_s = 5e-5;
		 }},
	};
	for (const Case& c : cases)
	{
		CharpyParameters p;
		c.apply(p);
		const CharpyResult clear = runCharpy(p);
		p.end_when_clear = false;
		const CharpyResult full = runCharpy(p);
		EXPECT_LT(clear.end_time_s, full.end_time_s) << c.name << ": the specimen never got clear";
		EXPECT_LT(clear.internal_steps, full.internal_steps) << c.name;
		std::printf("%s: %.4f J at %.1f ms, %.4f J at %.1f ms (kinetic against the hammer at the end %.3f J)\n", c.name,
					clear.energy_loss_J, 1e3 * clear.end_time_s, full.energy_loss_J, 1e3 * full.end_time_s, clear.kinetic_against_hammer_J);
		EXPECT_NEAR(clear.energy_loss_J, full.energy_loss_J, 0.005 * full.energy_loss_J)
			<< c.name << ": " << clear.energy_loss_J << " J at " << clear.end_time_s << " s, " << full.energy_loss_J << " J at the end";
		EXPECT_EQ(clear.plastic_work_J, full.plastic_work_J) << c.name << ": the joints yielded after the end";
	}
}
