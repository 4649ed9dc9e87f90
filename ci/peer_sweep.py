#!/usr/bin/env python3
"""The MuJoCo peer over the same frame steps and solver iterations as our sweep (ci/charpy_sweep.py), one
CSV row per run: the peer beside our methods in REPORT.md.

  bash ci/peer_env.sh python3 ci/peer_sweep.py [--runner=build/bin/charpy] [--out=report/charpy-peer.csv]
                                               [--quick] [mujoco_charpy flags, e.g. --friction=0.1]

With --runner the peer takes the runner's Mp, impact speed and whatever geometry its --json names
(ci/models/mujoco_charpy.py --from-runner); without it, the standard geometry (ISO 148-1). MuJoCo's timestep is the
frame step (it has no contact substeps). Runs are made one after another in this process (one core; MuJoCo
steps on one thread), each timed from building the model to its last step, like the runner's wall_s.
Written whole (tmp file + rename).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "models"))
import charpy_sweep  # noqa: E402
import mujoco_charpy  # noqa: E402
from sweep import csvfile  # noqa: E402

FIRST_COLUMNS = ("key", "method", "dt_ms", "auto_dt", "iterations", "contact_substep_s")


def configurations(quick=False):
    steps = [1, 0.1] if quick else charpy_sweep.DT_MS
    iterations = [10] if quick else charpy_sweep.ITERATIONS
    return [(dt, it) for it in iterations for dt in steps]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runner", help="follow this runner's parameters (its --json output)")
    parser.add_argument("--out", default="report/charpy-peer.csv")
    parser.add_argument("--quick", action="store_true", help="two frame steps, 10 iterations (tests)")
    args, model_flags = parser.parse_known_args(argv)
    for flag in model_flags:
        name = flag.split("=", 1)[0]
        if name.lstrip("-").replace("-", "_") in ("dt_s", "iterations"):
            parser.error(f"{name}: the sweep sets the time step and the iterations itself")
    try:
        base, _ = mujoco_charpy.parse_args((["--from-runner=" + args.runner] if args.runner else []) + model_flags)
        errors = mujoco_charpy.validate(base)
        if errors:
            raise mujoco_charpy.ParameterError("\n".join(errors))
    except mujoco_charpy.ParameterError as e:
        print(f"peer_sweep: {e}", file=sys.stderr)
        return 2
    source = f"runner {args.runner}" if args.runner else "standard geometry (ISO 148-1)"
    rows = []
    for dt_ms, it in configurations(args.quick):
        p = dict(base, dt_s=dt_ms / 1000.0, iterations=it)
        r = mujoco_charpy.run(p)
        row = {"key": f"mujoco/dt={dt_ms:g}/it={it}", "method": "mujoco", "dt_ms": f"{dt_ms:g}", "auto_dt": "0",
               "iterations": str(it), "contact_substep_s": "", "parameters_from": source}
        row.update({k: (int(v) if isinstance(v, bool) else v) for k, v in r.items() if k not in ("method", "iterations")})
        rows.append(row)
        print(f"{row['key']}: loss {r['energy_loss_J']:.1f} J, hinge {r['plastic_work_J']:.1f} J, analytic {r['analytic_J']:.1f} J, "
              f"{r['wall_s']:.4f} s{' DIVERGED' if r['diverged'] else ''}", file=sys.stderr)
    csvfile.write_rows(args.out, rows, FIRST_COLUMNS)
    print(f"{len(rows)} rows in {args.out} (MuJoCo {rows[0]['mujoco_version']}, parameters from {source})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
