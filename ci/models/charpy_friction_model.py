#!/usr/bin/env python3
"""Quasi-static rigid-plastic model of the Charpy scene with Coulomb friction at the striker and the anvils.

The model is independent of Bullet and of the scene's code: it takes the scene's geometry and yield stress
(the runner's defaults, or any flags below) and returns the energy the hammer loses until the specimen
slips off the anvils, for a friction coefficient mu.

Model (one half of the specimen, by symmetry; plane X-Z, X = impact direction, Z = specimen axis):
- each half is a rigid bar of depth b (X) and length L/2 (Z); the halves are joined at mid-span by a plastic
  hinge at the ligament's centre, d = notch + (b - notch) / 2 from the back face, moment Mp = fy b h^2 / 4;
  by symmetry the hinge carries an axial force N and no shear;
- the striker is a circle of radius rs (the rounded edge, centre on the symmetry plane) that pushes the
  halves' front faces (the thesis' flat nose, which bears with its corners off mid-span, is not modelled);
  each anvil edge is a circle of radius ra whose centre is ra behind the anvil face and ra beyond the gap's
  side face (ra = 0, the scene's sharp edges); the back face rolls on the circle until the contact reaches
  the half's end, then the back corner slides round the circle until it drops into the gap (its z reaches
  gap / 2, where the sharp edge's corner leaves too; the tapered wall behind a rounded edge falls away from a
  corner that moves towards mid-span);
- contacts are unilateral with Coulomb friction mu: the friction force opposes the sliding velocity of the
  half's material point over the contact, found from the mechanism's kinematics;
- for every half angle phi: position (the hinge stays on the symmetry plane, the back face or its corner touches
  the anvil circle, the front face touches the striker circle), then equilibrium of the half (two forces, one
  moment) for the striker force Fs, the anvil force Fa and N. The hammer's resisting force is 2 x the
  X component of the striker force; its work over the striker's travel until the half slips off the anvil
  edge is the loss. Without friction it is Mp x theta_pass
  exactly; the contacts self-lock when the equilibrium has no solution with positive contact forces.
Inertia (the halves' kinetic energy, impacts) is not in the model.

Usage: python3 ci/models/charpy_friction_model.py [--mu=0.1] [--sweep=0,0.3,0.05] [--json] [geometry flags]
"""
import argparse
import json
import math
import sys

STANDARD = dict(width_m=0.010, length_m=0.055, notch_m=0.002, gap_m=0.040, striker_radius_m=0.002,
                anvil_radius_m=0.0, fy_pa=400e6)


def positive(name, low=0.0):
    def check(text):
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{name}: '{text}' is not a number")
        if not math.isfinite(value) or value < low:
            raise argparse.ArgumentTypeError(f"{name}: {text} is not in [{low}, inf)")
        return value
    return check


