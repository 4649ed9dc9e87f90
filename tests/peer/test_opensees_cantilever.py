"""The OpenSees peer (ci/models/opensees_cantilever.py): its cantilever pushover against closed forms under linear geometry
(elastic, elastic-perfectly plastic, bilinear), its mesh convergence at the drifts the project compares, its cyclic
mode and its command line. Run through ci/opensees_env.sh (the pinned openseespy in a venv), which exits 77 (skip)
only when openseespy cannot be installed; run by another python without openseespy, this file exits 77 too.

  bash ci/opensees_env.sh python3 tests/peer/test_opensees_cantilever.py

About 10 s.
"""
import json
import math
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CI = os.path.join(HERE, "..", "..", "ci", "models")
sys.path.insert(0, CI)
sys.path.insert(1, os.path.dirname(CI))  # ci/: the sweep and report tools
import opensees_cantilever as oc  # noqa: E402

SCRIPT = os.path.join(CI, "opensees_cantilever.py")
# the project's cantilever (demos/structures/Cantilever.h): 2 m, 50 mm wide (along z), 100 mm deep, E 200 GPa, fy 400 MPa
L, W, D, E, FY = 2.0, 0.05, 0.10, 200e9, 400e6
I = W * D ** 3 / 12
MP = FY * W * D ** 2 / 4
MY = MP / 1.5
KAPPA_Y = 2 * FY / (E * D)
DELTA_Y = KAPPA_Y * L ** 2 / 3  # tip deflection at first yield (linear geometry): 0.0533 m, drift 2.67 %
EPP = "1e-6"  # Steel01 at b = 0 leaves a section with no stiffness once its last fibre yields (see ElasticPlasticTest)


def run(*args):
    result, _ = oc.run(["--length-m", str(L), "--width-m", str(W), "--depth-m", str(D), "--youngs-modulus-pa", str(E),
                        "--yield-stress-pa", str(FY), *args])
    return result


def ratios(result):
    return [r["load_ratio"] for r in result["pushover"]]


# ---------------------------------------------------------------------------------------------------------------
# Closed forms of the cantilever under a tip load P, linear geometry: the root moment M0 = P L, the moment
# M(s) = P s at s from the tip, and the tip deflection delta = int_0^L kappa(M(s)) s ds = (1 / P^2) int_0^M0 kappa(M) M dM.


def epp_deflection(m):
    """Elastic-perfectly plastic rectangle, M0 = m Mp: kappa = kappa_y M / My up to My = Mp / 1.5, and
    kappa_y / sqrt(3 (1 - M / Mp)) above (from M = Mp (1 - (kappa_y / kappa)^2 / 3)). With u = 1 - M / Mp,
    int_My^M0 kappa M dM = kappa_y Mp^2 / sqrt(3) [F(1/3) - F(1 - m)], F(u) = 2 sqrt(u) - 2/3 u^(3/2), so
    delta = L^2 kappa_y / m^2 [(2/3)^2 / 3 + (F(1/3) - F(1 - m)) / sqrt(3)] for m > 2/3, m / (2/3) delta_y below;
    at m = 1 it is 20/9 delta_y: the root hinge forms at a finite deflection, and M0 stays Mp beyond it."""
    def F(u):
        return 2 * math.sqrt(u) - 2 / 3 * u ** 1.5
    if m <= 2 / 3:
        return m / (2 / 3) * DELTA_Y
    return L ** 2 * KAPPA_Y / m ** 2 * ((2 / 3) ** 2 / 3 + (F(1 / 3) - F(1 - m)) / math.sqrt(3))


def epp_load_ratio(delta):
    if delta >= epp_deflection(1.0):
        return 1.0
    lo, hi = 0.0, 1.0
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if epp_deflection(mid) < delta else (lo, mid)
    return lo


def bilinear_load_ratio(delta, b):
    """Bilinear rectangle (hardening modulus b E), from the root curvature k0 instead: by parts,
    delta = L^2 [k0 / 2 - int_0^k0 M(k)^2 dk / (2 M(k0)^2)]. Above kappa_y, with the elastic core c = h kappa_y / k
    (h = d / 2), M = Mp (1 - (kappa_y / k)^2 / 3) + 2 w b E k (h^3 / 3 - c h^2 / 2 + c^3 / 6) = A + B k + C / k^2,
    whose square integrates in closed form. b = 0 is the elastic-perfectly plastic rectangle again."""
    h, H = D / 2, b * E
    A = MP - W * H * KAPPA_Y * h ** 3
    B = 2 * W * H * h ** 3 / 3
    C = -MP * KAPPA_Y ** 2 / 3 + W * H * KAPPA_Y ** 3 * h ** 3 / 3

    def moment(k):
        return E * I * k if k <= KAPPA_Y else A + B * k + C / k ** 2

    def G(k):  # int M^2 dk
        return (A * A * k + B * B * k ** 3 / 3 - C * C / (3 * k ** 3) + A * B * k * k - 2 * A * C / k
                + 2 * B * C * math.log(k))

    def deflection(k0):
        if k0 <= KAPPA_Y:
            return k0 * L ** 2 / 3
        return L ** 2 * (k0 / 2 - (MY ** 2 * KAPPA_Y / 3 + G(k0) - G(KAPPA_Y)) / (2 * moment(k0) ** 2))

    lo, hi = 0.0, KAPPA_Y
    while deflection(hi) < delta:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if deflection(mid) < delta else (lo, mid)
    return moment(lo) / MP


