#!/usr/bin/env python3
"""The wrecking ball example rendered headless (OSMesa): before the impact every joint marker is elastic green and
nothing is orange (yielded) or red (broken); after it, yielded and broken joints show in their colours.

  structure_colours.py BROWSER WORKDIR
"""
import glob
import os
import shutil
import subprocess
import sys

from PIL import Image

# demos/examples/StructureView.cpp: kYieldedRgba, kBrokenRgba, kElasticMarkerRgba as 8-bit colours
YIELDED = (255, 140, 13)
BROKEN = (217, 20, 20)
ELASTIC = (26, 191, 51)


def count(path, colour, tolerance=30):
    image = Image.open(path).convert("RGB")
    pixels = image.get_flattened_data() if hasattr(image, "get_flattened_data") else image.getdata()
    return sum(1 for p in pixels if all(abs(a - b) <= tolerance for a, b in zip(p, colour)))


def main():
    browser, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    # 60 Hz browser frames at time scale 1: frames 0, 60, 120 written (t = 0.02, 1.02, 2.02 s); the ball hits at 1.1 s
    subprocess.run([browser, "--window_backend=osmesa", "--start_demo_name=Wrecking ball", "--nogui", "--png_file=frame",
                    "--png_skip_frames=59", "--fixed_timestep=0.0166667", "--max_frames=121", "--width=480", "--height=300"],
                   cwd=work, check=True, stdout=subprocess.DEVNULL)
    frames = sorted(glob.glob(os.path.join(work, "frame*.png")))
    if len(frames) != 3:
        sys.exit(f"expected 3 frames, got {frames}")
    before, after = os.path.join(work, "frame0.png"), os.path.join(work, "frame2.png")
    counts = {name: (count(before, c), count(after, c)) for name, c in (("yielded", YIELDED), ("broken", BROKEN), ("elastic", ELASTIC))}
    print(counts)
    failures = []
    if counts["elastic"][0] == 0:
        failures.append("no elastic joint marker before the impact")
    if counts["yielded"][0] or counts["broken"][0]:
        failures.append("yielded or broken colours before the impact")
    if counts["yielded"][1] == 0:
        failures.append("no yielded colour after the impact")
    if counts["broken"][1] == 0:
        failures.append("no broken colour after the impact")
    if failures:
        sys.exit("; ".join(failures))


if __name__ == "__main__":
    main()
