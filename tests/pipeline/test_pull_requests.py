#!/usr/bin/env python3
"""The split into upstream pull requests (ci/stage-pull-requests, patches/pull-requests), offline.

  test_pull_requests.py PROJECT_DIR WORK_DIR DOWNLOAD_DIR

CI has no bullet3 clone, so the branches are staged on a git repository of the pinned sdist's pristine
tree (cmake/PrepareBulletTree.cmake with an empty series: the sources the series is made against) with
--series-only: each pull request's patches of patches/series must apply there alone (or on the branch it
requires), one commit per patch, with no formatting violation, and nothing of 0020. The staging patches
(01NN) need upstream's build files, which the sdist lacks; they are checked for their place in a pull
request here and applied in a real checkout by `ci/stage-pull-requests bullet3 --build=DIR`.
Also: a spec that leaves a patch out, or names a patch twice, is refused.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import unittest

PROJECT, WORK, DOWNLOADS = (os.path.abspath(a) for a in sys.argv[1:4])
del sys.argv[1:4]
SCRIPT = os.path.join(PROJECT, "ci", "stage-pull-requests")
sys.path.insert(0, os.path.join(PROJECT, "ci"))


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def subject(patch):
    """the Subject: of a patch header, unfolded (git am joins continuation lines with a space)"""
    text = open(os.path.join(PROJECT, "patches", patch), encoding="utf-8").read()
    m = re.search(r"^Subject:\s*(?:\[PATCH[^\]]*\]\s*)?(.*(?:\n[ \t].*)*)", text, re.M)
    assert m, "%s has no Subject:" % patch
    return " ".join(part.strip() for part in m.group(1).split("\n"))


def series(name):
    return [l.split()[0] for l in open(os.path.join(PROJECT, "patches", name)) if l.strip() and not l.startswith("#")]


def spec():
    """patches/pull-requests: not-for-upstream numbers and {name: (numbers, requires)} in order"""
    held, prs, name = [], {}, None
    for line in open(os.path.join(PROJECT, "patches", "pull-requests")):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        m = re.fullmatch(r"\[(.+)\]", line)
        if m:
            name = m.group(1)
            prs[name] = ([], "")
            continue
        key, _, value = (x.strip() for x in line.partition("="))
        numbers = []
        if key in ("patches", "not-for-upstream"):
            for item in value.split():
                a, _, b = item.partition("-")
                numbers += ["%04d" % n for n in range(int(a), int(b or a) + 1)]
        if key == "not-for-upstream":
            held += numbers
        elif key == "patches":
            prs[name][0].extend(numbers)
        elif key == "requires":
            prs[name] = (prs[name][0], value)
    return held, prs


class SpecCheck(unittest.TestCase):
    def test_spec_covers_every_patch(self):
        r = run([SCRIPT, "--check"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("not for upstream: 0020", r.stdout)

    def write_spec(self, text):
        os.makedirs(WORK, exist_ok=True)
        path = os.path.join(WORK, "spec")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_a_patch_in_no_pull_request_is_refused(self):
        text = open(os.path.join(PROJECT, "patches", "pull-requests")).read().replace("patches = 0012 0105", "patches = 0105")
        r = run([SCRIPT, "--check", "--spec=" + self.write_spec(text)])
        self.assertEqual(r.returncode, 1)
        self.assertRegex(r.stderr, r"patch 0012-\S+ is in no pull request")

    def test_a_patch_in_two_pull_requests_is_refused(self):
        text = open(os.path.join(PROJECT, "patches", "pull-requests")).read().replace("patches = 0008-0009", "patches = 0008-0010")
        r = run([SCRIPT, "--check", "--spec=" + self.write_spec(text)])
        self.assertEqual(r.returncode, 1)
        self.assertIn("patch 0010 is in both", r.stderr)

    def test_an_unknown_prerequisite_is_refused(self):
        text = open(os.path.join(PROJECT, "patches", "pull-requests")).read() + "\n[late]\ntitle = t\npatches = 0099\nrequires = nothing\n"
        r = run([SCRIPT, "--check", "--spec=" + self.write_spec(text)])
        self.assertEqual(r.returncode, 1)
        self.assertIn("'late' requires 'nothing'", r.stderr)


class StagedOnTheSdist(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(WORK, ignore_errors=True)
        os.makedirs(os.path.join(WORK, "empty"))
        open(os.path.join(WORK, "empty", "series"), "w").close()
        tree = os.path.join(WORK, "bullet3")
        r = run(["cmake", "-DPROJECT_DIR=" + PROJECT, "-DDEST=" + tree, "-DDOWNLOAD_DIR=" + DOWNLOADS,
                 "-DSERIES=" + os.path.join(WORK, "empty", "series"), "-P",
                 os.path.join(PROJECT, "cmake", "PrepareBulletTree.cmake")])
        assert r.returncode == 0, r.stdout + r.stderr
        os.remove(os.path.join(tree, ".bullet-plasticity-stamp")) if os.path.exists(
            os.path.join(tree, ".bullet-plasticity-stamp")) else None
        ident = ["-c", "user.name=test", "-c", "user.email=test@invalid"]
        for cmd in (["init", "-q", "-b", "master"], ["add", "-A"], ident + ["commit", "-q", "-m", "pristine sdist"]):
            r = run(["git", "-C", tree] + cmd)
            assert r.returncode == 0, r.stderr
        cls.tree = tree
        cls.out = os.path.join(WORK, "descriptions")
        cls.staging = run([SCRIPT, tree, "--series-only", "--out=" + cls.out])
        cls.held, cls.prs = spec()

    def log(self, rev_range):
        return run(["git", "-C", self.tree, "log", "--reverse", "--format=%s", rev_range]).stdout.splitlines()

    def test_every_pull_request_stages_cleanly(self):
        self.assertEqual(self.staging.returncode, 0, self.staging.stdout + self.staging.stderr)
        self.assertEqual(run(["git", "-C", self.tree, "symbolic-ref", "--short", "HEAD"]).stdout.strip(), "master",
                         "the checkout is left on the branch it was on")

    def test_each_branch_has_exactly_its_own_series_patches(self):
        main = series("series")
        staged = 0
        for name, (numbers, requires) in self.prs.items():
            mine = [p for p in main if p[:4] in numbers]
            exists = run(["git", "-C", self.tree, "rev-parse", "--verify", "--quiet", "refs/heads/pr/" + name]).returncode == 0
            if not mine:
                self.assertFalse(exists, name + " has no patch in the series: no branch")
                self.assertRegex(self.staging.stdout, name + r"\s+skipped")
                continue
            base = "pr/" + requires if requires else "master"
            self.assertEqual(self.log(base + "..pr/" + name), [subject(p) for p in mine], name)
            staged += 1
        self.assertGreaterEqual(staged, 5)

    def test_no_branch_carries_a_patch_not_for_upstream(self):
        held = [subject(p) for p in series("series") if p[:4] in self.held]
        self.assertTrue(held, "0020 is in the series")
        for name in self.prs:
            for s in self.log("master..pr/" + name) if os.path.exists(os.path.join(self.out, name + ".md")) else []:
                self.assertNotIn(s, held, name)

    def test_descriptions_say_what_why_how_tested_and_show_figures(self):
        summary = json.load(open(os.path.join(self.out, "summary.json")))
        described = {e["name"]: e for e in summary["pull_requests"] if e.get("description")}
        self.assertIn("island-lookup", described)
        for name, entry in described.items():
            text = open(entry["description"], encoding="utf-8").read()
            self.assertIn("## What and why", text, name)
            self.assertIn("## How it was tested", text, name)
            for p in entry["patches"]:
                self.assertIn("### " + subject(p), text, name)
            self.assertIn("every changed line follows upstream's", text, name)
        island = open(described["island-lookup"]["description"], encoding="utf-8").read()
        # the figures are copied from the report, not typed into the spec
        bench = open(os.path.join(PROJECT, "report", "BENCHMARKS.md"), encoding="utf-8").read()
        row = re.search(r"^\| hinge_locked \| 10000 \|.*$", bench, re.M).group(0)
        self.assertIn(row, island)
        self.assertIn("Not staged in this run (--series-only): `0105-", island)


if __name__ == "__main__":
    unittest.main(verbosity=2)
