#!/usr/bin/env python3
"""Structures with textbook answers: error against run time.

  ci/structures_report.py [--runner=build/bin/structures] [--out=report/STRUCTURES.md] [--jobs=2] [--command=TEXT]

Runs build/bin/structures for every case below, every joint method of the factory (the upstream hinge-motor
stand-in among them), internal steps 1/60, 1/120, 1/240, 1/480 s and 1 ms at 10 and 50 iterations, plus the
converged setting the tests use, and writes OUT (markdown) whole (tmp file + rename): the error against the
plastic-analysis answer, whether the predicted mechanism formed, and the wall time of each run.
"""
import argparse
import concurrent.futures
import json
import os
import platform
import subprocess
import sys
import time

METHODS = ["hinge-motor", "plastic-hinge", "elastic-plastic", "elastic-plastic2"]
STEPS = [("1/60 s", 1 / 60), ("1/120 s", 1 / 120), ("1/240 s", 1 / 240), ("1/480 s", 1 / 480), ("1 ms", 1e-3)]
ITERATIONS = [10, 50]
# name, what, runner arguments, converged (dt, iterations), json field of the simulated value, of the answer, mechanism check
CASES = [
    ("cantilever collapse", "4 segments, tip load ramped 0.02/s from 0.9 Mp/L: P L / Mp at collapse (analytic 1), hinge at the root only",
     ["--scene=cantilever", "--ramp-rate=0.02"], (1e-3, 1000), "collapse_ratio", None, "cantilever"),
    ("cantilever dead load 1.5 Mp/L", "where it stops (analytic: 1.5 sin(theta) = theta, 1.4958 rad), measured from the bodies",
     ["--scene=cantilever", "--load-ratio=1.5"], (1e-3, 1000), "stop_rotation_rad", "analytic_stop_rotation_rad", None),
    ("portal frame, combined", "H h = V L/2 = 3 Mp: load factor at collapse (analytic 1, combined mechanism: base-left, mid-span, knee-right, base-right)",
     ["--scene=portal"], (1e-3, 200), "collapse_factor", "analytic_collapse_factor", "portal"),
    ("portal frame, sway", "H h = 3.5 Mp, V L/2 = Mp: load factor at collapse (analytic 8/7, sway mechanism: bases and knees)",
     ["--scene=portal", "--horizontal-load=58333.333", "--vertical-load=25000"], (1e-3, 200), "collapse_factor", "analytic_collapse_factor", "portal"),
    ("drop weight, simply supported", "1000 kg at 4.5 m/s on a 2 m beam: mid-span rotation (rigid-plastic estimate 0.1974 rad)",
     ["--scene=drop-weight"], (1e-4, 1000), "midspan_rotation_rad", "analytic_midspan_rotation_rad", None),
    ("drop weight, clamped", "the same, clamped: mid-span rotation (estimate 0.0987 rad; supports half of it)",
     ["--scene=drop-weight", "--clamped"], (1e-4, 1000), "midspan_rotation_rad", "analytic_midspan_rotation_rad", None),
]


def run(runner, args):
    start = time.monotonic()
    p = subprocess.run([runner, "--json"] + args, capture_output=True, text=True, timeout=3600)
    if p.returncode not in (0, 3):
        return {"error": p.stderr.strip()}
    d = json.loads(p.stdout)
    d["process_s"] = time.monotonic() - start
    return d


def mechanism_ok(kind, d):
    if kind == "cantilever":
        return d.get("mechanism") == ["root"]
    if kind == "portal":
        return bool(d.get("mechanism_matches"))
    return True


