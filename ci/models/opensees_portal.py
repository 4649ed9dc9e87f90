#!/usr/bin/env python3
"""The OpenSees peer of the portal's sway pushover under gravity (issue 23, large displacements): a fixed-base steel
portal frame with fibre sections in OpenSees (openseespy), corotational, the knees loaded down and then the left knee
pushed along x to given drifts.

  bash ci/opensees_env.sh python3 ci/models/opensees_portal.py --knee-load-n 100e3 --drifts 0.05,0.1,0.2
        [--span-m 4] [--height-m 3] [--width-m 0.05] [--depth-m 0.10] [--youngs-modulus-pa 200e9]
        [--yield-stress-pa 400e6] [--hardening-ratio 1e-6] [--elements 4] [--fibres 100] [--step-m 0.002]

The model (ndm 2, ndf 3): columns from (0, 0) and (L, 0) up to the knees at height h, the beam between the knees, each
member in --elements forceBeamColumn elements of 5 Gauss-Lobatto points on a fibre rectangle of Steel01 (E, fy,
b = --hardening-ratio: elastic-perfectly plastic at 1e-6, as ci/models/opensees_cantilever.py explains), corotational
geometry, both bases fixed. Gravity: --knee-load-n down at each knee in ten load-controlled steps, then held
(loadConst). Sway: a reference load of 1 N along +x at the left knee, displacement controlled, so the load factor is H
in newtons. Printed as JSON: H h / (4 Mp) (Mp = fy b d^2 / 4) at each drift (the left knee's x displacement / h),
with the knees' descent and the base shear checked against H.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import opensees_cantilever as oc  # noqa: E402


def parser():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--span-m", type=float, default=4.0)
    p.add_argument("--height-m", type=float, default=3.0)
    p.add_argument("--width-m", type=float, default=0.05)
    p.add_argument("--depth-m", type=float, default=0.10)
    p.add_argument("--youngs-modulus-pa", type=float, default=200e9)
    p.add_argument("--yield-stress-pa", type=float, default=400e6)
    p.add_argument("--hardening-ratio", type=float, default=1e-6)
    p.add_argument("--knee-load-n", type=float, default=0.0)
    p.add_argument("--drifts", type=oc.drift_list, default=[0.05, 0.10, 0.20])
    p.add_argument("--elements", type=int, default=4)
    p.add_argument("--fibres", type=int, default=100)
    p.add_argument("--step-m", type=float, default=0.002)
    return p


def check(args):
    for name, value, low, high in (("--span-m", args.span_m, 0.1, 100), ("--height-m", args.height_m, 0.1, 100),
                                   ("--width-m", args.width_m, 1e-4, 10), ("--depth-m", args.depth_m, 1e-4, 10),
                                   ("--hardening-ratio", args.hardening_ratio, 1e-6, 0.5), ("--knee-load-n", args.knee_load_n, 0, 1e12),
                                   ("--elements", args.elements, 1, 100), ("--fibres", args.fibres, 2, 1000), ("--step-m", args.step_m, 1e-6, 1)):
        if not (low <= value <= high):
            raise SystemExit("opensees_portal.py: %s: %r is not in [%g, %g]" % (name, value, low, high))
    if any(d <= 0 or d >= 0.5 for d in args.drifts) or sorted(args.drifts) != args.drifts:
        raise SystemExit("opensees_portal.py: --drifts: increasing drifts in (0, 0.5), not %r" % (args.drifts,))


def build(ops, a):
    L, h, n = a.span_m, a.height_m, a.elements
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    nodes = {}

    def node(x, y):
        key = (round(x, 9), round(y, 9))
        if key not in nodes:
            nodes[key] = len(nodes) + 1
            ops.node(nodes[key], x, y)
        return nodes[key]

    members = [((0, 0), (0, h)), ((0, h), (L, h)), ((L, h), (L, 0))]
    ops.uniaxialMaterial("Steel01", 1, a.yield_stress_pa, a.youngs_modulus_pa, a.hardening_ratio)
    ops.section("Fiber", 1)
    for y, area in oc.Rectangle(a.width_m, a.depth_m).layers(a.fibres):
        ops.fiber(y, 0.0, area, 1)
    ops.geomTransf("Corotational", 1)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    element = 0
    for (x0, y0), (x1, y1) in members:
        for i in range(n):
            a_ = node(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * i / n)
            b_ = node(x0 + (x1 - x0) * (i + 1) / n, y0 + (y1 - y0) * (i + 1) / n)
            element += 1
            ops.element("forceBeamColumn", element, a_, b_, 1, 1, "-iter", 50, 1e-12)
    bases = (nodes[(0, 0)], nodes[(round(L, 9), 0)])
    for b in bases:
        ops.fix(b, 1, 1, 1)
    return nodes[(0, round(h, 9))], nodes[(round(L, 9), round(h, 9))], bases


def analysis(ops, integrator):
    ops.wipeAnalysis()
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm("Newton")
    ops.integrator(*integrator)
    ops.analysis("Static")


def step(ops, knee, du, depth=0):
    ops.integrator("DisplacementControl", knee, 1, du)
    if oc.analyze_one(ops):
        return True
    if depth >= 6:
        return False
    return step(ops, knee, du / 2, depth + 1) and step(ops, knee, du / 2, depth + 1)


def run(argv=None):
    a = parser().parse_args(argv)
    check(a)
    ops = oc.load_opensees()
    left, right, bases = build(ops, a)
    mp = a.yield_stress_pa * a.width_m * a.depth_m ** 2 / 4
    # gravity: the knees' loads in ten steps, then held
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for knee in (left, right):
        ops.load(knee, 0.0, -a.knee_load_n, 0.0)
    analysis(ops, ("LoadControl", 0.1))
    if ops.analyze(10) != 0:
        raise SystemExit("opensees_portal.py: the knee loads did not converge")
    ops.loadConst("-time", 0.0)
    # sway: 1 N along x at the left knee, displacement controlled
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(left, 1.0, 0.0, 0.0)
    analysis(ops, ("DisplacementControl", left, 1, a.step_m))
    rows = []
    for drift in a.drifts:
        remaining = drift * a.height_m - ops.nodeDisp(left, 1)
        count = max(1, math.ceil(remaining / a.step_m - 1e-9))
        ok = all(step(ops, left, remaining / count) for _ in range(count))
        ops.reactions()
        H = ops.getTime()
        shear = -sum(ops.nodeReaction(b, 1) for b in bases)
        descent = -(ops.nodeDisp(left, 2) + ops.nodeDisp(right, 2)) / 2
        rows.append({"target_drift": drift, "drift": ops.nodeDisp(left, 1) / a.height_m, "H_N": H, "base_shear_N": shear,
                     "knee_descent_m": descent, "load_ratio": H * a.height_m / (4 * mp), "converged": bool(ok) and abs(H - shear) <= 1e-6 * max(1.0, abs(H))})
        if not ok:
            break
    out = {"peer": "opensees", "openseespy_version": oc.openseespy_version(), "opensees_version": ops.version(),
           "inputs": {k: getattr(a, k) for k in vars(a)}, "plastic_moment_Nm": mp, "pushover": rows}
    ops.wipe()
    return out


if __name__ == "__main__":
    print(json.dumps(run()))
