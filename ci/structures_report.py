#!/usr/bin/env python3
"""Structures with textbook answers: error against run time.

  ci/structures_report.py [--runner=build/bin/structures] [--out=report/STRUCTURES.md] [--csv=build/sweep/structures.csv]
                          [--jobs=2] [--command=TEXT]

Runs build/bin/structures for every case below, every joint method of the factory (the upstream hinge-motor
stand-in among them), three solvers (upstream's sequential impulse, btMLCPSolver + Dantzig as upstream constructs
it, and the toolkit's default, btDirectJointSolver of patch 0019), internal steps 1/60, 1/120, 1/240, 1/480 s and 1 ms at 10 and 50 iterations, plus the converged setting
the tests use; then the game-settings summary (1/240 s, 10 iterations: collapse, holds at 0.9 of the collapse load
for 3 s, energy, fallbacks, cost per step). Writes OUT (markdown) whole (tmp file + rename): the error against the
plastic-analysis answer, whether the predicted mechanism formed, and the wall time of each run. The runs go through
ci/sweep (the runs of the other reports): their rows are kept in CSV (the runner's JSON whole in its 'json' column), and
a run the same runner binary already made is not run again.
"""
import argparse
import json
import os
import platform
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep import runner as sweep  # noqa: E402

METHODS = ["hinge-motor", "plastic-hinge", "elastic-plastic", "elastic-plastic2"]
# runner --solver name, label in the tables
SOLVERS = [("sequential-impulse", "sequential impulse"), ("dantzig", "Dantzig"), ("direct", "direct")]
GAME = ("1/240 s", 1 / 240, 10)
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
    ("portal frame, beam", "H h = Mp, V L/2 = 3.5 Mp: load factor at collapse (analytic 8/7, beam mechanism: knees and mid-span)",
     ["--scene=portal", "--horizontal-load=16666.667", "--vertical-load=87500"], (1e-3, 200), "collapse_factor", "analytic_collapse_factor", "portal"),
    ("drop weight, simply supported", "1000 kg at 4.5 m/s on a 2 m beam: mid-span rotation (rigid-plastic estimate 0.1974 rad)",
     ["--scene=drop-weight"], (1e-4, 1000), "midspan_rotation_rad", "analytic_midspan_rotation_rad", None),
    ("drop weight, clamped", "the same, clamped: mid-span rotation (estimate 0.0987 rad; supports half of it)",
     ["--scene=drop-weight", "--clamped"], (1e-4, 1000), "midspan_rotation_rad", "analytic_midspan_rotation_rad", None),
]


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
    if d.get("solver_fallbacks"):
        text += " [%d SI fallbacks]" % d["solver_fallbacks"]
    return "%s (%.2f s)" % (text, d["wall_s"])


# the collapse cases' plastic-analysis factor (for the holds at 0.9 of it) by their position in CASES
HOLD_FACTORS = {0: 1.0, 2: 1.0, 3: 8 / 7, 4: 8 / 7}


def hold_args(ci):
    case = CASES[ci]
    if case[6] == "cantilever":
        return ["--scene=cantilever", "--load-ratio=0.9", "--duration=3"]
    return case[2] + ["--ramp-rate=0", "--load-factor=%.8g" % (0.9 * HOLD_FACTORS[ci]), "--duration=3"]


def pct(x):
    return "n/a" if x is None else "%+.2f %%" % x


