"""GUI text renders whole under OSMesa: the first glyph of a Gwen label keeps its lower-left half.

Runs the browser with its GUI at 1024x768 for two frames and looks at the menu bar, whose layout is
fixed: "File" starts at x = 13 px, "View" at x = 46 px. Before patch 0009 the first quad of every
text batch lost its lower-left triangle (GLInstancingRenderer::drawPoints wrote point colours into
GLPrimitiveRenderer's index buffer), so the F's stem and the V's left stroke were missing.

usage: gui_text_whole.py BROWSER WORK_DIR
"""
import glob
import os
import shutil
import subprocess
import sys

from PIL import Image

DARK = 110  # luminance below which a pixel is glyph ink on the light menu bar


def ink(image, x0, x1, y0, y1):
    """Dark pixels in the box [x0, x1) x [y0, y1)."""
    return sum(1 for x in range(x0, x1) for y in range(y0, y1) if image.getpixel((x, y)) < DARK)


def main():
    browser, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    run = subprocess.run([browser, "--window_backend=osmesa", "--start_demo_name=Charpy", "--width=1024", "--height=768",
                          "--png_file=" + os.path.join(work, "frame"), "--max_frames=2"],
                         capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        sys.exit(f"browser exited {run.returncode}: {run.stderr[-500:]}")
    frames = sorted(glob.glob(os.path.join(work, "frame*.png")))
    if not frames:
        sys.exit("no frame written")
    image = Image.open(frames[-1]).convert("L")
    if image.size != (1024, 768):
        sys.exit(f"frame is {image.size}, expected (1024, 768)")
    checks = {
        # first glyphs: their lower-left halves
        "stem of the F of 'File' (x 13, y 6-14)": (ink(image, 13, 14, 6, 15), 6),
        "left stroke of the V of 'View' (x 46-48, y 6-13)": (ink(image, 46, 49, 6, 14), 5),
        # control: a glyph inside a label, never affected
        "the i and l of 'File' (x 19-22, y 4-15)": (ink(image, 19, 22, 4, 15), 10),
    }
    failed = [f"{what}: {count} dark pixels, expected at least {least}" for what, (count, least) in checks.items() if count < least]
    for what, (count, least) in checks.items():
        print(f"{what}: {count} dark pixels (at least {least})")
    if failed:
        sys.exit("GUI text is clipped:\n" + "\n".join(failed))


if __name__ == "__main__":
    main()