class ClosedFormTest(unittest.TestCase):
    def test_the_two_closed_forms_agree(self):
        for drift in (0.02, 0.03, 0.04, 0.05, 0.055):
            self.assertAlmostEqual(bilinear_load_ratio(drift * L, 0.0), epp_load_ratio(drift * L), places=6)
        self.assertAlmostEqual(epp_deflection(1.0) / DELTA_Y, 20 / 9, places=12)
        self.assertAlmostEqual(epp_load_ratio(0.05 * L), 0.98679, places=5)


class ElasticTest(unittest.TestCase):
    def test_tip_force_is_3_e_i_delta_over_l_cubed(self):
        # 0.5 % drift (a fifth of the first yield's); fibres: I (1 - 1/n^2), 1e-4 low at 100 fibres
        for geometry in ("linear", "corotational"):
            r = run("--hardening-ratio", "0.01", "--geometry", geometry, "--drifts", "0.0025,0.005")["pushover"]
            for row in r:
                expected = 3 * E * I * row["tip_deflection_m"] / L ** 3
                self.assertLess(abs(row["tip_force_N"] / expected - 1), 0.005, (geometry, row))
                self.assertAlmostEqual(row["tip_force_N"], row["reaction_force_N"], delta=1e-6 * row["tip_force_N"])


class ElasticPlasticTest(unittest.TestCase):
    """Steel01 at b = 1e-6, linear geometry, against epp_load_ratio."""

    def test_moderate_drifts_follow_the_closed_form(self):
        drifts = (0.03, 0.04, 0.05, 0.055)  # 1.1 - 2.1 delta_y
        r = run("--hardening-ratio", EPP, "--geometry", "linear", "--drifts", ",".join(map(str, drifts)))
        self.assertTrue(r["converged"])
        for drift, row in zip(drifts, r["pushover"]):
            expected = epp_load_ratio(drift * L)
            self.assertLess(abs(row["load_ratio"] / expected - 1), 0.01, (drift, expected, row))
            self.assertLess(row["load_ratio"], 1.0)
            self.assertAlmostEqual(row["root_moment_ratio"], row["load_ratio"], places=9)  # linear geometry: M = P L

    def test_tends_to_mp_over_l(self):
        # past 20/9 delta_y the closed form is Mp / L; the fibres' 1e-6 hardening lifts it by < 0.1 % at 20 delta_y
        r = run("--hardening-ratio", EPP, "--geometry", "linear", "--drifts", f"0.05,0.1,{20 * DELTA_Y / L}", "--step-m", "0.004")
        self.assertTrue(r["converged"])
        last = r["pushover"][-1]
        self.assertAlmostEqual(last["tip_deflection_m"] / DELTA_Y, 20.0, places=9)
        self.assertGreater(last["load_ratio"], 0.97)
        self.assertLess(abs(last["load_ratio"] - 1), 0.002, last)
        self.assertLess(r["pushover"][0]["load_ratio"], last["load_ratio"])

    def test_no_hardening_is_told_when_the_element_state_breaks(self):
        # b = 0: the root section has no stiffness once its last fibre yields; forceBeamColumn then keeps a state
        # whose end moment exceeds the section's (P L / Mp 1.02 at 20 % drift): the run says it did not converge
        r = run("--hardening-ratio", "0", "--geometry", "linear", "--drifts", "0.05,0.2", "--step-m", "0.004")
        self.assertTrue(r["pushover"][0]["converged"])
        self.assertFalse(r["pushover"][1]["converged"])
        self.assertFalse(r["converged"])


class BilinearTest(unittest.TestCase):
    def test_the_projects_hardening_ratios_follow_the_closed_form(self):
        for b in (0.01, 0.05):
            r = run("--hardening-ratio", str(b), "--geometry", "linear", "--drifts", "0.05,0.10")
            for row in r["pushover"]:
                expected = bilinear_load_ratio(row["tip_deflection_m"], b)
                self.assertLess(abs(row["load_ratio"] / expected - 1), 0.005, (b, expected, row))

    def test_corotational_geometry_lifts_the_load_and_shortens_the_arm(self):
        lin = run("--hardening-ratio", "0.01", "--geometry", "linear")["pushover"]
        cor = run("--hardening-ratio", "0.01", "--geometry", "corotational")["pushover"]
        for a, c in zip(lin, cor):
            self.assertGreater(c["load_ratio"], a["load_ratio"])
            self.assertLess(c["tip_axial_displacement_m"], 0)
            # the support's moment is P times the deformed arm L + u_x
            self.assertAlmostEqual(c["root_moment_Nm"], c["tip_force_N"] * (L + c["tip_axial_displacement_m"]),
                                   delta=1e-6 * c["root_moment_Nm"])


