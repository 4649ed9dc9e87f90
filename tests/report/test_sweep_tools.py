"""The sweep's CSV, shards, merge and resume, and the report generator, on tiny sweeps with a fake runner."""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CI = os.path.join(HERE, "..", "..", "ci")
sys.path.insert(0, CI)
import charpy_report  # noqa: E402
import charpy_sweep  # noqa: E402
from sweep import csvfile, runner  # noqa: E402

FAKE = os.path.join(HERE, "fake_charpy.py")


class SweepTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.log = os.path.join(self.dir, "calls.log")
        os.environ["FAKE_CHARPY_LOG"] = self.log
        self.configurations = charpy_sweep.configurations(quick=True)

    def calls(self):
        return open(self.log).read().splitlines() if os.path.exists(self.log) else []

    def test_every_configuration_runs_once_and_lands_in_the_csv(self):
        out = os.path.join(self.dir, "sweep.csv")
        rows = runner.run_all(FAKE, self.configurations, out, jobs=2, log=open(os.devnull, "w"))
        self.assertEqual(len(rows), len(self.configurations))
        self.assertEqual(len(self.calls()), len(self.configurations))
        written = csvfile.read_rows(out)
        self.assertEqual([r["key"] for r in written], [c["key"] for c in self.configurations])
        self.assertTrue(all(r["energy_loss_J"] for r in written))
        self.assertFalse(os.path.exists(out + ".tmp"))

    def test_fresh_rows_are_the_rows_a_resumed_sweep_returns(self):
        # the runner's booleans come back as ints from a fresh run and as text from the CSV; callers see text either way
        out = os.path.join(self.dir, "sweep.csv")
        fresh = runner.run_all(FAKE, self.configurations[:2], out, jobs=1, log=open(os.devnull, "w"))
        resumed = runner.run_all(FAKE, self.configurations[:2], out, jobs=1, log=open(os.devnull, "w"))
        self.assertEqual(fresh, resumed)

    def test_resume_keeps_finished_rows_and_runs_only_the_rest(self):
        out = os.path.join(self.dir, "sweep.csv")
        runner.run_all(FAKE, self.configurations[:2], out, jobs=1, log=open(os.devnull, "w"))
        before = csvfile.read_rows(out)
        rows = runner.run_all(FAKE, self.configurations, out, jobs=2, log=open(os.devnull, "w"))
        self.assertEqual(len(self.calls()), len(self.configurations), "finished runs were repeated")
        self.assertEqual(len(rows), len(self.configurations))
        self.assertEqual(csvfile.read_rows(out)[:2], before)

    def test_an_interrupted_sweeps_journal_counts_as_finished(self):
        # a sweep killed after its third run: two rows in the CSV, the third only in the journal (half a line after it)
        out = os.path.join(self.dir, "sweep.csv")
        runner.run_all(FAKE, self.configurations[:2], out, jobs=1, log=open(os.devnull, "w"))
        third = runner.run_one(FAKE, self.configurations[2], 600)
        with open(runner.journal_path(out), "w") as f:
            f.write(json.dumps(third) + "\n" + '{"key": "half')
        rows = runner.run_all(FAKE, self.configurations, out, jobs=2, log=open(os.devnull, "w"))
        self.assertEqual(len(self.calls()), len(self.configurations), "the journal's run was repeated")
        self.assertEqual(len(rows), len(self.configurations))
        self.assertEqual([r["key"] for r in csvfile.read_rows(out)], [c["key"] for c in self.configurations])
        self.assertEqual(csvfile.read_rows(out)[2]["energy_loss_J"], str(third["energy_loss_J"]))
        self.assertFalse(os.path.exists(runner.journal_path(out)))

    def test_rows_of_another_runner_build_are_run_again(self):
        out = os.path.join(self.dir, "sweep.csv")
        runner.run_all(FAKE, self.configurations[:2], out, jobs=1, log=open(os.devnull, "w"))
        rebuilt = os.path.join(self.dir, "fake_charpy_rebuilt.py")
        with open(FAKE) as f, open(rebuilt, "w") as g:
            g.write(f.read() + "\n# another build\n")
        os.chmod(rebuilt, 0o755)
        runner.run_all(rebuilt, self.configurations[:2], out, jobs=1, log=open(os.devnull, "w"))
        self.assertEqual(len(self.calls()), 4, "rows of the old build were reused")
        self.assertEqual({r["runner_id"] for r in csvfile.read_rows(out)}, {runner.runner_id(rebuilt)})

    def test_failed_runs_are_recorded_and_retried_on_resume(self):
        out = os.path.join(self.dir, "sweep.csv")
        bad = [{"key": "bad", "method": "x", "flags": ["--method=broken-on-purpose"]}]
        rows = runner.run_all(FAKE, bad, out, jobs=1, log=open(os.devnull, "w"))
        self.assertIn("exit 2", rows[0]["failure"])
        runner.run_all(FAKE, bad, out, jobs=1, log=open(os.devnull, "w"))
        self.assertEqual(len(self.calls()), 2)

    def test_shards_cover_every_configuration_once_and_merge_to_the_full_sweep(self):
        full = os.path.join(self.dir, "full.csv")
        runner.run_all(FAKE, self.configurations, full, jobs=2, log=open(os.devnull, "w"))
        shards = []
        for i in (1, 2, 3):
            path = os.path.join(self.dir, f"shard{i}.csv")
            runner.run_all(FAKE, runner.in_shard(self.configurations, (i, 3)), path, jobs=1, log=open(os.devnull, "w"))
            shards.append(path)
        merged = csvfile.merge(shards)
        self.assertEqual(sorted(r["key"] for r in merged), sorted(c["key"] for c in self.configurations))
        by_key = {r["key"]: r for r in csvfile.read_rows(full)}
        for r in merged:
            self.assertEqual(r["energy_loss_J"], by_key[r["key"]]["energy_loss_J"])

    def test_merge_rejects_two_different_results_for_one_key(self):
        a, b = os.path.join(self.dir, "a.csv"), os.path.join(self.dir, "b.csv")
        csvfile.write_rows(a, [{"key": "k", "energy_loss_J": "1"}])
        csvfile.write_rows(b, [{"key": "k", "energy_loss_J": "2"}])
        with self.assertRaises(SystemExit):
            csvfile.merge([a, b])

    def test_bad_shard_is_named(self):
        for text in ("0/2", "3/2", "x", "1/0"):
            with self.assertRaises(SystemExit) as e:
                runner.parse_shard(text)
            self.assertIn("--shard", str(e.exception))


