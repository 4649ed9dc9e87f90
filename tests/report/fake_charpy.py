#!/usr/bin/env python3
"""A stand-in for build/bin/charpy --json in the sweep tests: a deterministic result from the flags,
and one line per call appended to $FAKE_CHARPY_LOG (so tests can count runs)."""
import json
import os
import sys

flags = dict(a.split("=", 1) if "=" in a else (a, "1") for a in sys.argv[1:])
with open(os.environ["FAKE_CHARPY_LOG"], "a") as log:
    log.write(" ".join(sys.argv[1:]) + "\n")
if flags.get("--method") == "broken-on-purpose":
    sys.exit(2)
dt = float(flags.get("--dt", "0.005"))
loss = 127.4 * (1 + 10 * dt)
print(json.dumps({"method": flags.get("--method"), "dt": dt, "steps": int(0.06 / dt), "wall_s": 0.001 / dt * 1e-3,
                  "E0_J": 283.0, "energy_loss_J": loss, "plastic_work_J": loss * 0.95, "analytic_J": 127.4,
                  "error_pct": (loss - 127.4) / 127.4 * 100, "verdict": "stable"}))
