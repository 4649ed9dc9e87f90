#!/usr/bin/env python3
"""Animations of the city example, from the frames the browser wrote (it only reads the world):

  ci/city_pictures.py --frames=JIT_DIR,JOINTED_DIR,RIGID_DIR --out-dir=DIR [--fps=N] [--scale=S]

Writes DIR/city.gif (the first directory's frames, PREFIX<n>.png in the order of n) and DIR/city-modes.gif (the
three directories' frames side by side, left to right, frame by frame, each scaled by S, default 0.6; each frame's
ledger names its mode). Every file is written whole (a temporary file, then renamed).
"""
import argparse
import os
import sys

import frames  # ci/frames.py


def main(argv=None):
    from PIL import Image

    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", required=True, help="comma-separated frame directories: jit, jointed, rigid")
    parser.add_argument("--out-dir", required=True)
    parser.add_argument("--fps", type=float, default=15.0)
    parser.add_argument("--scale", type=float, default=0.6)
    args = parser.parse_args(argv)
    if not 0.1 <= args.scale <= 1:
        raise SystemExit(f"city_pictures: --scale: {args.scale} is not in [0.1, 1]")
    if not 0.5 <= args.fps <= 100:
        raise SystemExit(f"city_pictures: --fps: {args.fps} is not in [0.5, 100]")
    directories = args.frames.split(",")
    if len(directories) != 3:
        raise SystemExit(f"city_pictures: --frames: {len(directories)} directories, expected 3 (jit, jointed, rigid)")
    runs = [frames.frames_of(d, "city_pictures") for d in directories]
    count = min(len(r) for r in runs)
    if any(len(r) != count for r in runs):
        raise SystemExit("city_pictures: --frames: the directories hold " + ", ".join(str(len(r)) for r in runs) + " frames; expected as many in each")
    os.makedirs(args.out_dir, exist_ok=True)
    frames.save_gif([Image.open(f) for f in runs[0]], os.path.join(args.out_dir, "city.gif"), args.fps, 64)
    side = []
    for k in range(count):
        panels = [Image.open(r[k]).convert("RGB") for r in runs]
        panels = [p.resize((round(p.width * args.scale), round(p.height * args.scale)), Image.LANCZOS) for p in panels]
        width = sum(p.width for p in panels)
        height = max(p.height for p in panels)
        canvas = Image.new("RGB", (width, height), (255, 255, 255))
        x = 0
        for p in panels:
            canvas.paste(p, (x, 0))
            x += p.width
        side.append(canvas)
    frames.save_gif(side, os.path.join(args.out_dir, "city-modes.gif"), args.fps, 64)
    print(f"wrote city.gif and city-modes.gif ({count} frames each) to {args.out_dir}")


if __name__ == "__main__":
    sys.exit(main())
