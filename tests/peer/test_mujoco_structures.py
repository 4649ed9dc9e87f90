"""The MuJoCo structures peer (ci/models/mujoco_structures.py): its cantilever is the project's (segment masses and
inertias, Mp and Mp/L against the runner), its energy bookkeeping read from MuJoCo's constraint forces, the collapse
load and the mechanisms at its stiffest friction rows, the creep report/STRUCTURES-MUJOCO.md describes, and the
quick report. Run by ctest through ci/peer_env.sh (the pinned mujoco in the build tree's venv), which skips it (77)
only when mujoco cannot be installed. About 5 s.

STRUCTURES_RUNNER (set by ctest): build/bin/structures, for the test that the model has the runner's Mp.
"""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CI = os.path.join(HERE, "..", "..", "ci", "models")
sys.path.insert(0, CI)
sys.path.insert(1, os.path.dirname(CI))  # ci/: the sweep and report tools
import mujoco_structures as ms  # noqa: E402
from sweep import csvfile  # noqa: E402

STIFFEST = ("stiffest", "Newton", 100)


class ModelTest(unittest.TestCase):
    def test_segments_are_the_projects(self):
        import mujoco
        # BeamBuilder: m = rho b d L/n = 7800 x 0.05 x 0.1 x 0.5 = 19.5 kg; btBoxShape: Izz = m/12 (l^2 + d^2)
        model = mujoco.MjModel.from_xml_string(ms.cantilever_xml(4))
        self.assertEqual(model.nbody, 5)
        for b in range(1, 5):
            self.assertAlmostEqual(model.body_mass[b], 19.5, places=9)
            self.assertAlmostEqual(model.body_inertia[b][2], 19.5 / 12 * (0.25 + 0.01), places=9)
        self.assertEqual(list(model.dof_frictionloss), [50000.0] * 4)
        self.assertAlmostEqual(ms.MP, 50000.0)

    @unittest.skipUnless(os.environ.get("STRUCTURES_RUNNER"), "STRUCTURES_RUNNER not set")
    def test_mp_and_collapse_load_are_the_runners(self):
        ms.check_runner(os.environ["STRUCTURES_RUNNER"])  # raises SystemExit when they differ


class CollapseTest(unittest.TestCase):
    """A dead load of 1.5 Mp/L until the root stops (4 segments, stiffest friction rows, Newton)."""

    @classmethod
    def setUpClass(cls):
        cls.r = ms.cantilever_run(4, STIFFEST, 1.5, 10.0, stop=True)

    def test_load_work_is_kinetic_plus_dissipated(self):
        r = self.r
        self.assertTrue(r["finite"] and not r["diverged"], r)
        self.assertLess(abs(r["load_work_J"] - r["kinetic_J"] - r["dissipated_J"]), 0.01 * r["load_work_J"], r)

    def test_the_root_dissipates_mp_times_its_rotation(self):
        # MuJoCo's root friction row against Mp x the root's rotation from qpos, and both about all the work
        r = self.r
        self.assertLess(abs(r["root_dissipated_J"] - r["root_mp_x_rotation_J"]), 0.01 * r["root_mp_x_rotation_J"], r)
        self.assertLess(abs(r["dissipated_J"] - r["mp_x_rotations_J"]), 0.01 * r["dissipated_J"], r)
        self.assertGreater(r["root_dissipated_J"], 0.98 * r["dissipated_J"])

    def test_stops_where_plastic_analysis_says(self):
        self.assertAlmostEqual(ms.stop_rotation(1.5), 1.4957816, places=6)
        self.assertLess(abs(self.r["stop_rotation_rad"] - ms.stop_rotation(1.5)), 0.01 * ms.stop_rotation(1.5), self.r)

    def test_a_wrong_plastic_moment_is_told(self):
        # the same bookkeeping on hinges of 0.8 Mp: the root dissipates 0.8 x Mp x its rotation, so the check can fail
        xml = ms.cantilever_xml(4, *STIFFEST).replace(f'frictionloss="{ms.MP:.9g}"', f'frictionloss="{0.8 * ms.MP:.9g}"')
        r = ms.Run(xml, [ms.MP / ms.LENGTH_M])
        for _ in range(24):
            r.step(1.5)
        self.assertAlmostEqual(r.root_dissipated / r.root_path, 0.8, delta=0.01)


