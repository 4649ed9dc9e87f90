"""The OpenSees portal peer (ci/models/opensees_portal.py, issue 23's large displacements) against closed forms: the elastic
sway stiffness of a fixed-base portal by slope-deflection, its fall under the knee loads (P-Delta), and the sway
mechanism's second-order load at a large drift. Run through ci/opensees_env.sh, which exits 77 (skip) only when
openseespy cannot be installed; run by another python without openseespy, this file exits 77 too.

  bash ci/opensees_env.sh python3 tests/peer/test_opensees_portal.py

About 3 s.
"""
import math
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CI = os.path.join(HERE, "..", "..", "ci", "models")
sys.path.insert(0, CI)
sys.path.insert(1, os.path.dirname(CI))  # ci/: the sweep and report tools
import opensees_portal as op  # noqa: E402

# the project's portal (demos/structures/Portal.h): 4 m x 3 m, 50 x 100 mm steel, E 200 GPa, fy 400 MPa
L, H, W, D, E, FY = 4.0, 3.0, 0.05, 0.10, 200e9, 400e6
EI = E * W * D ** 3 / 12
MP = FY * W * D ** 2 / 4


def sway_stiffness(knee_load_n):
    out = op.run(["--knee-load-n", repr(knee_load_n), "--drifts", "0.0005,0.001", "--step-m", "0.0005"])
    a, b = out["pushover"]
    return (b["H_N"] - a["H_N"]) / ((b["drift"] - a["drift"]) * H)


class PortalPeer(unittest.TestCase):
    def test_elastic_sway_stiffness_is_slope_deflections(self):
        # slope-deflection, antisymmetric sway psi, knee rotation t, k = (I/L) / (I/h): joint equilibrium
        # 4 t - 6 psi + 6 k t = 0, storey shear H = (4 EI / h^2)(6 psi - 3 t) -> K = (4 EI / h^3)(6 - 18 / (4 + 6 k))
        k = H / L
        closed = 4 * EI / H ** 3 * (6 - 18 / (4 + 6 * k))
        self.assertAlmostEqual(sway_stiffness(0.0) / closed, 1.0, delta=0.005)

    def test_knee_loads_take_p_over_h_off_the_stiffness(self):
        # a frame of straight columns loses 2 P / h; the columns' own bowing (P-delta) takes a little more
        drop = sway_stiffness(0.0) - sway_stiffness(100e3)
        self.assertGreater(drop, 2 * 100e3 / H)
        self.assertLess(drop, 1.2 * 2 * 100e3 / H)

    def test_the_mechanism_carries_the_second_order_load(self):
        out = op.run(["--knee-load-n", "100e3", "--drifts", "0.2"])
        row = out["pushover"][0]
        self.assertTrue(row["converged"])
        d = row["drift"]
        second_order = (4 * MP - 2 * 100e3 * H * d) / (4 * MP * math.sqrt(1 - d * d))
        self.assertAlmostEqual(row["load_ratio"] / second_order, 1.0, delta=0.01)
        self.assertLess(row["load_ratio"], 0.5)  # a first-order analysis says 1
        # the knees went down as the columns turned, h (1 - cos theta) (less their elastic shortening)
        self.assertAlmostEqual(row["knee_descent_m"], H * (1 - math.sqrt(1 - d * d)), delta=0.002)

    def test_bad_arguments_are_named(self):
        done = subprocess.run([sys.executable, os.path.join(CI, "opensees_portal.py"), "--drifts", "0.2,0.1"], capture_output=True, text=True)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("--drifts: increasing drifts in (0, 0.5)", done.stderr)


if __name__ == "__main__":
    try:
        op.oc.load_opensees()
    except ImportError as e:
        print("openseespy: %s" % e, file=sys.stderr)
        sys.exit(77)
    unittest.main()
