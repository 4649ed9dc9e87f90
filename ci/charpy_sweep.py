#!/usr/bin/env python3
"""Error against run time: the Charpy test over methods 1-8 x frame steps x solver iterations x
contact substeps, and the plastic methods with the direct solve (--solver=direct) down to no substeps and
with speculative contacts (--speculative-contacts), with each plastic method's converged reference run,
each run by the console runner, one CSV row per run.

  ci/charpy_sweep.py [--runner=build/bin/charpy] [--out=report/charpy-sweep.csv] [--jobs=N]
                     [--shard=i/n] [--quick]
  ci/charpy_sweep.py --merge SHARD.csv... --out=report/charpy-sweep.csv

Finished rows are kept: run it again after an interruption and it goes on where it stopped.
With --shard=i/n it runs every n-th configuration (write each shard to its own --out, then merge).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep import csvfile, runner  # noqa: E402

METHODS = ["rigid", "brittle", "spring", "spring2", "hinge-motor", "plastic-hinge", "elastic-plastic", "elastic-plastic2"]
# frame steps, ms: the issue's list plus the thesis' Table 3.1 steps (0.1001, 0.099, 0.08 ms)
DT_MS = [0.01, 0.02, 0.05, 0.08, 0.099, 0.1, 0.1001, 0.2, 0.5, 1, 2, 5, 16.7]
ITERATIONS = [10, 50]
# internal step during contact, s: the default, twice it (convergence), and off (every frame step
# taken as it is)
CONTACT_SUBSTEP_S = [1e-5, 2e-5, 0]
# the direct solve (--solver=direct, btDirectJointSolver): the plastic methods at 10 iterations, with the default
# substep and coarser ones, down to none
DIRECT_METHODS = ["hinge-motor", "plastic-hinge", "elastic-plastic", "elastic-plastic2"]
DIRECT_SUBSTEP_S = [1e-5, 5e-5, 1e-4, 0]
# the direct solve with speculative box-box contacts (--speculative-contacts, patch 0036), at contact substeps up to
# what the hammer closes within the contacts' reach (0.3 mm at 4.4 m/s: 68 us), and 0.1 ms (one step per 0.1 ms frame:
# the only substep that keeps the whole test within 100 internal steps at 0.1 ms frames)
SPECULATIVE_SUBSTEP_S = [1e-5, 3e-5, 6e-5, 1e-4]
# and at 1 ms frames only, the substeps between (the frame step changes only the steps before the contacts' first
# tick: the world steps at the substep on its own clock): how the loss moves with the substep, not only at the chosen ones
LANDSCAPE_SUBSTEP_S = [4e-5, 5e-5, 7e-5, 8e-5, 9e-5, 1.1e-4, 1.2e-4]
LANDSCAPE_DT_MS = 1
# and with frames shorter than 5 ms gathered out of contact into one internal step (--free-step=5e-3): the steps a
# test takes then no longer grow with the frame rate (0.1 ms frames after the pass were a step each)
FREE_STEP_S = 5e-3
FREE_SUBSTEP_S = [3e-5, 6e-5]
# and those again with slow contacts stepped by their motion (--contact-travel, the speculative contacts' reach for
# the halves): a piece longer than the substep in which the pairs in or near contact move at most 0.3 mm is one step
FREE_TRAVEL_M = 3e-4
# and without the runner's substeps, the world cutting its own steps where a pair in or near contact would move more
# than the speculative contacts' reach for the halves (--world-contact-travel, patch 0053)
WORLD_TRAVEL_M = 3e-4
# and again with frames shorter than 1/60 s gathered into the world's fixed 1/60 s steps (--world-step: upstream's
# fixed-step stepSimulation, the world lagging the frames by less than a step), which the world cuts by its contacts:
# the steps a test takes then no longer grow with the frame rate
WORLD_STEP_S = 1.0 / 60.0
# each plastic method's converged run, the reference of the discretisation errors: direct solve, speculative contacts,
# 2 us contact substeps (the loss moves by 0.1 % between 2 and 1 us; sequential impulse gives the same at 2 us)
REFERENCE_SUBSTEP_S = 2e-6
FIRST_COLUMNS = ("key", "method", "dt_ms", "auto_dt", "iterations", "contact_substep_s", "free_step_s", "contact_travel_m",
                 "world_contact_travel_m", "world_step_s", "solver", "contacts", "reference")


def configurations(quick=False):
    """Every configuration of the sweep; quick: a tiny one for tests."""
    methods = ["plastic-hinge", "elastic-plastic2"] if quick else METHODS
    steps = [1, 0.1] if quick else DT_MS
    iterations = [10] if quick else ITERATIONS
    substeps = [1e-5] if quick else CONTACT_SUBSTEP_S
    out = []

    def add(method, it, sub, dt, solver, speculative=False, reference=False, free=0, travel=0, world=0, world_step=0):
        flags = [f"--method={method}", f"--iterations={it}", f"--contact-substep={sub:g}"]
        flags.append("--auto-dt" if dt == "auto" else f"--dt={dt / 1000:.10g}")
        key = f"{method}/dt={dt}/it={it}/sub={sub:g}"
        if solver != "sequential-impulse":
            flags.append(f"--solver={solver}")
            key += f"/solver={solver}"
        if speculative:
            flags.append("--speculative-contacts")
            key += "/speculative"
        if free:
            flags.append(f"--free-step={free:g}")
            key += f"/free={free:g}"
        if travel:
            flags.append(f"--contact-travel={travel:g}")
            key += f"/travel={travel:g}"
        if world:
            flags.append(f"--world-contact-travel={world:g}")
            key += f"/world={world:g}"
        if world_step:
            flags.append(f"--world-step={world_step:.10g}")
            key += f"/wstep={world_step:.6g}"
        if reference:
            key = f"{method}/reference"
        out.append({
            "key": key,
            "method": method,
            "dt_ms": "" if dt == "auto" else f"{dt:g}",
            "auto_dt": "1" if dt == "auto" else "0",
            "iterations": str(it),
            "contact_substep_s": f"{sub:g}",
            "free_step_s": f"{free:g}" if free else "",
            "contact_travel_m": f"{travel:g}" if travel else "",
            "world_contact_travel_m": f"{world:g}" if world else "",
            "world_step_s": f"{world_step:.6g}" if world_step else "",
            "solver": solver,
            "contacts": "speculative" if speculative else "",
            "reference": "1" if reference else "",
            "flags": flags,
        })

    for method in methods:
        for it in iterations:
            for sub in substeps:
                for dt in steps + ["auto"]:
                    add(method, it, sub, dt, "sequential-impulse")
    for method in (["plastic-hinge"] if quick else DIRECT_METHODS):
        for sub in ([1e-4] if quick else DIRECT_SUBSTEP_S):
            for dt in steps + ["auto"]:
                add(method, 10, sub, dt, "direct")
    for method in (["plastic-hinge"] if quick else DIRECT_METHODS):
        add(method, 10, REFERENCE_SUBSTEP_S, 0.1, "direct", speculative=True, reference=True)
        for sub in ([6e-5] if quick else SPECULATIVE_SUBSTEP_S):
            for dt in steps + ["auto"]:
                add(method, 10, sub, dt, "direct", speculative=True)
        for sub in ([] if quick else LANDSCAPE_SUBSTEP_S):
            add(method, 10, sub, LANDSCAPE_DT_MS, "direct", speculative=True)
        for sub in ([] if quick else FREE_SUBSTEP_S):
            for dt in steps:
                add(method, 10, sub, dt, "direct", speculative=True, free=FREE_STEP_S)
                add(method, 10, sub, dt, "direct", speculative=True, free=FREE_STEP_S, travel=FREE_TRAVEL_M)
        for dt in ([] if quick else steps + ["auto"]):
            add(method, 10, 0, dt, "direct", speculative=True, world=WORLD_TRAVEL_M)
        for dt in ([] if quick else [s for s in steps if s < WORLD_STEP_S * 1000 - 0.05]):
            add(method, 10, 0, dt, "direct", speculative=True, world=WORLD_TRAVEL_M, world_step=WORLD_STEP_S)
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runner", default="build/bin/charpy")
    parser.add_argument("--out", default="report/charpy-sweep.csv")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--shard", default="1/1")
    parser.add_argument("--quick", action="store_true", help="a tiny sweep (tests)")
    parser.add_argument("--merge", nargs="+", metavar="CSV", help="merge shard CSV files into --out")
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error(f"--jobs: {args.jobs} is not a whole number >= 1")
    if args.merge:
        rows = csvfile.merge(args.merge)
        csvfile.write_rows(args.out, rows, FIRST_COLUMNS)
        print(f"{len(rows)} rows from {len(args.merge)} files written to {args.out}")
        return 0
    todo = runner.in_shard(configurations(args.quick), runner.parse_shard(args.shard))
    rows = runner.run_all(args.runner, todo, args.out, args.jobs, first_columns=FIRST_COLUMNS)
    failed = [r for r in rows if r.get("failure")]
    for r in failed:
        print(f"failed: {r['key']}: {r['failure']}", file=sys.stderr)
    print(f"{len(rows)} rows in {args.out}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
