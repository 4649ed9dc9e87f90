"""ci/city_pictures.py: the city's animation and its three modes side by side, files written whole, bad input refused."""
import os
import subprocess
import sys
import tempfile
import unittest

from PIL import Image

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ci", "city_pictures.py")


def frames(d, name, count, channel):
    """count frames of one colour channel (0 red, 1 green, 2 blue), brighter frame by frame (a GIF keeps equal frames as one)"""
    directory = os.path.join(d, name)
    os.makedirs(directory)
    for i in range(count):
        colour = [0, 0, 0]
        colour[channel] = 255 - 40 * i
        Image.new("RGB", (40, 30), tuple(colour)).save(os.path.join(directory, f"frame{i}.png"))
    return directory


class CityPicturesTest(unittest.TestCase):
    def run_script(self, dirs, out, *extra):
        return subprocess.run([sys.executable, SCRIPT, "--frames=" + ",".join(dirs), f"--out-dir={out}", *extra], capture_output=True, text=True)

    def test_the_three_modes_side_by_side(self):
        with tempfile.TemporaryDirectory() as d:
            dirs = [frames(d, m, 3, c) for m, c in (("jit", 0), ("jointed", 1), ("rigid", 2))]
            out = os.path.join(d, "out")
            r = self.run_script(dirs, out, "--scale=0.5")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(sorted(os.listdir(out)), ["city-modes.gif", "city.gif"])
            with Image.open(os.path.join(out, "city.gif")) as gif:
                self.assertEqual((gif.n_frames, gif.size), (3, (40, 30)))
            with Image.open(os.path.join(out, "city-modes.gif")) as gif:
                self.assertEqual((gif.n_frames, gif.size), (3, (60, 15)))
                rgb = gif.convert("RGB")
                # left to right: jit (red), jointed (green), rigid (blue)
                self.assertGreater(rgb.getpixel((5, 7))[0], 200)
                self.assertGreater(rgb.getpixel((30, 7))[1], 200)
                self.assertGreater(rgb.getpixel((55, 7))[2], 200)

    def test_bad_input_is_refused(self):
        with tempfile.TemporaryDirectory() as d:
            dirs = [frames(d, "jit", 3, 0), frames(d, "jointed", 2, 1), frames(d, "rigid", 3, 2)]
            out = os.path.join(d, "out")
            r = self.run_script(dirs, out)
            self.assertNotEqual(r.returncode, 0)
            self.assertIn("the directories hold 3, 2, 3 frames", r.stderr)
            r = self.run_script(dirs[:2], out)
            self.assertIn("--frames: 2 directories, expected 3", r.stderr)
            r = self.run_script([dirs[0], dirs[2], dirs[0]], out, "--scale=2")
            self.assertIn("--scale: 2.0 is not in [0.1, 1]", r.stderr)
            r = self.run_script([dirs[0], dirs[2], os.path.join(d, "none")], out)
            self.assertIn("no PNG frames in", r.stderr)
            self.assertFalse(os.path.exists(os.path.join(out, "city-modes.gif")))


if __name__ == "__main__":
    unittest.main()
