#!/usr/bin/env python3
"""The standard striker with friction against the quasi-static rigid-plastic model (issue 14 part 1).

Usage: python3 test_friction_model.py RUNNER  (the charpy console runner)
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
CI = os.path.join(HERE, "..", "..", "ci", "models")
sys.path.insert(0, CI)
sys.path.insert(1, os.path.dirname(CI))  # ci/: the sweep and report tools
from charpy_friction_model import CharpyFrictionModel, STANDARD  # noqa: E402

RUNNER = None


def run(*flags):
    out = subprocess.run([RUNNER, "--method=plastic-hinge", "--json"] + list(flags), check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def run_many(flag_lists):
    """run(*flags) for each list of flags, as many at once as the machine has cores; the results by their flags"""
    unique = list(dict.fromkeys(tuple(f) for f in flag_lists))
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        return dict(zip(unique, pool.map(lambda flags: run(*flags), unique)))


class FrictionModelTest(unittest.TestCase):
    def test_model_without_friction_is_the_plastic_work_of_the_runners_pass_angle(self):
        # two independent derivations: the model integrates the hammer force over the striker's travel, the
        # runner's CharpySection bisects the pass angle
        r = run("--geometry=standard")
        loss, lock = CharpyFrictionModel(**STANDARD).loss(0.0)
        self.assertIsNone(lock)
        self.assertAlmostEqual(loss / r["analytic_J"], 1.0, delta=1e-3)

    def test_rounded_anvils_without_friction_cost_the_plastic_work_of_their_pass_angle(self):
        # the back corner slides round the 1 mm edge until it drops into the gap where a sharp edge lets it go, and
        # (virtual work) the hammer's work over the corner's slide, whose hinge travel has no bound on its rate at
        # the end, is the hinge's. Before the corner's slide was modelled the rounded anvils' model stopped 1.07 J
        # short (126.33 J), and these runs with friction ended 1.5-2.5 % above it (now 0.4-0.6 %)
        rounded = CharpyFrictionModel(**dict(STANDARD, anvil_radius_m=0.001))
        self.assertLess(rounded.phi_face, rounded.phi_pass - 1e-3)
        loss, lock = rounded.loss(0.0)
        self.assertIsNone(lock)
        self.assertAlmostEqual(loss / (rounded.mp * 2 * rounded.phi_pass), 1.0, delta=1e-5)

    def test_rounded_anvils_with_friction_match_an_independent_position_level_derivation(self):
        # A review's own implementation (helper-32): material points placed at position level and differentiated,
        # moments about the world origin, the corner's slide parametrised by the contact's angle on the circle (smooth
        # at its lowest point), 400-point Gauss-Legendre, hammer power checked against 2 (Mp phi' + mu Fa |slip_a| +
        # mu Fs |slip_s|) to 1e-5 at every point: 142.030597 J at friction 0.1, 185.616232 J at 0.25. Wrong corner
        # phases it tried all fail here: a back face rolling on past the half's end 186.23 J, the corner's friction
        # along the face 185.67 J, the face's normal at the corner 190.69 J, the friction's sign flipped locks.
        rounded = CharpyFrictionModel(**dict(STANDARD, anvil_radius_m=0.001))
        for mu, independent in ((0.1, 142.030597), (0.25, 185.616232)):
            with self.subTest(mu=mu):
                loss, lock = rounded.loss(mu)
                self.assertIsNone(lock)
                self.assertAlmostEqual(loss, independent, delta=5e-3)

    def test_friction_costs_more_the_more_there_is_and_locks_at_last(self):
        model = CharpyFrictionModel(**STANDARD)
        losses = [model.loss(mu)[0] for mu in (0.0, 0.05, 0.1, 0.25)]
        self.assertEqual(losses, sorted(losses))
        self.assertGreater(losses[-1], losses[0] * 1.3)
        self.assertIsNotNone(model.loss(0.6)[1], "a friction of 0.6 self-locks the contacts")

    def test_runner_loss_is_within_3_percent_of_the_model_and_the_specimen_passes(self):
        model = CharpyFrictionModel(**STANDARD)
        for mu in (0.05, 0.1, 0.25):
            with self.subTest(mu=mu):
                r = run("--geometry=standard", f"--friction={mu}")
                expected, _ = model.loss(mu)
                self.assertTrue(r["passed_anvils"] and not r["over_the_top"], r)
                self.assertLess(abs(r["energy_loss_J"] - expected) / expected, 0.03, (mu, r["energy_loss_J"], expected))

    def test_rounded_tapered_anvils_match_the_model_at_both_substeps_without_energy_gain(self):
        # ISO 148-1 anvils: 1 mm edges, the gap tapered by 11 degrees behind them. Before patch 0018 GJK stopped
        # early on these millimetre shapes (losses 40-130 J, gains up to hundreds of J at 2e-6 s substeps).
        iso = ("--geometry=standard", "--anvil-radius=0.001", "--anvil-taper=0.192")
        model = CharpyFrictionModel(**dict(STANDARD, anvil_radius_m=0.001))
        for substep in ("1e-5", "2e-6"):
            for mu in (0.05, 0.1, 0.25):
                with self.subTest(substep=substep, mu=mu):
                    r = run(*iso, f"--friction={mu}", f"--contact-substep={substep}")
                    expected, _ = model.loss(mu)
                    self.assertTrue(r["passed_anvils"] and not r["over_the_top"], r)
                    self.assertGreaterEqual(r["energy_loss_J"], r["plastic_work_J"], r)
                    self.assertLess(r["max_penetration_m"], 1e-4, r)
                    # measured +0.40 to +0.63 % (+1.5 to +2.5 % against the model without the corner's slide)
                    self.assertLess(abs(r["energy_loss_J"] - expected) / expected, 0.015, (mu, r["energy_loss_J"], expected))

    def test_rounded_anvils_match_the_model_for_other_gaps_notches_widths_and_yield_stresses(self):
        # geometries no other test or report runs, at the runner's default steps (sequential impulse, 10 us
        # substeps): measured +0.4 to +0.9 % (the direct solve at 2 us +0.6 to +1.4 %)
        iso = ("--geometry=standard", "--anvil-radius=0.001", "--anvil-taper=0.192")
        cases = ((dict(gap_m=0.045), ("--anvil-gap=0.045",)), (dict(notch_m=0.003), ("--notch-depth=0.003",)),
                 (dict(width_m=0.008), ("--specimen-width=0.008",)), (dict(fy_pa=300e6), ("--fy=300e6",)))
        for params, flags in cases:
            model = CharpyFrictionModel(**dict(STANDARD, anvil_radius_m=0.001, **params))
            for mu in (0.1, 0.2):
                with self.subTest(flags=flags, mu=mu):
                    r = run(*iso, *flags, f"--friction={mu}")
                    expected, lock = model.loss(mu)
                    self.assertIsNone(lock)
                    self.assertTrue(r["passed_anvils"] and not r["over_the_top"], r)
                    self.assertLess(abs(r["energy_loss_J"] - expected) / expected, 0.015, (mu, r["energy_loss_J"], expected))

    def test_coarse_steps_with_the_direct_solve_and_speculative_contacts_match_the_converged_runs(self):
        if os.environ.get("BP_COARSE_FRICTION_TEST") == "separate":
            self.skipTest("run as its own ctest test, charpy.friction_coarse_steps_match_the_converged_runs")
        # issue 25: 0.07 ms contact substeps, frames of 0.1 ms, 1 ms and 1/60 s gathered out of contact into steps of up
        # to 5 ms (--free-step), btDirectJointSolver (two friction rows per contact, patch 0037, within Coulomb's cone,
        # patch 0043; the contacts' penetration corrected without momentum, patch 0038; friction bounds whose reversals
        # are damped, patch 0039), speculative contacts for the specimen's boxes and the hammer's children (patches
        # 0036, 0040) with a part's edge across a face touching it at both ends (patch 0042), the world stepped to the
        # striker's touch (plastic::timeToTouch_s) and to a half's release from a sharp anvil (plastic::timeToRelease_s),
        # the halves' slide along the anvils after the fold left to them (SubstepPolicy's speculative reach). Each case
        # is held to its converged run (2 us substeps, 5.2 m/s), which is held to the model (measured +0.2 to +0.3 %
        # with the sharp anvils, +0.4 to +1.0 % with the ISO anvils). The loss at coarse steps depends a little on the
        # run, so each case runs at five impact speeds, 5.1-5.3 m/s (the converged loss moves with the speed by at most
        # 0.6 %, 1.4 % and 2.5 % with the ISO anvils at friction 0.2 and 0.25), the median held to 2 % of the converged
        # loss and each run to 3 %, all but two of each frame step's 80 runs to 3 % of the model, and every run to 100
        # internal steps (issue 25's targets; frictions 0.01-0.04 added with patch 0051, which brought the ISO anvils'
        # runs at 0.01 to at most 100 steps). Measured within 3 % of the model: 50 of 50 at each frame step (mean 1.33 % in
        # each; 1.30 / 1.33 / 1.32 % before patch 0048); internal steps 76-85 at each. At 0.06 ms substeps
        # (the setting before): 50 of 50 within 3 % (mean 1.21 % in 1 ms frames), but 91-103 steps in 1 ms frames,
        # 89-106 at 1/60 s (the test ran on to the frame's end and a second frame, its spinning halves within the 1/60 s
        # horizon of the clear test: now it ends at the internal step that leaves the specimen clear, within 1 ms, and
        # 1/60 s frames read as 1 ms ones) and 97-188 in 0.1 ms frames without the free step (a frame was at least one
        # step, and the halves slide along the sharp anvils' walls for 10 ms after the fold). At 0.08 ms: 48, 48 and 45
        # of 50 (before the end within a frame).
        # History (1 ms frames, 0.06 ms): in Coulomb's box (before patch 0043) 47 of 50 within 3 % of the model (mean
        # 1.77 %): where the solve turned the slip both friction rows carried mu N, and the striker's arc pushed the
        # halves onto their supports. Before the world was stepped to the touch, 38 of 50 (mean 2.6 %): the striker's
        # speculative contact, met within a step, carried the bend's load while the striker still crossed the gap (up
        # to 2 J). Before patch 0040 the medians were -4.5 to +2.0 % and single runs -9.6 to +3.0 %: a compound's
        # child (the ISO anvils' rounded edges, the hammer's striker) got its contacts only once its box overlapped a
        # half, the half sank into it, and the contacts' position correction turned the yielding hinge (up to 7.2 J of
        # plastic work booked beyond the energy lost, max_booked_excess_J).
        converged = ("--solver=direct", "--speculative-contacts", "--contact-substep=2e-6", "--dt=1e-3", "--impact-speed=5.2")
        iso = ("--anvil-radius=0.001", "--anvil-taper=0.192")
        speeds = (5.1, 5.15, 5.2, 5.25, 5.3)
        frames = ("1e-4", "1e-3", str(1.0 / 60.0))
        mus = (0.01, 0.02, 0.04, 0.05, 0.1, 0.15, 0.2, 0.25)

        def coarse_of(frame):
            return ("--solver=direct", "--speculative-contacts", "--contact-substep=7e-5", "--free-step=5e-3", f"--dt={frame}")
        # the 256 runs at once on every core (they are independent), then checked in order
        results = run_many([("--geometry=standard", *anvils, f"--friction={mu}", *converged) for anvils in ((), iso) for mu in mus]
                           + [("--geometry=standard", *anvils, f"--friction={mu}", f"--impact-speed={v}", *coarse_of(frame))
                              for frame in frames for anvils in ((), iso) for mu in mus for v in speeds])
        references = {}
        for frame in frames:
            coarse = coarse_of(frame)
            model_errors = []
            for anvils in ((), iso):
                model = CharpyFrictionModel(**dict(STANDARD, anvil_radius_m=0.001 if anvils else 0.0))
                for mu in mus:
                    with self.subTest(frame=frame, anvils=anvils, mu=mu):
                        expected, _ = model.loss(mu)
                        if (anvils, mu) not in references:
                            references[anvils, mu] = results[("--geometry=standard", *anvils, f"--friction={mu}", *converged)]["energy_loss_J"]
                        reference = references[anvils, mu]
                        self.assertLess(abs(reference - expected) / expected, 0.03, (mu, reference, expected))
                        errors = []
                        for v in speeds:
                            r = results[("--geometry=standard", *anvils, f"--friction={mu}", f"--impact-speed={v}", *coarse)]
                            self.assertTrue(r["passed_anvils"] and not r["over_the_top"], r)
                            self.assertLess(r["max_energy_gain_J"], 1e-4 * r["E0_J"], r)
                            self.assertLess(r["max_booked_excess_J"], 1e-3 * r["E0_J"], r)
                            errors.append((r["energy_loss_J"] - reference) / reference)
                            self.assertLess(abs(errors[-1]), 0.03, (mu, v, errors[-1]))
                            model_errors.append((r["energy_loss_J"] - expected) / expected)
                            self.assertLessEqual(r["steps"], 100, (mu, v, r["steps"]))
                        errors.sort()
                        self.assertLess(abs(errors[len(errors) // 2]), 0.02, (mu, errors))
            self.assertGreaterEqual(sum(abs(e) < 0.03 for e in model_errors), len(model_errors) - 2, (frame, sorted(model_errors)))

    def test_the_worlds_contact_stepping_matches_the_model_in_at_most_100_steps(self):
        # issue 25 in the library: no runner substeps, the world cuts its own steps (patch 0053,
        # btDiscreteDynamicsWorld::setContactStepping at the speculative reach) with the direct solve and speculative
        # contacts; 1 ms and 1/60 s frames, and 0.1 ms frames gathered into the world's fixed 1/60 s steps (upstream's
        # fixed-step stepSimulation), at two impact speeds. Measured over friction 0.02-0.25 and five speeds, 5.1-5.3
        # m/s (120 runs): 70-90 internal steps and -0.3 to +1.6 % from the model with the sharp anvils, 67-87 steps and
        # +0.3 to +3.1 % with the ISO anvils (their converged run is itself +2.7 % from the model at friction 0.25: the
        # ISO seam). Before the bound took the children of a compound, the points of one near the other, the closing
        # along their boxes' axes and the spin a body lost in the last steps, these runs took 132-557 steps at 5.2 m/s;
        # without the lost spin 5 of the 120 were 3.1-5.8 % from the model (the fold braked to rest within a step, the
        # next step long, the contacts turning it again within it).
        iso = ("--anvil-radius=0.001", "--anvil-taper=0.192")
        world = ("--solver=direct", "--speculative-contacts", "--contact-substep=0", "--world-contact-travel=3e-4")
        frames = (("--dt=1e-4", "--world-step=0.0166667"), ("--dt=1e-3",), (f"--dt={1.0 / 60.0}",))
        mus = (0.02, 0.05, 0.1, 0.25)
        speeds = (5.1, 5.3)
        cases = [(anvils, mu, v, frame) for anvils in ((), iso) for mu in mus for v in speeds for frame in frames]
        results = run_many([("--geometry=standard", *anvils, f"--friction={mu}", f"--impact-speed={v}", *world, *frame)
                            for anvils, mu, v, frame in cases])
        model_errors = []
        for anvils, mu, v, frame in cases:
            with self.subTest(anvils=anvils, mu=mu, v=v, frame=frame):
                expected, lock = CharpyFrictionModel(**dict(STANDARD, anvil_radius_m=0.001 if anvils else 0.0)).loss(mu)
                self.assertIsNone(lock)
                r = results[("--geometry=standard", *anvils, f"--friction={mu}", f"--impact-speed={v}", *world, *frame)]
                self.assertTrue(r["passed_anvils"] and not r["over_the_top"] and not r["tunnelled"], r)
                self.assertLess(r["max_energy_gain_J"], 1e-4 * r["E0_J"], r)
                self.assertLess(r["max_booked_excess_J"], 1e-3 * r["E0_J"], r)
                self.assertLess(r["max_penetration_m"], 3e-4, r)
                self.assertLessEqual(r["steps"], 100, r)
                model_errors.append((r["energy_loss_J"] - expected) / expected)
                self.assertLess(abs(model_errors[-1]), 0.035, (mu, v, frame, r["energy_loss_J"], expected))
        self.assertGreaterEqual(sum(abs(e) < 0.03 for e in model_errors), len(model_errors) - 2, sorted(model_errors))

    def test_high_friction_converges_at_coarser_substeps(self):
        # friction 0.25 with the sharp anvils at 80-120 us substeps: each run within 1 % of the converged loss (patch
        # 0050). Before it the cone shares of a half's contacts cycled to the iteration cap and the step kept whichever
        # solve the cap fell on: 183.2-187.8 J at 80 us, 181.0-184.0 J at 90 us and 183.2-187.5 J at 100 us against
        # 188.2 J (measured 187.5-188.1 J now)
        coarse = ("--solver=direct", "--speculative-contacts", "--free-step=5e-3", "--contact-travel=3e-4", "--dt=1e-3")
        speeds = (5.1, 5.15, 5.2, 5.25, 5.3)
        substeps = ("8e-5", "9e-5", "1e-4", "1.2e-4")
        converged = ("--geometry=standard", "--friction=0.25", "--impact-speed=5.2", "--solver=direct", "--speculative-contacts")
        runs = [("--geometry=standard", "--friction=0.25", f"--impact-speed={v}", f"--contact-substep={h}", *coarse)
                for h in substeps for v in speeds]
        results = run_many([converged] + runs)
        reference = results[converged]["energy_loss_J"]
        for flags in runs:
            r = results[flags]
            with self.subTest(flags=flags):
                self.assertTrue(r["passed_anvils"] and not r["over_the_top"], r)
                self.assertLess(abs(r["energy_loss_J"] - reference) / reference, 0.01, (r["energy_loss_J"], reference))

    def test_the_frictionless_striker_goes_over_the_top_within_5_percent_of_converged_in_few_steps(self):
        # Without friction the specimen rides over the anvils (the model's pass does not apply): issue 25's target is
        # the converged loss. 70 us substeps, the five speeds, both anvils, three frame steps. A part sliding on an
        # anvil without friction no longer holds the substep while its joint does not flow (the sharp anvils' runs took
        # 103-106 internal steps at 1 ms frames); the ISO anvils' runs then still took up to 107, 110 and 104 in 0.1 ms,
        # 1 ms and 1/60 s frames (126 before), a half bouncing on a rounded edge during the fold, until a capsule lying
        # on a face touched it at both ends (patch 0051): now at most 100 at every frame step
        iso = ("--anvil-radius=0.001", "--anvil-taper=0.192")
        speeds = (5.1, 5.15, 5.2, 5.25, 5.3)
        frames = ("1e-4", "1e-3", str(1.0 / 60.0))
        converged = ("--solver=direct", "--speculative-contacts")

        def coarse_of(frame):
            return ("--solver=direct", "--speculative-contacts", "--contact-substep=7e-5", "--free-step=5e-3",
                    "--contact-travel=3e-4", f"--dt={frame}")
        cases = [(anvils, v) for anvils in ((), iso) for v in speeds]
        results = run_many([("--geometry=standard", *anvils, f"--impact-speed={v}", *converged) for anvils, v in cases]
                           + [("--geometry=standard", *anvils, f"--impact-speed={v}", *coarse_of(frame))
                              for frame in frames for anvils, v in cases])
        for frame in frames:
            for anvils, v in cases:
                with self.subTest(frame=frame, anvils=anvils, v=v):
                    reference = results[("--geometry=standard", *anvils, f"--impact-speed={v}", *converged)]["energy_loss_J"]
                    r = results[("--geometry=standard", *anvils, f"--impact-speed={v}", *coarse_of(frame))]
                    self.assertTrue(r["passed_anvils"], r)
                    self.assertLess(r["max_energy_gain_J"], 1e-4 * r["E0_J"], r)
                    self.assertLess(abs(r["energy_loss_J"] - reference) / reference, 0.05, (r["energy_loss_J"], reference))
                    self.assertLessEqual(r["steps"], 100, r["steps"])

    def test_the_thesis_flat_nose_jams_where_the_standard_striker_does_not(self):
        flat = run("--geometry=thesis", "--friction=0.1")
        edge = run("--geometry=standard", "--friction=0.1")
        self.assertFalse(flat["passed_anvils"] and not flat["over_the_top"])
        self.assertTrue(edge["passed_anvils"])

    def test_the_sweep_csv_keeps_every_column_of_a_settings_name_with_commas(self):
        # the coarse-step settings are named "direct, speculative, 0.06 ms": unquoted, they broke every column after it
        with tempfile.TemporaryDirectory() as out:
            done = subprocess.run([sys.executable, os.path.join(HERE, "..", "..", "ci", "charpy_friction_sweep.py"),
                                   f"--runner={RUNNER}", "--mus=0.1", f"--out-dir={out}"], capture_output=True, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(os.path.join(out, "charpy-friction.csv"), newline="") as f:
                rows = list(csv.DictReader(f))
            with open(os.path.join(out, "FRICTION.md")) as f:
                markdown = f.read()
        self.assertIn("direct, speculative, 0.06 ms", {r["settings"] for r in rows})
        # each frame-step table shows each frame step's own run in its column (the 0.1 ms runs' name ends with
        # "1 ms frames": a suffix match showed them in the 1 ms column too): the gathered runs, those with the contact
        # travel, and those in the world's own steps
        for heading, suffix in (("## The standard striker at every frame step", "free step 5 ms, {} frames"),
                                ("### The same with slow contacts stepped by their motion", "travel 0.3 mm, {} frames"),
                                ("## The standard striker in the world's own steps", "world's steps 0.3 mm, {} frames")):
            table = markdown[markdown.index(heading):]
            line = next(x for x in table.splitlines() if x.startswith("| standard | 0.10 |"))
            cells = [c.strip() for c in line.strip("|").split("|")][2:]
            frames = ("0.1 ms", "1 ms", "1/60 s")
            self.assertEqual(len(cells), len(frames), (heading, line))
            for frame, cell in zip(frames, cells):
                run = next(r for r in rows if r["geometry"] == "standard" and r["settings"].endswith(suffix.format(frame)))
                self.assertEqual(cell.split(" / ")[0], f"{float(run['loss_J']):.2f}", (heading, frame, line))
                self.assertEqual(cell.split(" / ")[1], run["steps"], (heading, frame, line))
        for r in rows:
            self.assertIn(r["accuracy"], ("accurate", "did-not-pass", "over-the-top", "penetrated", "unstable"), r)
            self.assertGreater(float(r["end_time_s"]), 0, r)
            self.assertGreater(int(r["steps"]), 0, r)

    def test_bad_model_input_names_the_parameter(self):
        with self.assertRaisesRegex(ValueError, "gap"):
            CharpyFrictionModel(**dict(STANDARD, gap_m=0.06))
        out = subprocess.run([sys.executable, os.path.join(CI, "charpy_friction_model.py"), "--mu=-1"],
                             capture_output=True, text=True)
        self.assertEqual(out.returncode, 2)
        self.assertIn("mu", out.stderr)


if __name__ == "__main__":
    RUNNER = sys.argv.pop(1)
    unittest.main(verbosity=2)