def summary_rows(results, converged_cell):
    """Scene x method x solver at game settings: the error, the mechanism, the hold, the energy, the cost."""
    rows = []
    for ci, case in enumerate(CASES):
        if ci == 1:
            continue  # the dead load is the cantilever's energy check, in its row
        for m in METHODS:
            for s, slabel in SOLVERS:
                d = results[(ci, m, s, GAME[0], GAME[2])]
                err = cell(case, d).rsplit(" (", 1)[0] if "error" not in d else "refused"
                kind = case[6]
                mech = "n/a" if kind is None else ("yes" if mechanism_ok(kind, d) and d.get(case[4]) is not None else "no")
                hold = creep = "n/a"
                if ci in HOLD_FACTORS:
                    h = results[("hold", ci, m, s)]
                    if "error" not in h:
                        largest = h.get("max_rotation_rad")
                        if largest is None:
                            largest = max(h.get("max_root_rotation_rad", 0), h.get("max_inner_rotation_rad", 0))
                        hold, creep = "%.4f rad" % largest, "%.4f rad" % h.get("creep_rad", 0)
                # energy gained (positive): what the bodies hold and the joints booked against what was put in
                gain = None
                if m != "hinge-motor":
                    if kind == "cantilever":
                        e = results[(1, m, s, GAME[0], GAME[2])]
                        if e.get("load_work_J"):
                            gain = 100 * (e["kinetic_J"] + e["booked_plastic_work_J"] - e["load_work_J"]) / e["load_work_J"]
                    elif kind == "portal":
                        if d.get("load_work_J"):
                            gain = 100 * (d["kinetic_J"] + d["booked_plastic_work_J"] - d["load_work_J"]) / d["load_work_J"]
                    elif d.get("initial_kinetic_J"):
                        gain = 100 * (d["kinetic_end_J"] + d["booked_plastic_work_J"] - d["initial_kinetic_J"]) / d["initial_kinetic_J"]
                steps = d.get("steps", 0) if "error" not in d else 0
                us = 1e6 * d["wall_s"] / steps if steps else float("nan")
                cost = ("%.0f" % us, "%.0f" % (4 * us)) if steps >= 100 else ("(%d steps)" % steps, "")
                rows.append([case[0], m, slabel, err, mech, hold, creep, "n/a (not booked)" if m == "hinge-motor" else pct(gain),
                             "%d" % d.get("solver_fallbacks", 0), cost[0], cost[1], converged_cell(ci, m, s)])
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runner", default="build/bin/structures")
    ap.add_argument("--out", default="report/STRUCTURES.md")
    ap.add_argument("--csv", default="build/sweep/structures.csv")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--command", default="python3 ci/structures_report.py")
    a = ap.parse_args()
    jobs = {}
    for ci, case in enumerate(CASES):
        for s, _ in SOLVERS:
            for m in METHODS:
                for label, dt in STEPS:
                    for it in ITERATIONS:
                        jobs[(ci, m, s, label, it)] = case[2] + ["--solver=" + s, "--method=" + m, "--dt=%.10g" % dt, "--iterations=%d" % it]
                dt, it = case[3]
                jobs[(ci, m, s, "converged", it)] = case[2] + ["--solver=" + s, "--method=" + m, "--dt=%g" % dt, "--iterations=%d" % it]
    for ci in HOLD_FACTORS:
        for s, _ in SOLVERS:
            for m in METHODS:
                jobs[("hold", ci, m, s)] = hold_args(ci) + ["--solver=" + s, "--method=" + m, "--dt=%.10g" % GAME[1], "--iterations=%d" % GAME[2]]
    started = time.monotonic()
    # the runner exits 3 when its verdict fails (the JSON is printed all the same)
    by_name = {repr(key): key for key in jobs}
    rows = sweep.run_all(a.runner, [{"key": repr(key), "flags": args} for key, args in jobs.items()], a.csv, a.jobs, timeout_s=3600,
                         accept_codes=(0, 3), keep_json=True)
    results = {by_name[r["key"]]: ({"error": r["failure"]} if r.get("failure") else json.loads(r["json"])) for r in rows}
    total = time.monotonic() - started

    def converged_cell(ci, m, s):
        return cell(CASES[ci], results[(ci, m, s, "converged", CASES[ci][3][1])])

    lines = [
        "# Structures with textbook answers: error against run time",
        "",
        "Generated by `%s` (%d runs of `build/bin/structures` through ci/sweep, %.0f s with %d jobs for those not already in"
        " `%s` from the same runner) on %s, %s, Python %s."
        % (a.command, len(jobs), total, a.jobs, a.csv, platform.node(), platform.processor() or platform.machine(), platform.python_version()),
        "",
        "Each cell: the simulated value's error against the plastic-analysis answer the scene computes from its parameters,",
        "and the run's wall time. ✗: the joints that turned are not the predicted mechanism (cantilever: more than the root;",
        "portal: not the predicted hinges). Collapse loads come from a quasi-static ramp (0.02/s from 0.9 of the answer) held",
        "when a joint runs away, confirmed when the held load turns the mechanism 0.05 rad; a structure that sags or creeps",
        "before its collapse load shows a negative error; `none, sagged X rad`: no collapse was confirmed within the run's",
        "duration but its joints crept that far under loads that rose past the answer. Rotations and work are measured on the bodies, not read from the",
        "joints' bookkeeping. Solvers: upstream's `btSequentialImpulseConstraintSolver`, `btMLCPSolver` + `btDantzigSolver`",
        "as upstream constructs them (runner `--solver=dantzig`: a dense direct solve; iterations are used only by a step",
        "that falls back to sequential impulse), and the toolkit's default, `btDirectJointSolver` (patch 0019, runner",
        "`--solver=direct`: the joint and contact rows solved directly along the joint graph, no setting).",
        "`[N SI fallbacks]`: steps in which the direct solve failed and the step was solved by sequential impulse. `converged`: the setting the tests use (1 ms and 1000 iterations for the",
        "cantilever, 1 ms and 200 for the portal, 0.1 ms and 1000 for the drop weight), with each solver. Reproduce one cell with",
        "`build/bin/structures <case flags> --solver=S --method=M --dt=DT --iterations=N --json`.",
        "",
        "The elastic-plastic methods are elastic (EI/L) where a joint's period spans at least 25 steps (their frequency",
        "ratio), rigid-plastic otherwise: on the portal at 1 ms they bend elastically before the collapse and the frame",
        "gives 5-11 % early. That is the coarse model of its elastic part, not the second-order (P-delta) effect first",
        "thought: the portal's members have two segments each, so each joint's elastic stiffness is EI over 1.5-2 m and",
        "the frame bends up to 0.19 rad before it collapses; with 8 beam and 4 column segments",
        "(`--beam-segments=8 --column-segments=4`) elastic-plastic2 collapses within +0.5 % in all three cases with the",
        "predicted mechanism (0.055 rad before it), and with the vertical load alone (`--horizontal-load=0`: symmetric, no",
        "sway, no P-delta) the two-segment frame is already -8.7 % (+0.15 % with 8 and 4 segments), while with the sway load",
        "alone (`--vertical-load=0`) it is +1.2 %. The rigid-plastic drop-weight estimate leaves out the elastic energy",
        "(Mp^2 / (2 EI/L) per hinge) those methods store, and their mid-span rotation is measured at the deepest point.",
        "",
        "## Game settings: 1/240 s (four internal steps per 60 Hz frame), 10 iterations",
        "",
        "Targets (issue 13): collapse loads within 3 % with the predicted mechanism, no flow and no creep below collapse,",
        "drop-weight rotations within 3 %, no energy gain. **hold 0.9, 3 s**: the load held at 0.9 of the plastic-analysis",
        "collapse load for 3 s from the start (cantilever `--load-ratio=0.9`, portal `--ramp-rate=0 --load-factor=0.9 x",
        "answer`): the largest joint rotation over the run and its change from 1 s to 3 s (creep). **energy gain**: what the",
        "bodies hold (kinetic) and the joints booked (plastic work) against what went in: cantilever, from the 1.5 Mp/L dead",
        "load, and portal, from the collapse run: (kinetic + booked - load work) / load work; drop weight: (kinetic at the end",
        "+ booked - the ball's kinetic energy) / the latter (its impact is inelastic: a few percent lost at least). Negative:",
        "lost, not gained; elastic energy is left out (0 for rigid-plastic joints). The hinge-motor stand-in books nothing.",
        "**fallbacks**: steps whose direct solve failed and fell back to sequential impulse.",
        "**us/step**: the run's wall time per internal step (the scene's own bookkeeping included; a shared 2-core machine,",
        "compare within one run; not shown for runs under 100 steps, which the set-up dominates;",
        "`build/bin/game_settings_benchmarks` measures the step alone, report/GAME_SETTINGS.md).",
        "",
        "| scene | method | solver | error | mechanism | hold 0.9, 3 s: largest rotation | creep 1-3 s | energy gain | fallbacks | us/step | us/frame (x4) | converged |",
        "|" + " --- |" * 12,
    ]
    for row in summary_rows(results, converged_cell):
        lines.append("| " + " | ".join(row) + " |")
    lines += [
        "",
        "The drop weight misses the 3 % target at 1/240 s with every solver and method: the plastic phase after",
        "the impact lasts about 22 internal steps (simply supported) or 6 (clamped), and Bullet's semi-implicit Euler moves",
        "each step with the velocity at its end, so the rotations come out short by a first-order step error (about half",
        "at 1/480 s; with Dantzig and the rigid-plastic methods -3.7 % / -4.6 % at 1/960 s, -2.0 % / -2.8 % at 1/3840 s).",
        "Sequential impulse adds its own error on the clamped beam (the right clamp turns the wrong way).",
        "",
    ]
    for ci, case in enumerate(CASES):
        name, what, args = case[0], case[1], case[2]
        lines += ["## %s" % name, "", "%s. Flags: `%s`." % (what, " ".join(args)), ""]
        header = "| method | solver | iterations | " + " | ".join(l for l, _ in STEPS) + " | converged |"
        lines += [header, "|" + " --- |" * (len(STEPS) + 4)]
        for m in METHODS:
            for s, slabel in SOLVERS:
                for it in ITERATIONS:
                    row = [m, slabel, str(it)] + [cell(case, results[(ci, m, s, l, it)]) for l, _ in STEPS]
                    row.append(converged_cell(ci, m, s) if it == ITERATIONS[0] else "")
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
