#!/usr/bin/env python3
"""The OpenSees peer of the cantilever pushover (issue 23): a steel cantilever with a fibre section in OpenSees
(openseespy), pushed at its tip to given drifts, as an independent reference for the project's plastic joints.

  bash ci/opensees_env.sh python3 ci/models/opensees_cantilever.py [--length-m 2.0] [--width-m 0.05] [--depth-m 0.10]
        [--youngs-modulus-pa 200e9] [--yield-stress-pa 400e6] [--hardening-ratio 0.01] [--material steel01|steel02]
        [--drifts 0.05,0.10 | --cyclic-drifts 0.05,-0.05,0.05] [--geometry corotational|linear]
        [--elements 8] [--integration-points 5] [--fibres 100] [--step-m 0.001] [--format json|markdown]

The model: the member along +x from a fixed support at x = 0 to the tip at x = L, in the x-y plane (ndm 2, ndf 3),
bending about z; the section's width is along z, its depth along y. The tip load is a reference load of 1 N along -y
fixed in the world (a dead load, not a follower), and the analysis is displacement controlled: the tip's y
displacement is driven to -drift x L, so the load factor of the pattern is the tip force P in newtons. P is read
from the domain's pseudo time (getTime(), which DisplacementControl sets to the load factor) and checked against the
support's reaction (reactions() + nodeReaction); the root moment is the support's moment reaction, which equals
P (L + u_x,tip) under corotational geometry and P L under linear geometry.

  load_ratio        = P L / Mp, with Mp = fy W_pl (rectangle: W_pl = b d^2 / 4; the bilinear material's first yield
                      is at fy, so Mp is the plastic moment of the section at that stress)
  root_moment_ratio = M_root / Mp

Signs in the output follow the project's (demos/structures): positive drift, deflection, tip force and moments when
the tip goes down (-y); rotations are positive when the tip goes down (-theta_z).

The material: Steel01 (bilinear, kinematic hardening: E, fy, b = --hardening-ratio), or Steel02 (Giuffre-Menegotto-
Pinto, R0 20, cR1 0.925, cR2 0.15, the same E, fy, b; its monotonic curve rounds the corner, so its Mp is approached,
not reached at first yield). The section: fibres (layers across the depth, each with its area and its centroid's y;
an even count gives the rectangle's W_pl exactly and b d^3 / 12 (1 - 1 / n^2) for I).

The elements: forceBeamColumn (force-based, Gauss-Lobatto integration). Its moment field is the exact equilibrium one
(linear along each element under a tip load, and the section moment at the root integration point is the support's
moment), so a few elements follow the spread of plasticity and converge fast: measured on the 2 m, 50 x 100 mm case
at hardening 0.01 and 10 % drift, corotational, P L / Mp = 1.09379 / 1.09468 / 1.09480 at 4 / 8 / 16 elements of 5
points, while dispBeamColumn (linear curvature in each element, equilibrium only in the weak sense) gave 1.1092 /
1.0941 / 1.0949 and its end moments overshoot the section's (up to 1.04 Mp on an elastic-perfectly plastic
section). --element disp switches to dispBeamColumn for comparison.
An elastic-perfectly plastic section of finitely many fibres has no stiffness once its last fibre yields (at
n kappa_y for n fibres), which a force-based element cannot invert: use a hardening ratio of 1e-6 or more for
elastic-perfectly plastic runs, not 0.

--cyclic-drifts D1,D2,...: the tip is driven through 0 -> D1 L -> D2 L -> ..., and every step's tip deflection, tip
force, root moment, root curvature (the root integration point's), tip rotation and root rotation (the rotation of
the node at --root-rotation-at-m, by default the end of the first element) are printed as arrays.

openseespylinux's wheel carries its own libblas.so.3 but its liblapack.so.3 does not find it without Debian's
libblas3; load_opensees() loads the wheel's copy first, so no system package is needed.
"""
import argparse
import ctypes
import importlib.util
import json
import math
import os
import sys
import time

OPENSEESPY_VERSION = "3.7.1.2"  # ci/opensees_env.sh installs it


