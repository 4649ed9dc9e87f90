"""ci/charpy_pictures.py: plots from a history CSV and an animation from PNG frames, files written whole,
bad input refused."""
import os
import subprocess
import sys
import tempfile
import unittest

from PIL import Image

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ci", "charpy_pictures.py")


def history(path, rows=50):
    with open(path, "w") as f:
        f.write("time_s,potential_J,kinetic_J,elastic_J,total_J,plastic_work_J,bend_angle_rad,hammer_angle_rad\n")
        for i in range(rows):
            bend = 0.02 * i
            work = 64.0 * bend  # a hinge yielding at Mp = 64 N m
            f.write(f"{1e-4 * i},{40.0},{243.0 - work},{0},{283.0 - work},{work},{bend},{0.001 * i}\n")


class PicturesTest(unittest.TestCase):
    def test_plots_and_animation(self):
        with tempfile.TemporaryDirectory() as d:
            history(os.path.join(d, "history.csv"))
            frames = os.path.join(d, "frames")
            os.makedirs(frames)
            for i, colour in enumerate(("red", "green", "blue")):
                Image.new("RGB", (32, 24), colour).save(os.path.join(frames, f"frame{i}.png"))
            out = os.path.join(d, "out")
            subprocess.run([sys.executable, SCRIPT, f"--history={d}/history.csv", f"--frames={frames}", f"--out-dir={out}"],
                           check=True, capture_output=True)
            for name in ("energy.png", "moment-rotation.png"):
                with Image.open(os.path.join(out, name)) as im:
                    self.assertGreater(im.size[0], 400)
            with Image.open(os.path.join(out, "charpy.gif")) as gif:
                self.assertEqual(gif.n_frames, 3)
            self.assertEqual(sorted(os.listdir(out)), ["charpy.gif", "energy.png", "moment-rotation.png"])

    def test_bad_input_is_refused_and_nothing_is_written(self):
        with tempfile.TemporaryDirectory() as d:
            history(os.path.join(d, "history.csv"))
            out = os.path.join(d, "out")
            r = subprocess.run([sys.executable, SCRIPT, f"--history={d}/history.csv", f"--out-dir={out}", "--fps=0"],
                               capture_output=True, text=True)
            self.assertNotEqual(r.returncode, 0)
            self.assertIn("--fps: 0.0 is not in [0.5, 100]", r.stderr)
            self.assertFalse(os.path.exists(out))
            with open(os.path.join(d, "bad.csv"), "w") as f:
                f.write("time_s,kinetic_J\n0,1\n")
            r = subprocess.run([sys.executable, SCRIPT, f"--history={d}/bad.csv", f"--out-dir={out}"], capture_output=True, text=True)
            self.assertNotEqual(r.returncode, 0)
            self.assertIn("lacks the columns", r.stderr)


if __name__ == "__main__":
    unittest.main()