class ReportTest(unittest.TestCase):
    def test_report_has_the_plot_the_tables_and_the_thesis_table(self):
        d = tempfile.mkdtemp()
        os.environ["FAKE_CHARPY_LOG"] = os.path.join(d, "calls.log")
        csv_path = os.path.join(d, "sweep.csv")
        runner.run_all(FAKE, charpy_sweep.configurations(quick=True), csv_path, jobs=2, log=open(os.devnull, "w"))
        md, png = charpy_report.report(csvfile.read_rows(csv_path), d, "test", "sweep.csv")
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertGreater(os.path.getsize(png), 10000)
        text = open(md).read()
        self.assertIn("## Energy loss [J], 10 iterations, contact substep 0.01 ms (default)", text)
        self.assertIn("| plastic-hinge | ", text)
        self.assertIn("| 0.1001 | 100 |", text)  # thesis Table 3.1, first row
        self.assertIn("shared 2-core machine", text)
        # the fake runner's loss at 1 ms is 127.4 * 1.01 = 128.7 J
        self.assertIn("128.7", text)

    def test_fewest_steps_takes_the_cheapest_run_within_5_percent_that_passes(self):
        # issue 25's table: per method and frame step, the fewest internal steps within 5 % of the converged loss
        def row(key, loss, steps, dt_ms="1", accuracy="accurate", **extra):
            return dict(dict(key=key, method="plastic-hinge", dt_ms=dt_ms, auto_dt="0", iterations="10", solver="direct",
                             contacts="speculative", reference="", contact_substep_s="6e-05", energy_loss_J=str(loss),
                             steps=str(steps), accuracy=accuracy), **extra)
        ref = row("ref", 100.0, 5000, dt_ms="0.1", reference="1", contact_substep_s="2e-06")
        rows = [ref,
                row("cheap-but-off", 106.0, 20),             # +6 %: outside
                row("cheap-but-stuck", 101.0, 25, accuracy="did-not-pass"),
                row("within", 104.9, 46),                    # the one
                row("within-dearer", 100.5, 263, contact_substep_s="1e-05"),
                row("sixty", 104.0, 120, dt_ms="16.7")]
        peer = [dict(key="p1", method="mujoco", dt_ms="0.01", iterations="50", energy_loss_J="125.0", steps="6000",
                     passed_anvils="1", diverged="0"),
                dict(key="p2", method="mujoco", dt_ms="1", iterations="10", energy_loss_J="100.0", steps="60",
                     passed_anvils="1", diverged="0"),
                dict(key="p3", method="mujoco", dt_ms="0.05", iterations="10", energy_loss_J="127.0", steps="1200",
                     passed_anvils="1", diverged="0")]
        converged = {"plastic-hinge": ref}
        text = charpy_report.fewest_steps(rows, converged, peer)
        self.assertIn("| 1 | 46 (direct, speculative, 0.06 ms, +4.9 %) | none |", text)
        self.assertIn("| 16.7 | 120 (direct, speculative, 0.06 ms, +4.0 %) | not run |", text)
        self.assertNotIn("| 0.1 |", text)  # the reference run is no frame step of the table
        self.assertIn("1 of these 2 cells", text)
        self.assertIn("1200 at 0.05 ms (+1.6 %", text)

    def test_pareto_front_keeps_only_unbeaten_points(self):
        front = charpy_report.pareto_front([(1, 10, "a"), (2, 5, "b"), (3, 7, "c"), (4, 1, "d")])
        self.assertEqual([p[2] for p in front], ["a", "b", "d"])


if __name__ == "__main__":
    unittest.main()