class MeshTest(unittest.TestCase):
    def test_twice_as_fine_moves_the_load_ratio_by_less_than_half_a_percent(self):
        # the defaults (8 elements x 5 Lobatto points, 100 fibres, 1 mm steps) against 16 x 5, 200 fibres, 0.5 mm
        for b in ("0.01", "0.05"):
            for geometry in ("corotational", "linear"):
                base = ratios(run("--hardening-ratio", b, "--geometry", geometry))
                fine = ratios(run("--hardening-ratio", b, "--geometry", geometry, "--elements", "16", "--fibres", "200",
                                  "--step-m", "0.0005"))
                more_points = ratios(run("--hardening-ratio", b, "--geometry", geometry, "--integration-points", "10"))
                for x, y, z in zip(base, fine, more_points):
                    self.assertLess(abs(y / x - 1), 0.005, (b, geometry, base, fine))
                    self.assertLess(abs(z / x - 1), 0.005, (b, geometry, base, more_points))


class CyclicTest(unittest.TestCase):
    def test_a_cycle_has_a_loop(self):
        r = run("--hardening-ratio", "0.01", "--geometry", "linear", "--cyclic-drifts", "0.05,-0.05,0.05")
        self.assertTrue(r["converged"])
        c = r["cyclic"]
        n = len(c["tip_deflection_m"])
        for key in ("tip_force_N", "root_moment_Nm", "root_rotation_rad", "root_curvature_per_m", "tip_rotation_rad"):
            self.assertEqual(len(c[key]), n, key)
        self.assertEqual(c["tip_deflection_m"][0], 0.0)
        for rev in c["reversals"]:
            self.assertAlmostEqual(c["tip_deflection_m"][rev["step"]], rev["target_drift"] * L, places=9)
        self.assertEqual(c["root_rotation_at_m"], L / 8)
        # linear geometry: the root moment is P L at every step
        for p, m in zip(c["tip_force_N"], c["root_moment_Nm"]):
            self.assertAlmostEqual(m, p * L, delta=1e-6 * MP)
        # unloading from the first peak starts at the elastic stiffness 3 E I / L^3
        k = c["reversals"][0]["step"]
        slope = (c["tip_force_N"][k + 1] - c["tip_force_N"][k]) / (c["tip_deflection_m"][k + 1] - c["tip_deflection_m"][k])
        self.assertLess(abs(slope / (3 * E * I / L ** 3) - 1), 0.005)
        # the loop dissipates: the work of the tip force over the closed cycle (from the first peak back to it) is positive
        j = c["reversals"][2]["step"]
        work = sum((c["tip_force_N"][i] + c["tip_force_N"][i + 1]) / 2 * (c["tip_deflection_m"][i + 1] - c["tip_deflection_m"][i])
                   for i in range(k, j))
        self.assertGreater(work, 0.1 * MP * DELTA_Y / L)
        # the pushover's peak is the first reversal's
        push = run("--hardening-ratio", "0.01", "--geometry", "linear", "--drifts", "0.05")["pushover"][0]
        self.assertAlmostEqual(c["tip_force_N"][k], push["tip_force_N"], delta=1e-6 * push["tip_force_N"])


class CommandLineTest(unittest.TestCase):
    def cli(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True, timeout=120)

    def test_json_names_the_inputs_and_the_pinned_version(self):
        done = self.cli("--hardening-ratio", "0.05", "--drifts", "0.05,0.10")
        self.assertEqual(done.returncode, 0, done.stderr)
        out = json.loads(done.stdout)
        self.assertEqual(out["openseespy_version"], oc.OPENSEESPY_VERSION)
        self.assertEqual(out["inputs"]["hardening_ratio"], 0.05)
        self.assertEqual(out["inputs"]["geometry"], "corotational")
        self.assertAlmostEqual(out["section"]["plastic_moment_Nm"], MP, places=6)
        self.assertAlmostEqual(out["section"]["fibre_plastic_moment_Nm"], MP, places=6)
        self.assertEqual([r["target_drift"] for r in out["pushover"]], [0.05, 0.10])
        for row in out["pushover"]:
            self.assertAlmostEqual(row["load_ratio"], row["tip_force_N"] * L / MP, places=12)

    def test_markdown_and_bad_input(self):
        done = self.cli("--format", "markdown", "--drifts", "0.05")
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("| 0.05 | 0.10000 |", done.stdout)
        for bad in (["--drifts", "0.1,0.05"], ["--drifts", "x"], ["--hardening-ratio", "-0.1"], ["--section", "tube"],
                    ["--integration-points", "2"]):
            done = self.cli(*bad)
            self.assertEqual(done.returncode, 2, bad)


if __name__ == "__main__":
    try:
        oc.load_opensees()
    except (ImportError, RuntimeError, OSError) as e:
        print(f"test_opensees_cantilever.py: openseespy does not import ({e}): skipped (run it through ci/opensees_env.sh)",
              file=sys.stderr)
        sys.exit(77)
    unittest.main(verbosity=2)
