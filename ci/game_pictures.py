#!/usr/bin/env python3
"""Pictures of one wrecking-ball run, from what build/bin/wrecking_ball and the browser wrote (they only read the world):

  ci/game_pictures.py --history=history.csv --joints=joints.csv --frames=DIR --out-dir=DIR [--fps=N]

Writes DIR/wrecking-ball.gif (or --gif-name; the frames PREFIX<n>.png of --frames in the order of n), DIR/energy.png (gravity work,
kinetic energy, plastic energy booked by the joints and measured from the bodies, dissipated, against time) and
DIR/joint-energy.png (each joint's plastic energy, broken joints marked). Every file is written whole (a temporary
file, then renamed). An MP4 is not made: Debian's ffmpeg is not among the project's dependencies.
"""
import argparse
import csv
import os
import sys

import frames  # ci/frames.py

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path, needed):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"game_pictures: {path} has no rows")
    missing = [c for c in needed if c not in rows[0]]
    if missing:
        raise SystemExit(f"game_pictures: {path} lacks the columns {', '.join(missing)}")
    return rows


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)


def energy_plot(rows, path):
    columns = (("gravity_work_J", "work of gravity"), ("kinetic_J", "kinetic"), ("plastic_booked_J", "plastic (booked by the joints)"),
               ("plastic_measured_J", "plastic (Mp x rotations from the bodies)"), ("dissipated_J", "dissipated (contacts, solver)"))
    fig, ax = plt.subplots(figsize=(8, 5), dpi=100)
    t = [float(r["time_s"]) for r in rows]
    for column, label in columns:
        ax.plot(t, [float(r[column]) / 1e3 for r in rows], label=label, ls="--" if column == "plastic_measured_J" else "-")
    ax.set_xlabel("time [s] (60 Hz frames)")
    ax.set_ylabel("energy [kJ]")
    ax.set_title("Wrecking ball: energy balance measured from the bodies")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, path)


# more joints than this: only those that booked at least 1 % of the largest are drawn (a building's hundreds)
MAX_JOINTS_SHOWN = 40


def shown_joints(rows):
    """The joints the per-joint plot draws: all of them, or past MAX_JOINTS_SHOWN those that booked 1 % of the largest."""
    if len(rows) <= MAX_JOINTS_SHOWN:
        return rows
    largest = max(float(r["booked_work_J"]) for r in rows)
    if not largest > 0:
        return rows[:MAX_JOINTS_SHOWN]
    return [r for r in rows if float(r["booked_work_J"]) >= 0.01 * largest]


def joint_plot(rows, path):
    title = "Wrecking ball: plastic energy per joint (red: broken)"
    shown = shown_joints(rows)
    if len(shown) < len(rows):
        title = "Wrecking ball: plastic energy of the %d of %d joints with 1 %% of the largest or more (red: broken)" % (len(shown), len(rows))
    rows = shown
    names = [r["joint"] for r in rows]
    booked = [float(r["booked_work_J"]) / 1e3 for r in rows]
    broken = [r["broken"] == "1" for r in rows]
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
    ax.bar(range(len(names)), booked, color=["#d91414" if b else "#ff8c0d" for b in broken])
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels(names, rotation=60, ha="right", fontsize=8)
    ax.set_ylabel("plastic energy [kJ]")
    ax.set_title(title, fontsize=10)
    ax.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    save(fig, path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--history", required=True)
    parser.add_argument("--joints", required=True)
    parser.add_argument("--frames", required=True)
    parser.add_argument("--out-dir", required=True)
    parser.add_argument("--fps", type=float, default=30.0)
    parser.add_argument("--gif-name", default="wrecking-ball.gif", help="the animation's file name in --out-dir")
    args = parser.parse_args(argv)
    if not 0.5 <= args.fps <= 100:
        raise SystemExit(f"game_pictures: --fps: {args.fps} is not in [0.5, 100]")
    history = read_csv(args.history, ["time_s", "gravity_work_J", "kinetic_J", "plastic_booked_J", "plastic_measured_J", "dissipated_J"])
    joints = read_csv(args.joints, ["joint", "booked_work_J", "broken"])
    os.makedirs(args.out_dir, exist_ok=True)
    energy_plot(history, os.path.join(args.out_dir, "energy.png"))
    joint_plot(joints, os.path.join(args.out_dir, "joint-energy.png"))
    n = frames.animation(args.frames, os.path.join(args.out_dir, args.gif_name), args.fps, 64, "game_pictures")
    print(f"wrote energy.png, joint-energy.png, {args.gif_name} ({n} frames) to {args.out_dir}")


if __name__ == "__main__":
    sys.exit(main())
