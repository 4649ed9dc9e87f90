#!/usr/bin/env python3
"""Pictures of one Charpy run, from what the runner and the browser wrote (they only read the world):

  ci/charpy_pictures.py --history=history.csv --out-dir=DIR [--frames=DIR] [--fps=N]

Writes DIR/energy.png (kinetic, potential, elastic, plastic and total energy against time),
DIR/moment-rotation.png (the moment the bending joints transmit against the bend: the slope of the
plastic work over the bend angle, which is Mp while the hinge yields) and, with --frames, DIR/charpy.gif
from the frames PREFIX<n>.png in that folder, in the order of n. Every file is written whole (a temporary
file, then renamed).
"""
import argparse
import csv
import os
import sys

import frames  # ci/frames.py

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_history(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"charpy_pictures: {path} has no rows")
    needed = ["time_s", "potential_J", "kinetic_J", "elastic_J", "total_J", "plastic_work_J", "bend_angle_rad"]
    missing = [c for c in needed if c not in rows[0]]
    if missing:
        raise SystemExit(f"charpy_pictures: {path} lacks the columns {', '.join(missing)}")
    return {c: [float(r[c]) for r in rows] for c in needed}


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)


def energy_plot(h, path):
    fig, ax = plt.subplots(figsize=(8, 5), dpi=100)
    t_ms = [t * 1e3 for t in h["time_s"]]
    for column, label in (("kinetic_J", "kinetic"), ("potential_J", "potential"), ("elastic_J", "elastic"),
                          ("plastic_work_J", "plastic work"), ("total_J", "total (kinetic + potential + elastic)")):
        ax.plot(t_ms, h[column], label=label)
    total_with_plastic = [a + b for a, b in zip(h["total_J"], h["plastic_work_J"])]
    ax.plot(t_ms, total_with_plastic, "k--", lw=1, label="total + plastic work")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("energy [J]")
    ax.set_title("Charpy run: energy balance")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, path)


def moment_plot(h, path):
    bend = [abs(b) for b in h["bend_angle_rad"]]
    work = h["plastic_work_J"]
    angles, moments = [], []
    for i in range(1, len(bend)):
        d_angle = bend[i] - bend[i - 1]
        if d_angle > 1e-6:
            angles.append(bend[i])
            moments.append((work[i] - work[i - 1]) / d_angle)
    fig, ax = plt.subplots(figsize=(8, 5), dpi=100)
    ax.plot(angles, moments, ".", ms=3)
    ax.set_xlabel("bend angle of the middle joint [rad]")
    ax.set_ylabel("moment: d(plastic work) / d(bend) [N m]")
    ax.set_title("Charpy run: moment against rotation of the bending joint")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    save(fig, path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--history", required=True)
    parser.add_argument("--out-dir", required=True)
    parser.add_argument("--frames")
    parser.add_argument("--fps", type=float, default=10.0)
    args = parser.parse_args(argv)
    if not 0.5 <= args.fps <= 100:
        raise SystemExit(f"charpy_pictures: --fps: {args.fps} is not in [0.5, 100]")
    h = read_history(args.history)
    os.makedirs(args.out_dir, exist_ok=True)
    energy_plot(h, os.path.join(args.out_dir, "energy.png"))
    moment_plot(h, os.path.join(args.out_dir, "moment-rotation.png"))
    written = ["energy.png", "moment-rotation.png"]
    if args.frames:
        n = frames.animation(args.frames, os.path.join(args.out_dir, "charpy.gif"), args.fps, 128, "charpy_pictures")
        written.append(f"charpy.gif ({n} frames)")
    print(f"wrote {', '.join(written)} to {args.out_dir}")


if __name__ == "__main__":
    sys.exit(main())