class CharpyFrictionModel:
    def __init__(self, width_m, length_m, notch_m, gap_m, striker_radius_m, anvil_radius_m, fy_pa):
        if not 0 <= notch_m < 0.9 * width_m:
            raise ValueError(f"notch: {notch_m} is not in [0, 0.9 x width = {0.9 * width_m})")
        if not 0 < gap_m < length_m:
            raise ValueError(f"gap: {gap_m} is not in (0, length = {length_m})")
        self.b = width_m
        self.half_length = length_m / 2
        ligament = width_m - notch_m
        self.d = notch_m + ligament / 2  # hinge from the back face
        self.front = width_m - self.d    # front face from the hinge
        self.rs = striker_radius_m
        self.ra = anvil_radius_m
        self.za = gap_m / 2 + anvil_radius_m  # anvil circle centre: x = -ra, z = za
        self.mp = fy_pa * width_m * ligament ** 2 / 4
        self.phi_face = self._bisect(lambda phi: self.anvil_contact(phi) < self.half_length)
        self.phi_pass = self.phi_face if anvil_radius_m == 0 else self._bisect(
            lambda phi: self.corner_z(phi) > gap_m / 2)

    # geometry for a half angle phi: u_a = (sin, cos) along the half, u_n = (cos, -sin) its front normal (x, z). Up to
    # phi_face the back face rolls on the anvil circle; past it (rounded edges only) the back face's corner slides
    # round the circle until it drops into the gap (its z reaches gap / 2, the circle's lowest point; the tapered
    # wall behind it falls away from a corner that moves towards mid-span)
    def corner_z(self, phi):
        """z of the half's back corner (its end on the back face)"""
        return self.half_length * math.cos(phi) + self.d * math.sin(phi)

    def _rolls(self, phi):
        return phi <= self.phi_face or self.ra == 0

    def _corner_from_centre(self, phi):
        """(x, z) of the back corner from the anvil circle's centre while it slides round the circle"""
        dz = min(self.ra, max(-self.ra, self.corner_z(phi) - self.za))
        return math.sqrt(self.ra * self.ra - dz * dz), dz

    def hinge_x(self, phi):
        if self._rolls(phi):
            return (self.d + self.ra - self.za * math.sin(phi)) / math.cos(phi) - self.ra
        dx, _ = self._corner_from_centre(phi)
        return dx - self.ra - self.half_length * math.sin(phi) + self.d * math.cos(phi)

    def striker_x(self, phi):
        return self.hinge_x(phi) + (self.front + self.rs) / math.cos(phi)

    def anvil_contact(self, phi):
        """distance along the half from the hinge to the anvil contact point while the back face rolls"""
        return (self.za - (self.d + self.ra) * math.sin(phi)) / math.cos(phi)

    def anvil_normal(self, phi):
        """unit normal of the anvil's force on the half: the back face's while it rolls, the circle's at the corner"""
        if self._rolls(phi):
            return (math.cos(phi), -math.sin(phi))
        dx, dz = self._corner_from_centre(phi)
        return (dx / self.ra, dz / self.ra)

    def _bisect(self, below):
        lo, hi = 0.0, math.pi / 2 - 1e-9
        for _ in range(200):
            mid = (lo + hi) / 2
            if below(mid):
                lo = mid
            else:
                hi = mid
        return lo

    def resisting_force(self, phi, mu):
        """hammer's resisting force (N) at half angle phi, or None when the contacts lock"""
        s, c = math.sin(phi), math.cos(phi)
        ua, un = (s, c), (c, -s)
        h = 1e-7
        dxh = (self.hinge_x(phi + h) - self.hinge_x(phi - h)) / (2 * h)
        dxs = (self.striker_x(phi + h) - self.striker_x(phi - h)) / (2 * h)
        xh, xs = self.hinge_x(phi), self.striker_x(phi)
        # contact points relative to the hinge (x, z); the hinge is at (xh, 0)
        ts = (xs - self.rs * un[0] - xh, -self.rs * un[1])
        na = self.anvil_normal(phi)
        ta = (-self.ra + self.ra * na[0] - xh, self.za + self.ra * na[1])
        tangent = (-na[1], na[0])

        def velocity(r):  # of the half's material point at r, per unit dphi: H' + J r, J(x, z) = (z, -x)
            return (dxh + r[1], -r[0])

        vs = velocity(ts)
        slip_s = (vs[0] - dxs) * ua[0] + vs[1] * ua[1]
        slip_a = velocity(ta)[0] * tangent[0] + velocity(ta)[1] * tangent[1]
        sign_s = math.copysign(1.0, slip_s) if abs(slip_s) > 1e-12 else 0.0
        sign_a = math.copysign(1.0, slip_a) if abs(slip_a) > 1e-12 else 0.0
        # unit forces on the half per unit normal force: striker -un - mu sign_s ua, anvil na - mu sign_a tangent (the
        # back face's normal and direction while it rolls, the circle's at the corner)
        fs = (-un[0] - mu * sign_s * ua[0], -un[1] - mu * sign_s * ua[1])
        fa = (na[0] - mu * sign_a * tangent[0], na[1] - mu * sign_a * tangent[1])

        def torque(r, f):  # work per unit dphi of force f at r: f . J r
            return f[0] * r[1] - f[1] * r[0]

        # unknowns Fs, Fa, N: x-forces, z-forces, moment about the hinge (the hinge resists with -Mp)
        a = [[fs[0], fa[0], 0.0], [fs[1], fa[1], 1.0], [torque(ts, fs), torque(ta, fa), 0.0]]
        rhs = [0.0, 0.0, self.mp]
        det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]))
        if abs(det) < 1e-18:
            return None
        # Cramer's rule for the two contact forces (a[0][2] = a[2][2] = 0)
        det_s = -a[0][1] * (-rhs[2] * a[1][2])
        det_a = a[0][0] * (-a[1][2] * rhs[2])
        force_s, force_a = det_s / det, det_a / det
        if force_s <= 0 or force_a < 0:
            return None
        # the striker gets the reaction; its travel is -x: resisting force = -x component of (-force on half)
        return -2.0 * force_s * fs[0]

    def loss(self, mu, steps=4000):
        """(loss J, None) or (None, half angle at which the contacts lock); the rolling and the corner's slide are
        integrated apart, with as many steps each (the hinge's travel curves differently in each, and its rate
        grows without bound as the corner reaches the circle's lowest point)"""
        total = 0.0
        for start, end in ((0.0, self.phi_face), (self.phi_face, self.phi_pass)):
            for i in range(steps if end > start else 0):
                p0 = start + (end - start) * i / steps
                p1 = start + (end - start) * (i + 1) / steps
                pm = (p0 + p1) / 2
                force = self.resisting_force(pm, mu)
                if force is None:
                    return None, pm
                total += force * (self.striker_x(p0) - self.striker_x(p1))
        return total, None


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mu", type=positive("mu"), default=None, help="friction coefficient (default: the sweep)")
    parser.add_argument("--sweep", default="0,0.3,0.05", help="FIRST,LAST,STEP of mu, default 0,0.3,0.05")
    parser.add_argument("--json", action="store_true", help="print JSON lines")
    for key, value in STANDARD.items():
        parser.add_argument("--" + key.replace("_", "-"), type=positive(key), default=value,
                            help=f"default {value} (the runner's standard geometry)")
    args = parser.parse_args(argv)
    try:
        model = CharpyFrictionModel(**{k: getattr(args, k) for k in STANDARD})
    except ValueError as e:
        parser.error(str(e))
    if args.mu is not None:
        mus = [args.mu]
    else:
        try:
            first, last, step = (float(x) for x in args.sweep.split(","))
        except ValueError:
            parser.error(f"--sweep: '{args.sweep}' is not FIRST,LAST,STEP")
        if not (0 <= first <= last and step > 0):
            parser.error(f"--sweep: '{args.sweep}' needs 0 <= FIRST <= LAST and STEP > 0")
        mus = [first + i * step for i in range(int(round((last - first) / step)) + 1)]
    for mu in mus:
        loss, lock = model.loss(mu)
        row = {"mu": round(mu, 6), "loss_J": loss, "locks_at_phi_rad": lock, "plastic_J": model.mp * 2 * model.phi_pass,
               "theta_pass_rad": 2 * model.phi_pass, "Mp_Nm": model.mp}
        if args.json:
            print(json.dumps(row))
        elif loss is None:
            print(f"mu {mu:.3f}: the contacts lock at a bend of {2 * lock:.3f} rad")
        else:
            print(f"mu {mu:.3f}: loss {loss:.2f} J (plastic {row['plastic_J']:.2f} J, theta_pass {2 * model.phi_pass:.4f} rad)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
