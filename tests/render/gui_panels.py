"""The browser's GUI panels are where demos/examples/ViewFraming.h says: the examples frame their scenes in the rest.

Runs the browser with its GUI at 800x600 and 1024x768 for two frames and looks for the edges of the 3D view (its
background colour) next to the explorer (left), the parameters (right), the menu bar (top) and the console with the
status bar (bottom), at the widths and heights ViewFraming.h gives them.

usage: gui_panels.py BROWSER VIEWFRAMING_H WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

from PIL import Image


def constant(header, name):
    m = re.search(r"constexpr int %s = ([0-9 +]+);" % name, header)
    if not m:
        sys.exit(f"{name} not found in ViewFraming.h")
    return sum(int(t) for t in m.group(1).split("+"))


def main():
    browser, header_file, work = sys.argv[1], sys.argv[2], sys.argv[3]
    header = open(header_file).read()
    side, top, bottom = (constant(header, n) for n in ("kBrowserSidePanel_px", "kBrowserMenuBar_px", "kBrowserBottomPanels_px"))
    failed = []
    for w, h in ((800, 600), (1024, 768)):
        d = os.path.join(work, f"{w}x{h}")
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        run = subprocess.run([browser, "--window_backend=osmesa", "--start_demo_name=Cantilever", f"--width={w}", f"--height={h}",
                              "--png_file=" + os.path.join(d, "frame"), "--max_frames=2"], capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            sys.exit(f"browser exited {run.returncode}: {run.stderr[-500:]}")
        image = Image.open(os.path.join(d, "frame1.png")).convert("RGB")
        background = image.getpixel((side + 2, h // 2 + 60))  # the 3D view just right of the explorer, left of any text
        row, column = h - bottom - 8, side + 2  # below the structure and left of the ledger's ink
        checks = {
            "explorer's edge": (image.getpixel((side - 1, row)) != background, image.getpixel((side, row)) == background),
            "parameters' edge": (image.getpixel((w - side, row)) != background, image.getpixel((w - side - 1, row)) == background),
            "menu bar's edge": (image.getpixel((column, top - 1)) != background, image.getpixel((column, top)) == background),
            "console's edge": (image.getpixel((column, h - bottom)) != background, image.getpixel((column, h - bottom - 1)) == background),
        }
        for what, (panel, view) in checks.items():
            print(f"{w}x{h} {what}: panel {'yes' if panel else 'NO'}, 3D view {'yes' if view else 'NO'}")
            if not (panel and view):
                failed.append(f"{w}x{h} {what}")
    if failed:
        sys.exit("the GUI panels are not where ViewFraming.h says: " + ", ".join(failed))


if __name__ == "__main__":
    main()