class HoldAndYieldTest(unittest.TestCase):
    def test_the_root_yields_near_mp_over_l_at_the_stiffest_rows(self):
        # 4 segments: below 1.0 the root turns less than 0.05 rad in 1 s, above 1.05 more
        at_09 = ms.cantilever_run(4, STIFFEST, 0.9, 1.0)
        at_11 = ms.cantilever_run(4, STIFFEST, 1.1, 1.0)
        self.assertLess(at_09["max_root_rotation_rad"], 0.05, at_09)
        self.assertGreater(at_11["max_root_rotation_rad"], 0.5, at_11)
        root, _, diverged, _ = ms.cantilever_collapse(4, STIFFEST)
        self.assertEqual(diverged, 0)
        self.assertGreater(float(root), 0.9)
        self.assertLess(float(root), 1.05)

    def test_frictionloss_creeps_below_mp(self):
        # what STRUCTURES-MUJOCO.md reports: MuJoCo's soft friction rows let the cantilever sag under 0.9 Mp/L;
        # at MuJoCo's default softness it hangs down (tip 2 m below) within 3 s; the stiffest rows still creep
        default = ms.cantilever_run(4, ("default", "Newton", 100), 0.9, 3.0)
        stiffest = ms.cantilever_run(4, STIFFEST, 0.9, 3.0)
        self.assertGreater(default["tip_sag_m"], 1.9, default)
        self.assertGreater(stiffest["tip_sag_m"], 0.05, stiffest)
        self.assertGreater(stiffest["creep_rad"], 0.01, stiffest)
        self.assertLess(stiffest["tip_sag_m"], default["tip_sag_m"])


class PortalTest(unittest.TestCase):
    def test_the_combined_mechanism_forms_at_1_1(self):
        r = ms.portal_run(STIFFEST, 1.1, 1.0, until_rad=0.05)
        self.assertEqual(r["mechanism"], "base-left mid-span knee-right base-right", r)
        self.assertLess(r["closure_gap_m"], 1e-3)
        rot = r["rotations"]  # plastic analysis: -0.5 / 1 / -1 / 0.5 of the mid-span's
        for site, share in [("base-left", -0.5), ("knee-right", -1.0), ("base-right", 0.5)]:
            self.assertAlmostEqual(rot[site] / rot["mid-span"], share, delta=0.05, msg=(site, rot))

    def test_holds_at_0_9(self):
        r = ms.portal_run(STIFFEST, 0.9, 1.0)
        self.assertLess(r["max_rotation_rad"], 0.01, r)


class QuickReportTest(unittest.TestCase):
    def test_quick_sweep_writes_csv_and_report_whole(self):
        out = tempfile.mkdtemp()
        csv, md = os.path.join(out, "s.csv"), os.path.join(out, "S.md")
        done = subprocess.run([sys.executable, os.path.join(CI, "mujoco_structures.py"), "--quick", f"--csv={csv}", f"--md={md}"],
                              capture_output=True, text=True, timeout=120)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertEqual(sorted(os.listdir(out)), ["S.md", "s.csv"])  # no .tmp left behind
        rows = {r["key"]: r for r in csvfile.read_rows(csv)}
        self.assertIn("mujoco/stiff/Newton/100/hold/4", rows)
        self.assertIn("mujoco/stiff/Newton/100/stop/4", rows)
        self.assertGreater(float(rows["mujoco/stiff/Newton/100/time/4"]["median_us"]), 0)
        with open(md) as f:
            text = f.read()
        self.assertIn(f"# The structures scenes in MuJoCo {ms.MUJOCO_VERSION}", text)
        for heading in ("## Hold at 0.9 Mp/L", "## Collapse load", "## Energy balance in a collapse", "## Wall time per step"):
            self.assertIn(heading, text)
        done = subprocess.run([sys.executable, os.path.join(CI, "mujoco_structures.py"), "--quick", "--runner=/nonexistent", f"--csv={csv}"],
                              capture_output=True, text=True, timeout=60)
        self.assertEqual(done.returncode, 2)
        self.assertIn("/nonexistent is not an executable file", done.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
