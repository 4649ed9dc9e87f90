"""ci/game_pictures.py: the animation, the energy plot and the per-joint plot of a wrecking-ball run, files written
whole, bad input refused."""
import os
import subprocess
import sys
import tempfile
import unittest

from PIL import Image

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ci", "game_pictures.py")


def inputs(d):
    with open(os.path.join(d, "history.csv"), "w") as f:
        f.write("time_s,gravity_work_J,kinetic_J,elastic_J,plastic_booked_J,plastic_measured_J,dissipated_J,yielded_joints,broken_joints\n")
        for i in range(30):
            f.write(f"{i / 60},{100.0 * i},{50.0 * i},0,{40.0 * i},{40.0 * i},{10.0 * i},0,0\n")
    with open(os.path.join(d, "joints.csv"), "w") as f:
        f.write("joint,plastic_moment_Nm,booked_rotation_rad,measured_rotation_rad,booked_work_J,measured_work_J,broken,broken_at_s\n")
        f.write("base-left,1000,0.2,0.2,200,200,1,1.3\nknee-left,1000,0.1,0.1,100,100,0,-1\n")
    frames = os.path.join(d, "frames")
    os.makedirs(frames)
    for i, colour in enumerate(("red", "green", "blue", "white")):
        Image.new("RGB", (32, 24), colour).save(os.path.join(frames, f"frame{i}.png"))
    return frames


class GamePicturesTest(unittest.TestCase):
    def run_script(self, d, *extra):
        return subprocess.run([sys.executable, SCRIPT, f"--history={d}/history.csv", f"--joints={d}/joints.csv", f"--frames={d}/frames",
                               f"--out-dir={d}/out", *extra], capture_output=True, text=True)

    def test_animation_and_plots(self):
        with tempfile.TemporaryDirectory() as d:
            inputs(d)
            r = self.run_script(d)
            self.assertEqual(r.returncode, 0, r.stderr)
            out = os.path.join(d, "out")
            self.assertEqual(sorted(os.listdir(out)), ["energy.png", "joint-energy.png", "wrecking-ball.gif"])
            with Image.open(os.path.join(out, "wrecking-ball.gif")) as gif:
                self.assertEqual(gif.n_frames, 4)
            with Image.open(os.path.join(out, "energy.png")) as im:
                self.assertGreater(im.size[0], 400)

    def test_bad_input_is_refused(self):
        with tempfile.TemporaryDirectory() as d:
            inputs(d)
            r = self.run_script(d, "--fps=0")
            self.assertNotEqual(r.returncode, 0)
            self.assertIn("--fps: 0.0 is not in [0.5, 100]", r.stderr)
            with open(os.path.join(d, "joints.csv"), "w") as f:
                f.write("joint,broken\nbase-left,1\n")
            r = self.run_script(d)
            self.assertNotEqual(r.returncode, 0)
            self.assertIn("lacks the columns booked_work_J", r.stderr)
            self.assertFalse(os.path.exists(os.path.join(d, "out", "wrecking-ball.gif")))

class ShownJointsTest(unittest.TestCase):
    def test_a_building_shows_the_joints_that_yielded(self):
        sys.path.insert(0, os.path.dirname(SCRIPT))
        import game_pictures

        few = [{"joint": "j%d" % i, "booked_work_J": str(i)} for i in range(10)]
        self.assertEqual(game_pictures.shown_joints(few), few)
        many = [{"joint": "j%d" % i, "booked_work_J": "0"} for i in range(200)]
        many[3]["booked_work_J"] = "1000"
        many[150]["booked_work_J"] = "10"
        many[151]["booked_work_J"] = "9.99"
        self.assertEqual([r["joint"] for r in game_pictures.shown_joints(many)], ["j3", "j150"])
        idle = [{"joint": "j%d" % i, "booked_work_J": "0"} for i in range(200)]
        self.assertEqual(len(game_pictures.shown_joints(idle)), game_pictures.MAX_JOINTS_SHOWN)



if __name__ == "__main__":
    unittest.main()
