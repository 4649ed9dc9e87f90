#!/usr/bin/env python3
"""Feeds random argument lists to the console runner (fixed seed, bounded in time) and checks that it
never crashes or hangs: exit 0 with a result, or exit 2 with a message, and no file written then.

  fuzz_runner.py RUNNER WORKDIR [CASES]
"""
import os
import random
import subprocess
import sys

FLAGS = ["method", "dt", "auto-dt", "fy", "parts", "anvil-gap", "hammer-thickness", "max-plastic-rotation",
         "iterations", "release-angle", "initial-energy", "friction", "contact-substep", "auto-dt-coarse", "free-step",
         "youngs-modulus", "density", "specimen-width", "specimen-length", "notch-depth", "min-steps-per-period",
         "brittle-force", "hammer-mass", "draft", "duration", "json", "list-methods", "help"]
VALUES = ["-1", "0", "nan", "NaN", "inf", "-inf", "1e308", "-1e308", "1e-300", "abc", "", "1e", "0x10", " 3",
          "2", "3", "7", "0.5", "1e-4", "1e-3", "0.02", "400e6", "plastic-hinge", "rigid", "spring2", "64", "65",
          "10001", "1,5", "--", "=", "1e-7"]


def random_args(rng):
    args = []
    for _ in range(rng.randint(0, 5)):
        roll = rng.random()
        if roll < 0.08:
            args.append("--" + "".join(rng.choice("abcxyz-_") for _ in range(rng.randint(1, 8))))  # unknown flag
        elif roll < 0.12:
            args.append(rng.choice(["-x", "plain", "---dt=1", "--=3", "--dt"]))  # malformed
        else:
            flag = rng.choice(FLAGS)
            args.append(f"--{flag}" if rng.random() < 0.1 else f"--{flag}={rng.choice(VALUES)}")
    if not any(a.startswith("--duration") for a in args):
        args.append("--duration=0.003")  # keep valid runs short; the fuzz is about the input
    return args


def main(runner, work, cases, hang_s=30.0):
    rng = random.Random(20261121)
    os.makedirs(work, exist_ok=True)
    history = os.path.join(work, "history.csv")
    failures = []
    for i in range(cases):
        args = random_args(rng)
        if os.path.exists(history):
            os.remove(history)
        cmd = [runner] + args + [f"--history={history}"]
        try:
            done = subprocess.run(cmd, capture_output=True, text=True, timeout=hang_s)
        except subprocess.TimeoutExpired:
            failures.append(f"hang (> {hang_s:g} s): {cmd}")
            continue
        if done.returncode not in (0, 2):
            failures.append(f"exit {done.returncode} (crash?): {cmd}\n{done.stderr[-300:]}")
        elif done.returncode == 2 and (not done.stderr.strip() or os.path.exists(history)):
            failures.append(f"exit 2 without a message or with a file written: {cmd}")
        elif done.returncode == 0 and not done.stdout.strip():
            failures.append(f"exit 0 without output: {cmd}")
        elif "nan" in done.stdout.lower() and "--json" in " ".join(args) and '"finite":true' in done.stdout:
            failures.append(f"NaN in a finite result: {cmd}")
    for f in failures:
        print(f)
    print(f"{cases} random argument lists, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 300,
                  float(sys.argv[4]) if len(sys.argv) > 4 else 30.0))
