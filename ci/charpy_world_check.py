#!/usr/bin/env python3
"""The world's own contact steps (patch 0053) on cases the reports do not list, each against its own converged run.

Three scenes (the thesis scene; the standard striker with friction 0.1; the standard striker without friction on
ISO anvils), impact speeds of 2.5, 3.5, 6, 8 and 12 m/s, each as it is, with a 3 mm notch and with a 30 kg hammer,
run with `--solver=direct --speculative-contacts --contact-substep=0 --world-contact-travel=3e-4` at 1 ms and 1/60 s
frames, against the same case with the direct solve and speculative contacts at 2 us contact substeps in 0.1 ms
frames (its converged run) with the contact rows' turn prediction (`--contact-turn-prediction`, patch 0055; without
it the 2 us runs still carry a first-order loss of halves sliding on the striker while they spin: 118.8 J against
113.0 J for the thesis scene with a 3 mm notch at 12 m/s). Prints one line per run (internal steps, steps to the test's end, loss, its converged
loss, the difference, verdicts) and a summary; a line is marked << where the run is not stable, ends otherwise than
its converged run (through the gap, over the top, not through), is more than 5 % off, or takes more than 100
internal steps to the test's end. Not part of CI (180 runs, about a minute on two cores).

Usage: python3 ci/charpy_world_check.py --runner=build/bin/charpy [--converged-runner=RUNNER] [--jobs=2]
(--converged-runner: the build that runs the converged runs, default --runner: a candidate build against a known one)
"""
import argparse
import concurrent.futures
import json
import subprocess
import sys

WORLD = ["--solver=direct", "--speculative-contacts", "--contact-substep=0", "--world-contact-travel=3e-4"]
CONVERGED = ["--solver=direct", "--speculative-contacts", "--dt=1e-4", "--contact-substep=2e-6", "--contact-turn-prediction"]
FRAMES = {"1 ms": "1e-3", "1/60 s": repr(1.0 / 60.0)}
SCENES = {"thesis": ["--geometry=thesis"],
          "standard, friction 0.1": ["--geometry=standard", "--friction=0.1"],
          "standard, frictionless, ISO anvils": ["--geometry=standard", "--friction=0", "--anvil-radius=0.001",
                                                 "--anvil-taper=0.192"]}
SPEEDS_M_S = ["2.5", "3.5", "6", "8", "12"]
VARIANTS = {"": [], "3 mm notch": ["--notch-depth=0.003"], "30 kg hammer": ["--hammer-mass=30"]}


def run(runner, args):
    out = subprocess.run([runner, "--json"] + args, capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runner", required=True)
    parser.add_argument("--converged-runner", default="")
    parser.add_argument("--jobs", type=int, default=2)
    a = parser.parse_args(argv)
    converged_runner = a.converged_runner or a.runner
    cases = [(s, v, n, SCENES[s] + [f"--impact-speed={v}"] + VARIANTS[n]) for s in SCENES for v in SPEEDS_M_S
             for n in VARIANTS]
    jobs = []
    for case in cases:
        jobs.append(case[3] + CONVERGED)
        jobs += [case[3] + WORLD + [f"--dt={dt}"] for dt in FRAMES.values()]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        results = dict(zip(map(tuple, jobs), pool.map(lambda j: run(converged_runner if j[-len(CONVERGED):] == CONVERGED else a.runner, j), jobs)))
    marked = 0
    errors = []
    for scene, speed, variant, args in cases:
        ref = results[tuple(args + CONVERGED)]
        for frame, dt in FRAMES.items():
            r = results[tuple(args + WORLD + [f"--dt={dt}"])]
            err = 100.0 * (r["energy_loss_J"] - ref["energy_loss_J"]) / ref["energy_loss_J"]
            errors.append(abs(err))
            bad = (r["verdict"] != "stable" or r["accuracy"] != ref["accuracy"] or abs(err) > 5.0
                   or r["test_steps"] > 100)
            marked += bad
            print(f"{scene:34} {speed:>4} m/s {variant:12} {frame:7} steps {r['steps']:3} (test {r['test_steps']:3}) "
                  f"loss {r['energy_loss_J']:7.2f} J converged {ref['energy_loss_J']:7.2f} J {err:+5.1f} % "
                  f"{r['verdict']} {r['accuracy']} / {ref['accuracy']}{'  <<' if bad else ''}")
    print(f"{marked} of {len(errors)} runs marked; mean |difference| {sum(errors) / len(errors):.2f} %, "
          f"largest {max(errors):.1f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