def load_opensees():
    """openseespy.opensees, with the wheel's libblas.so.3 loaded first when the system has none."""
    spec = importlib.util.find_spec("openseespylinux")
    if spec is not None and spec.origin:
        blas = os.path.join(os.path.dirname(spec.origin), "lib", "libblas.so.3")
        if os.path.exists(blas):
            ctypes.CDLL(blas, mode=ctypes.RTLD_GLOBAL)
    import openseespy.opensees as ops
    return ops


def openseespy_version():
    from importlib import metadata
    try:
        return metadata.version("openseespy")
    except metadata.PackageNotFoundError:
        return None


# ---------------------------------------------------------------------------------------------------------------
# Sections. Each shape gives its closed-form properties and its layers across the depth (the fibres); a new shape
# (tube, round bar, I section, as demos/plastic/SectionResponse.h has them) is a class with the same methods and
# an entry in SECTIONS with its own options.


class Rectangle:
    name = "rectangle"
    options = (("width_m", 0.05, "the section's width along the bending axis z [m]"),
               ("depth_m", 0.10, "the section's depth in the bending plane (along y) [m]"))

    def __init__(self, width_m, depth_m):
        if not (width_m > 0 and depth_m > 0):
            raise ValueError("the rectangle's width and depth must be positive")
        self.width_m, self.depth_m = width_m, depth_m

    def inputs(self):
        return {"section": self.name, "width_m": self.width_m, "depth_m": self.depth_m}

    def depth(self):
        return self.depth_m

    def area(self):
        return self.width_m * self.depth_m

    def second_moment(self):
        return self.width_m * self.depth_m ** 3 / 12.0

    def elastic_modulus(self):
        return self.width_m * self.depth_m ** 2 / 6.0

    def plastic_modulus(self):
        return self.width_m * self.depth_m ** 2 / 4.0

    def layers(self, count):
        """(y of the centroid [m], area [m^2]) of count equal layers across the depth."""
        h = self.depth_m / count
        return [(-self.depth_m / 2 + (i + 0.5) * h, self.width_m * h) for i in range(count)]


SECTIONS = {"rectangle": Rectangle}


def section_from_args(args):
    cls = SECTIONS[args.section]
    return cls(**{name: getattr(args, name) for name, _, _ in cls.options})


def section_properties(section, E, fy, fibres):
    layers = section.layers(fibres)
    I, Wpl, d = section.second_moment(), section.plastic_modulus(), section.depth()
    Mp, My = fy * Wpl, fy * section.elastic_modulus()
    return {
        "area_m2": section.area(), "second_moment_m4": I, "elastic_modulus_m3": section.elastic_modulus(),
        "plastic_modulus_m3": Wpl, "plastic_moment_Nm": Mp, "yield_moment_Nm": My, "shape_factor": Mp / My,
        "yield_curvature_per_m": 2 * fy / (E * d),
        "fibre_second_moment_m4": sum(a * y * y for y, a in layers),
        "fibre_plastic_moment_Nm": fy * sum(a * abs(y) for y, a in layers),
    }


# ---------------------------------------------------------------------------------------------------------------
# The model and the analysis


def analyze_one(ops):
    """One step of the analysis as set up: Newton, else KrylovNewton, else Newton from the initial stiffness. True
    when one of them converged (Newton is the algorithm again after it)."""
    if ops.analyze(1) == 0:
        return True
    for algorithm in (("KrylovNewton",), ("Newton", "-initial")):
        ops.algorithm(*algorithm)
        ok = ops.analyze(1) == 0
        ops.algorithm("Newton")
        if ok:
            return True
    return False


