"""The MuJoCo peer (ci/models/mujoco_charpy.py) against the analytic Mp * theta_pass at a converged step, its parameters
and bad input, and the peer sweep and report section. Run by ctest through ci/peer_env.sh (the pinned mujoco in
the build tree's venv), which skips it (77) only when mujoco cannot be installed.

CHARPY_RUNNER (set by ctest): the console runner, for the test that the peer follows its parameters.
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CI = os.path.join(HERE, "..", "..", "ci", "models")
sys.path.insert(0, CI)
sys.path.insert(1, os.path.dirname(CI))  # ci/: the sweep and report tools
import mujoco_charpy as mc  # noqa: E402
import peer_report  # noqa: E402
from sweep import csvfile  # noqa: E402

SCRIPT = os.path.join(CI, "mujoco_charpy.py")
CONVERGED_DT_S = 1e-5  # the sweep's smallest frame step: the loss moves by < 0.3 % from 2e-5 s (REPORT.md)


def run_cli(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True, timeout=300)


class AnalyticTest(unittest.TestCase):
    def test_theta_pass_with_sharp_edges_is_the_runners(self):
        # the runner's --json with its defaults: theta_pass_rad 1.99064471, analytic_J 127.401261
        p = dict(mc.defaults(), anvil_edge_radius_m=0.0)
        mp, d, theta, analytic = mc.section(p)
        self.assertAlmostEqual(mp, 64.0, places=9)
        self.assertAlmostEqual(d, 0.006, places=12)
        self.assertAlmostEqual(theta, 1.99064471, places=7)
        self.assertAlmostEqual(analytic, 127.401261, places=4)

    def test_a_rounded_anvil_edge_lets_the_halves_pass_with_less_bend(self):
        sharp = mc.section(dict(mc.defaults(), anvil_edge_radius_m=0.0))[2]
        rounded = mc.section(mc.defaults())[2]
        self.assertLess(rounded, sharp)
        self.assertGreater(rounded, sharp - 0.05)


class ConvergedRunTest(unittest.TestCase):
    """Standard geometry at the converged step, with a little friction (0.05): frictionless, MuJoCo squeezes the
    specimen up over the anvils (REPORT.md); with friction it goes through the gap as in a machine."""

    @classmethod
    def setUpClass(cls):
        cls.p = dict(mc.defaults(), dt_s=CONVERGED_DT_S, friction=0.05)
        cls.r = mc.run(cls.p)

    def test_the_specimen_goes_through_the_gap(self):
        self.assertFalse(self.r["diverged"], self.r["mujoco_warning"])
        self.assertTrue(self.r["passed_anvils"])
        self.assertFalse(self.r["over_the_top"])

    def test_hinge_work_is_mp_times_theta_pass(self):
        # frictionloss work Mp * |rotation| against Mp * theta_pass of the same geometry: within 3 %
        self.assertLess(abs(self.r["plastic_work_J"] - self.r["analytic_J"]), 0.03 * self.r["analytic_J"], self.r)

    def test_energy_loss_is_the_hinge_work_plus_contact_losses(self):
        # the hammer's loss covers the hinge work; friction and inelastic contacts add at most 10 % of it
        self.assertGreaterEqual(self.r["energy_loss_J"], self.r["plastic_work_J"] - 0.5)
        self.assertLess(self.r["energy_loss_J"], 1.10 * self.r["analytic_J"])
        self.assertGreaterEqual(self.r["hammer_loss_J"], self.r["energy_loss_J"] - 0.5)

    def test_the_check_tells_a_wrong_plastic_moment(self):
        # the same check on a hinge 25 % weaker than the ligament's Mp fails: it can fail
        r = mc.run(dict(self.p, plastic_moment_nm=48.0))
        _, _, _, analytic_64 = mc.section(self.p)
        self.assertGreater(abs(r["plastic_work_J"] - analytic_64), 0.03 * analytic_64)

    def test_a_step_the_contacts_cannot_take_is_told(self):
        r = mc.run(dict(mc.defaults(), dt_s=1e-3))
        self.assertTrue(r["diverged"])
        self.assertIn("unstable", r["mujoco_warning"])


class ParameterTest(unittest.TestCase):
    def test_bad_input_names_the_parameter(self):
        for flag, text in [("--dt-s=-1", "dt_s: -1 s is not > 0"), ("--anvil-gap-m=abc", "anvil_gap_m: 'abc' is not a number"),
                           ("--iterations=2.5", "iterations: '2.5' is not a whole number"),
                           ("--friction=nan", "friction: 'nan' is not a finite number"),
                           ("--anvil-gap-m=0.06", "anvil_gap_m: 0.06 m is not < specimen_length_m"),
                           ("--contact-impedance=1", "contact_impedance: 1 is not < 1"),
                           ("--contact-timeconst-steps=1", "contact_timeconst_steps: 1 steps is not >= 2")]:
            with self.subTest(flag=flag):
                done = run_cli(flag)
                self.assertEqual(done.returncode, 2, done.stderr)
                self.assertIn(text, done.stderr)

    def test_bad_json_names_its_source(self):
        path = os.path.join(tempfile.mkdtemp(), "p.json")
        with open(path, "w") as f:
            f.write('{"hammer_mass_kg": "heavy"}')
        done = run_cli(f"--from-json={path}")
        self.assertEqual(done.returncode, 2)
        self.assertIn("hammer_mass_kg: 'heavy' is not a number", done.stderr)
        done = run_cli("--from-json=/nonexistent.json")
        self.assertIn("from-json: /nonexistent.json", done.stderr)
        done = run_cli("--from-runner=/nonexistent")
        self.assertIn("from-runner: /nonexistent is not an executable file", done.stderr)

    def test_runner_json_and_dump_set_parameters_and_flags_win(self):
        path = os.path.join(tempfile.mkdtemp(), "p.json")
        with open(path, "w") as f:
            json.dump({"plastic_moment_Nm": 50, "impact_speed_m_s": 5.1, "anvil_gap_m": 0.041, "dt": 0.5, "iterations": 3, "method": "x"}, f)
        p, _ = mc.parse_args([f"--from-json={path}", "--anvil-gap-m=0.042"])
        self.assertEqual((p["plastic_moment_nm"], p["impact_speed_m_s"], p["anvil_gap_m"]), (50, 5.1, 0.042))
        self.assertEqual((p["dt_s"], p["iterations"]), (mc.defaults()["dt_s"], mc.defaults()["iterations"]))  # the peer steps its own way

    @unittest.skipUnless(os.environ.get("CHARPY_RUNNER"), "CHARPY_RUNNER not set")
    def test_follows_the_runner(self):
        runner = os.environ["CHARPY_RUNNER"]
        out = json.loads(subprocess.run([runner, "--json", "--fy=300e6"], capture_output=True, text=True, check=True).stdout.splitlines()[-1])
        p = mc.defaults()
        mc.from_runner_json(p, out)
        self.assertAlmostEqual(p["plastic_moment_nm"], out["plastic_moment_Nm"])
        self.assertAlmostEqual(p["impact_speed_m_s"], out["impact_speed_m_s"])
        self.assertAlmostEqual(mc.section(p)[0], 48.0)


class SweepTest(unittest.TestCase):
    def test_quick_sweep_and_report_section(self):
        out = os.path.join(tempfile.mkdtemp(), "charpy-peer.csv")
        done = subprocess.run([sys.executable, os.path.join(os.path.dirname(CI), "peer_sweep.py"), "--quick", f"--out={out}"],
                              capture_output=True, text=True, timeout=300)
        self.assertEqual(done.returncode, 0, done.stderr)
        rows = csvfile.read_rows(out)
        self.assertEqual([r["key"] for r in rows], ["mujoco/dt=1/it=10", "mujoco/dt=0.1/it=10"])
        self.assertTrue(all(float(r["wall_s"]) > 0 and r["mujoco_version"] == mc.MUJOCO_VERSION for r in rows))
        text = peer_report.section(peer_report.read(out), [])
        self.assertIn(f"## Peer: MuJoCo {mc.MUJOCO_VERSION}", text)
        self.assertIn("| 0.1 |", text)
        self.assertIn("diverged (reset)", text)  # 1 ms
        done = subprocess.run([sys.executable, os.path.join(os.path.dirname(CI), "peer_sweep.py"), "--quick", f"--out={out}", "--dt-s=1"],
                              capture_output=True, text=True)
        self.assertEqual(done.returncode, 2)
        self.assertIn("the sweep sets the time step", done.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