def cell(case, d):
    _, _, _, _, field, answer_field, kind = case
    if "error" in d:
        return "refused"
    value = d.get(field)
    answer = 1.0 if answer_field is None else d.get(answer_field)
    if value is None or answer in (None, 0):
        # no collapse confirmed: how far it sagged (crept) anyway
        sag = max([abs(x) for x in d.get("rotations_rad", [])] + [d.get("max_root_rotation_rad", 0), d.get("max_inner_rotation_rad", 0)])
        return "none, sagged %.2f rad (%.2f s)" % (sag, d["wall_s"])
    text = "%+.1f %%" % (100 * (value - answer) / answer)
    if kind and not mechanism_ok(kind, d):
        text += " ✗"
    if not d.get("finite", True):
        text += " NaN"
    return "%s (%.2f s)" % (text, d["wall_s"])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runner", default="build/bin/structures")
    ap.add_argument("--out", default="report/STRUCTURES.md")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--command", default="python3 ci/structures_report.py")
    a = ap.parse_args()
    jobs = {}
    for ci, case in enumerate(CASES):
        for m in METHODS:
            for label, dt in STEPS:
                for it in ITERATIONS:
                    jobs[(ci, m, label, it)] = case[2] + ["--method=" + m, "--dt=%.10g" % dt, "--iterations=%d" % it]
            dt, it = case[3]
            jobs[(ci, m, "converged", it)] = case[2] + ["--method=" + m, "--dt=%g" % dt, "--iterations=%d" % it]
    results = {}
    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run, a.runner, args): key for key, args in jobs.items()}
        for f in concurrent.futures.as_completed(futures):
            results[futures[f]] = f.result()
    total = time.monotonic() - started
    lines = [
        "# Structures with textbook answers: error against run time",
        "",
        "Generated by `%s` (%d runs of `build/bin/structures`, %.0f s with %d jobs) on %s, %s, Python %s."
        % (a.command, len(jobs), total, a.jobs, platform.node(), platform.processor() or platform.machine(), platform.python_version()),
        "",
        "Each cell: the simulated value's error against the plastic-analysis answer the scene computes from its parameters,",
        "and the run's wall time. ✗: the joints that turned are not the predicted mechanism (cantilever: more than the root;",
        "portal: not the predicted hinges). Collapse loads come from a quasi-static ramp (0.02/s from 0.9 of the answer) held",
        "when a joint runs away, confirmed when the held load turns the mechanism 0.05 rad; a structure that sags or creeps",
        "before its collapse load shows a negative error; `none, sagged X rad`: no collapse was confirmed within the run's",
        "duration but its joints crept that far under loads that rose past the answer. Rotations and work are measured on the bodies, not read from the",
        "joints' bookkeeping. `converged`: the setting the tests use (1 ms and 1000 iterations for the cantilever, 1 ms and",
        "200 for the portal, 0.1 ms and 1000 for the drop weight). Reproduce one cell with",
        "`build/bin/structures <case flags> --method=M --dt=DT --iterations=N --json`.",
        "",
        "The elastic-plastic methods are elastic (EI/L) where a joint's period spans at least 25 steps (their frequency",
        "ratio), rigid-plastic otherwise: on the portal at 1 ms they bend elastically by about 0.1 rad before the",
        "collapse and the frame gives about 9 % early, most likely from the second-order (P-delta) effect of the displaced",
        "loads that first-order plastic analysis leaves out (ten times stiffer, `--youngs-modulus=2e12`, elastic-plastic2",
        "collapses at +0.3 %). The rigid-plastic drop-weight estimate likewise leaves out the elastic energy",
        "(Mp^2 / (2 EI/L) per hinge) those methods store, and their mid-span rotation is measured at the deepest point.",
        "",
    ]
    for ci, case in enumerate(CASES):
        name, what, args = case[0], case[1], case[2]
        lines += ["## %s" % name, "", "%s. Flags: `%s`." % (what, " ".join(args)), ""]
        header = "| method | iterations | " + " | ".join(l for l, _ in STEPS) + " | converged |"
        lines += [header, "|" + " --- |" * (len(STEPS) + 3)]
        for m in METHODS:
            for it in ITERATIONS:
                row = [m, str(it)] + [cell(case, results[(ci, m, l, it)]) for l, _ in STEPS]
                row.append(cell(case, results[(ci, m, "converged", case[3][1])]) if it == ITERATIONS[0] else "")
                lines.append("| " + " | ".join(row) + " |")
        lines.append("")
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines))
    os.replace(tmp, a.out)
    print("wrote %s (%d runs, %.0f s)" % (a.out, len(jobs), total))


if __name__ == "__main__":
    sys.exit(main())