class Cantilever:
    def __init__(self, ops, args, section):
        self.ops, self.args, self.section = ops, args, section
        self.n = args.elements
        self.tip = self.n + 1
        self.L = args.length_m
        self.build()

    def build(self):
        ops, a = self.ops, self.args
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        for i in range(self.n + 1):
            ops.node(i + 1, i * self.L / self.n, 0.0)
        ops.fix(1, 1, 1, 1)
        if a.material == "steel01":
            ops.uniaxialMaterial("Steel01", 1, a.yield_stress_pa, a.youngs_modulus_pa, a.hardening_ratio)
        else:
            ops.uniaxialMaterial("Steel02", 1, a.yield_stress_pa, a.youngs_modulus_pa, a.hardening_ratio, 20.0, 0.925, 0.15)
        ops.section("Fiber", 1)
        for y, area in self.section.layers(a.fibres):
            ops.fiber(y, 0.0, area, 1)
        ops.geomTransf("Corotational" if a.geometry == "corotational" else "Linear", 1)
        ops.beamIntegration("Lobatto", 1, 1, a.integration_points)
        for e in range(self.n):
            if a.element == "force":
                ops.element("forceBeamColumn", e + 1, e + 1, e + 2, 1, 1, "-iter", 50, 1e-12)
            else:
                ops.element("dispBeamColumn", e + 1, e + 1, e + 2, 1, 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(self.tip, 0.0, -1.0, 0.0)  # 1 N along -y: the load factor is the tip force in N
        ops.constraints("Plain")
        ops.numberer("RCM")
        ops.system("BandGeneral")
        ops.test("NormDispIncr", a.tolerance_m, 50)
        ops.algorithm("Newton")
        ops.integrator("DisplacementControl", self.tip, 2, -a.step_m)  # each step sets its own increment
        ops.analysis("Static")
        self.steps = 0
        self.history = []

    def deflection(self):
        return -self.ops.nodeDisp(self.tip, 2)

    def step(self, du, depth=0):
        """One displacement-controlled step of the tip's deflection by du (down positive); on failure, halves and
        tries other algorithms down to 1/64 of the step. False when it cannot."""
        self.ops.integrator("DisplacementControl", self.tip, 2, -du)
        if analyze_one(self.ops):
            self.steps += 1
            self.record()
            return True
        if depth >= 6:
            return False
        return self.step(du / 2, depth + 1) and self.step(du / 2, depth + 1)

    def go_to(self, target_m):
        """Drives the tip's deflection to target_m in equal steps of at most --step-m."""
        remaining = target_m - self.deflection()
        count = max(1, math.ceil(abs(remaining) / self.args.step_m - 1e-9))
        du = remaining / count
        for _ in range(count):
            if not self.step(du):
                return False
        return True

    def state(self):
        ops, L = self.ops, self.L
        ops.reactions()
        P = ops.getTime()  # DisplacementControl: the pseudo time is the load factor, the tip force in N
        reaction = ops.nodeReaction(1, 2)
        root = ops.nodeReaction(1, 3)
        ux, uy, rz = ops.nodeDisp(self.tip)
        curvature = ops.eleResponse(1, "section", 1, "deformation")[1]
        section_moment = ops.eleResponse(1, "section", 1, "force")[1]
        Mp = self.args.plastic_moment_Nm
        return {
            "drift": -uy / L, "tip_deflection_m": -uy, "tip_axial_displacement_m": ux, "tip_rotation_rad": -rz,
            "tip_force_N": P, "reaction_force_N": reaction, "root_moment_Nm": root,
            "load_ratio": P * L / Mp, "root_moment_ratio": root / Mp, "root_curvature_per_m": -curvature,
            "root_section_moment_Nm": -section_moment,
        }

    def record(self):
        if self.args.cyclic_drifts:
            s = self.state()
            s["root_rotation_rad"] = -self.ops.nodeDisp(self.args.root_rotation_node, 3)
            self.history.append(s)


def pushover(ops, args, section):
    model = Cantilever(ops, args, section)
    rows = []
    for drift in args.drifts:
        ok = model.go_to(drift * args.length_m)
        s = model.state()
        check_equilibrium(s)
        s.update(target_drift=drift, converged=ok and element_state_is_compatible(args, s), steps=model.steps)
        rows.append(s)
        if not ok:
            break
    return rows


def cyclic(ops, args, section):
    model = Cantilever(ops, args, section)
    model.record()
    reached = []
    for drift in args.cyclic_drifts:
        ok = model.go_to(drift * args.length_m)
        reached.append({"target_drift": drift, "converged": ok, "step": len(model.history) - 1})
        if not ok:
            break
    keys = ("tip_deflection_m", "tip_force_N", "root_moment_Nm", "root_rotation_rad", "root_curvature_per_m",
            "tip_rotation_rad", "load_ratio", "root_moment_ratio")
    out = {k: [h[k] for h in model.history] for k in keys}
    out["reversals"] = reached
    out["root_rotation_at_m"] = (args.root_rotation_node - 1) * args.length_m / args.elements
    for h in model.history:
        check_equilibrium(h)
    if not all(element_state_is_compatible(args, h) for h in model.history):
        reached.append({"target_drift": None, "converged": False, "step": None,
                        "why": "the root section's moment is not the support's (the element's iterations failed)"})
    return out


def check_equilibrium(s):
    # the load factor and the support's reaction are the same force (to the solver's tolerance)
    if abs(s["tip_force_N"] - s["reaction_force_N"]) > 1e-6 * max(1.0, abs(s["tip_force_N"])):
        raise SystemExit(f"opensees_cantilever.py: load factor {s['tip_force_N']} N and reaction {s['reaction_force_N']} N differ")


def element_state_is_compatible(args, s):
    """forceBeamColumn: the root integration point's section moment is the support's moment. They part when the
    element's own iterations failed and it kept a state that is not in equilibrium, which the global Newton does not
    see (measured: hardening 0, linear geometry, 8 x 5 points, 100 fibres: P L / Mp 1.022 at 20 % drift, 1.066 at
    53 %, while no section can carry more than Mp). dispBeamColumn's section moments are not its end forces."""
    if args.element != "force":
        return True
    return abs(s["root_section_moment_Nm"] - s["root_moment_Nm"]) <= 1e-6 * args.plastic_moment_Nm


# ---------------------------------------------------------------------------------------------------------------


def drift_list(text):
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a comma-separated list of numbers: {text!r}")
    if not values or not all(math.isfinite(v) for v in values):
        raise argparse.ArgumentTypeError(f"not a list of finite numbers: {text!r}")
    return values


def parser():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--length-m", type=float, default=2.0, help="the cantilever's length L [m] (default 2.0)")
    p.add_argument("--section", choices=sorted(SECTIONS), default="rectangle", help="the section's shape")
    for cls in SECTIONS.values():
        for name, default, text in cls.options:
            p.add_argument("--" + name.replace("_", "-"), type=float, default=default, help=f"{cls.name}: {text} (default {default})")
    p.add_argument("--youngs-modulus-pa", type=float, default=200e9, help="E [Pa] (default 200e9)")
    p.add_argument("--yield-stress-pa", type=float, default=400e6, help="fy [Pa] (default 400e6)")
    p.add_argument("--hardening-ratio", type=float, default=0.01, help="the hardening modulus over E, b (default 0.01)")
    p.add_argument("--material", choices=("steel01", "steel02"), default="steel01")
    p.add_argument("--drifts", type=drift_list, default=[0.05, 0.10],
                   help="tip deflections over L to report, pushed in this order (default 0.05,0.10)")
    p.add_argument("--cyclic-drifts", type=drift_list, default=None,
                   help="a tip deflection history over L (e.g. 0.05,-0.05,0.05): prints every step's response as arrays")
    p.add_argument("--geometry", choices=("corotational", "linear"), default="corotational")
    p.add_argument("--element", choices=("force", "disp"), default="force", help="forceBeamColumn (default) or dispBeamColumn")
    p.add_argument("--elements", type=int, default=8, help="elements along the length (default 8)")
    p.add_argument("--integration-points", type=int, default=5, help="Gauss-Lobatto points per element (default 5)")
    p.add_argument("--fibres", type=int, default=100, help="layers across the depth (default 100)")
    p.add_argument("--step-m", type=float, default=0.001, help="the largest step of the tip's deflection [m] (default 0.001)")
    p.add_argument("--tolerance-m", type=float, default=1e-10, help="NormDispIncr's tolerance [m and rad] (default 1e-10)")
    p.add_argument("--root-rotation-at-m", type=float, default=None,
                   help="cyclic: the rotation reported as the root's is the node's nearest this x [m] (default: the first element's end)")
    p.add_argument("--format", choices=("json", "markdown"), default="json")
    return p


def check_args(p, args):
    if args.length_m <= 0:
        p.error("--length-m must be positive")
    if args.youngs_modulus_pa <= 0 or args.yield_stress_pa <= 0:
        p.error("--youngs-modulus-pa and --yield-stress-pa must be positive")
    if not 0 <= args.hardening_ratio < 1:
        p.error("--hardening-ratio must be in [0, 1)")
    if args.elements < 1 or args.integration_points < 3 or args.fibres < 2:
        p.error("--elements >= 1, --integration-points >= 3 (Gauss-Lobatto), --fibres >= 2")
    if not args.step_m > 0 or not args.tolerance_m > 0:
        p.error("--step-m and --tolerance-m must be positive")
    if any(d <= 0 for d in args.drifts) or any(b <= a for a, b in zip(args.drifts, args.drifts[1:])):
        p.error("--drifts must be positive and increasing (a monotonic pushover)")
    x = args.length_m / args.elements if args.root_rotation_at_m is None else args.root_rotation_at_m
    if not 0 <= x <= args.length_m:
        p.error("--root-rotation-at-m must be within the length")
    args.root_rotation_node = 1 + round(x / args.length_m * args.elements)


def markdown(result):
    i = result["inputs"]
    lines = [f"OpenSees {result['openseespy_version']}: {i['section']} {i['width_m'] * 1e3:g} x {i['depth_m'] * 1e3:g} mm, "
             f"L {i['length_m']:g} m, E {i['youngs_modulus_pa'] / 1e9:g} GPa, fy {i['yield_stress_pa'] / 1e6:g} MPa, "
             f"{i['material']} b {i['hardening_ratio']:g}, {i['geometry']}, {i['elements']} x {i['integration_points']} "
             f"{i['element']}BeamColumn, {i['fibres']} fibres",
             "",
             "| drift | tip deflection m | P N | P L / Mp | M_root / Mp | tip u_x m |",
             "| ---: | ---: | ---: | ---: | ---: | ---: |"]
    for r in result["pushover"]:
        lines.append(f"| {r['target_drift']:g} | {r['tip_deflection_m']:.5f} | {r['tip_force_N']:.1f} | {r['load_ratio']:.4f} "
                     f"| {r['root_moment_ratio']:.4f} | {round(r['tip_axial_displacement_m'], 5) + 0.0:.5f} |")
    return "\n".join(lines)


def run(argv=None):
    """The analysis of a command line: (the result as main prints it, the parsed arguments)."""
    p = parser()
    args = p.parse_args(argv)
    check_args(p, args)
    try:
        section = section_from_args(args)
    except ValueError as e:
        p.error(str(e))
    ops = load_opensees()
    props = section_properties(section, args.youngs_modulus_pa, args.yield_stress_pa, args.fibres)
    args.plastic_moment_Nm = props["plastic_moment_Nm"]
    I, L = props["second_moment_m4"], args.length_m
    props["yield_tip_deflection_m"] = props["yield_moment_Nm"] * L ** 2 / (3 * args.youngs_modulus_pa * I)
    props["yield_drift"] = props["yield_tip_deflection_m"] / L
    props["elastic_tip_stiffness_N_per_m"] = 3 * args.youngs_modulus_pa * I / L ** 3
    inputs = {"length_m": L, **section.inputs(), "youngs_modulus_pa": args.youngs_modulus_pa,
              "yield_stress_pa": args.yield_stress_pa, "hardening_ratio": args.hardening_ratio, "material": args.material,
              "geometry": args.geometry, "element": args.element, "elements": args.elements,
              "integration_points": args.integration_points, "fibres": args.fibres, "step_m": args.step_m,
              "tolerance_m": args.tolerance_m}
    started = time.perf_counter()
    result = {"peer": "opensees", "openseespy_version": openseespy_version(), "opensees_version": ops.version(),
              "inputs": inputs, "section": props}
    if args.cyclic_drifts:
        inputs["cyclic_drifts"] = args.cyclic_drifts
        result["cyclic"] = cyclic(ops, args, section)
        ok = all(r["converged"] for r in result["cyclic"]["reversals"])
        ok = ok and len(result["cyclic"]["reversals"]) == len(args.cyclic_drifts)
    else:
        inputs["drifts"] = args.drifts
        result["pushover"] = pushover(ops, args, section)
        ok = all(r["converged"] for r in result["pushover"]) and len(result["pushover"]) == len(args.drifts)
    result["converged"] = ok
    result["wall_s"] = time.perf_counter() - started
    ops.wipe()
    return result, args


def main(argv=None):
    result, args = run(argv)
    if args.format == "markdown" and not args.cyclic_drifts:
        print(markdown(result))
    else:
        print(json.dumps(result, indent=1 if not args.cyclic_drifts else None))
    sys.stdout.flush()
    if not result["converged"]:
        print("opensees_cantilever.py: the analysis did not converge (see converged in the output)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
