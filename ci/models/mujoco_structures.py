#!/usr/bin/env python3
"""The structures scenes in MuJoCo: the n-segment cantilever (and the portal frame) of demos/structures as a MuJoCo
peer, measured beside the project's solvers (btDirectJointSolver, sequential impulse, btMLCPSolver) in
report/STRUCTURES-MUJOCO.md and report/structures-mujoco.csv.

  bash ci/peer_env.sh python3 ci/models/mujoco_structures.py [--runner=build/bin/structures]
        [--bench=build-bench/bin/game_settings_benchmarks] [--csv=report/structures-mujoco.csv]
        [--md=report/STRUCTURES-MUJOCO.md] [--quick]

The model (the project's numbers, not guessed: demos/structures/Cantilever.h CantileverParameters, the segments
as demos/plastic/BeamBuilder.cpp builds them): a 2 m steel member along +x from a fixed support, 0.05 m wide (along
the bending axis z) and 0.10 m deep, fy 400 MPa (Mp = fy b d^2 / 4 = 50 kN m), density 7800 kg/m^3, in n rigid
boxes of length L/n, mass rho b d L/n, box inertia m/12 (l^2 + d^2) about z; zero gravity; the tip load P = lambda
Mp / L along -y at the free end (a dead load). --runner checks Mp and Mp/L against the runner's --json.

Each joint is a MuJoCo hinge about z with `frictionloss = Mp`: MuJoCo's dry-friction joint, the one model in MuJoCo
that is rigid-plastic by construction (no force law, a friction row bounded by Mp that holds the joint below Mp and
dissipates Mp |dtheta| while it slides), so the rotation it keeps is permanent and its dissipation can be read from
MuJoCo's own constraint forces. The alternative, a position actuator (or joint spring) with forcerange +-Mp, is an
explicit elastic force: it returns to its reference unless the script moves the reference each step (its own plastic
return map, not MuJoCo's), and its stiffness is bounded by the explicit step; not used.
The load is a Cartesian actuator (site at the tip, refsite at the world origin, gear 0 -1 0): a force of ctrl along
-y fixed in the world, applied at the tip point; its work is ctrl x the change of the actuator's length (the tip's
-y) over each step, exact for a constant force.

MuJoCo's friction rows are soft (solreffriction / solimpfriction): the row's force is regularised, so below Mp a
joint turns slowly (creep) instead of holding. Three softnesses are measured: MuJoCo's defaults (solref 0.02 1,
solimp 0.9 0.95 0.001), "stiff" (the Charpy peer's: time constant 2 steps, impedance 0.99) and "stiffest" (2 steps,
impedance 0.9999 = mjMAXIMP). Solvers: Newton (MuJoCo's default) and PGS, at MuJoCo's default iterations (100) and at
10. Timestep 1/240 s, MuJoCo's default Euler integrator.

Measured from MuJoCo's data: joint rotations from qpos, the tip from site_xpos, kinetic energy from mj_energyVel
(mjENBL_ENERGY, data.energy[1]), the friction rows' dissipation as -sum f dq over the rows of type
mjCNSTR_FRICTION_DOF / _TENDON (efc_force of the step times the change of the row's coordinate over the step).
"""
import argparse
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # ci/, for ci/sweep
from sweep import csvfile  # noqa: E402

MUJOCO_VERSION = "4.0.0"  # ci/peer_env.sh installs it
DT_S = 1.0 / 240.0
# demos/structures/Cantilever.h CantileverParameters (and Portal.h PortalParameters) defaults
LENGTH_M = 2.0
WIDTH_M = 0.05    # section along the bending axis z
DEPTH_M = 0.10    # section in the bending plane
YIELD_PA = 400e6
DENSITY = 7800.0
MP = YIELD_PA * WIDTH_M * DEPTH_M ** 2 / 4.0
PORTAL = {"span_m": 4.0, "height_m": 3.0, "column_segments": 2, "beam_segments": 2, "H_N": 50e3, "V_N": 75e3}

SOFTNESS = {  # name: (solref time constant [s] or None for MuJoCo's default, impedance or None)
    "default": (None, None),
    "stiff": (2 * DT_S, 0.99),
    "stiffest": (2 * DT_S, 0.9999),
}
SOLVERS = [("Newton", 100), ("Newton", 10), ("PGS", 100), ("PGS", 10)]  # 100 = MuJoCo's default iterations
SEGMENTS_TIMED = [4, 8, 16, 32, 64, 128]
HOLD_FACTOR, HOLD_S = 0.9, 3.0
STOP_FACTOR = 1.5
BISECT = (0.3, 1.6, 0.0025, 1.0, 0.05)  # low, high, to, run [s], "yields": a joint turns more than this [rad]


def segment(length_m):
    """(mass, (Ixx, Iyy, Izz)) of one segment box along x: b along z, d along y, as BeamBuilder makes it
    (btBoxShape::calculateLocalInertia: m/12 (ly^2 + lz^2), ...)."""
    m = DENSITY * WIDTH_M * DEPTH_M * length_m
    return m, (m / 12 * (DEPTH_M ** 2 + WIDTH_M ** 2), m / 12 * (length_m ** 2 + WIDTH_M ** 2), m / 12 * (length_m ** 2 + DEPTH_M ** 2))


def _header(softness, solver, iterations, model, noslip=0):
    tc, imp = SOFTNESS[softness]
    fr = "" if tc is None else f'solreffriction="{tc:.9g} 1" solimpfriction="{imp:.9g} {imp:.9g} 0.001"'
    eq = "" if tc is None else f'<equality solref="{tc:.9g} 1" solimp="{imp:.9g} {imp:.9g} 0.001"/>'
    return f"""<mujoco model="{model}">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="{DT_S:.12g}" solver="{solver}" iterations="{iterations}" noslip_iterations="{noslip}" gravity="0 0 0"><flag energy="enable"/></option>
  <default><joint type="hinge" axis="0 0 1" frictionloss="{MP:.9g}" {fr}/><tendon frictionloss="{MP:.9g}" {fr}/>{eq}</default>"""


def _body(name, pos, length, along_y, joint_pos, inner=""):
    m, (ixx, iyy, izz) = segment(length)
    if along_y:
        ixx, iyy = iyy, ixx
    return (f'<body name="{name}" pos="{pos[0]:.9g} {pos[1]:.9g} 0"><joint name="{name}" pos="{joint_pos[0]:.9g} {joint_pos[1]:.9g} 0"/>'
            f'<inertial pos="0 0 0" mass="{m:.9g}" diaginertia="{ixx:.9g} {iyy:.9g} {izz:.9g}"/>{inner}')


def cantilever_xml(n, softness="stiff", solver="Newton", iterations=100, noslip=0):
    """The n-segment cantilever: joint j{i} joins segment i to segment i-1 (j0: the support); site 'tip'."""
    seg = LENGTH_M / n
    parts = []
    for i in range(n):
        tip = f'<site name="tip" pos="{seg / 2:.9g} 0 0"/>' if i == n - 1 else ""
        parts.append(_body(f"j{i}", (seg / 2 if i == 0 else seg, 0), seg, False, (-seg / 2, 0), tip))
    return (_header(softness, solver, iterations, f"cantilever-{n}", noslip) + f"""
  <worldbody><site name="origin" pos="0 0 0"/>
    {''.join(parts)}{'</body>' * n}
  </worldbody>
  <actuator><general name="P" site="tip" refsite="origin" gear="0 -1 0 0 0 0"/></actuator>
</mujoco>""")


YOUNGS_PA = 200e9  # CantileverParameters::youngs_modulus_pa: the project's elastic joints are EI / l per joint


def actuator_alternative(n=4, stiffness_fraction=1.0, integrator="implicitfast", duration_s=HOLD_S):
    """The alternative not used: no frictionloss, each joint a position actuator (reference 0) with kp = fraction x
    EI / l, kv critical for one segment about its centre (2 sqrt(kp Izz)) and forcerange +-Mp, held at 0.9 Mp/L."""
    import mujoco  # noqa: PLC0415
    import numpy as np  # noqa: PLC0415
    seg = LENGTH_M / n
    kp = stiffness_fraction * YOUNGS_PA * WIDTH_M * DEPTH_M ** 3 / 12 / seg
    kv = 2 * math.sqrt(kp * segment(seg)[1][2])
    xml = cantilever_xml(n, "default").replace(f'frictionloss="{MP:.9g}"', 'frictionloss="0"')
    xml = xml.replace("<option ", f'<option integrator="{integrator}" ')
    xml = xml.replace("</actuator>", "".join(f'<position joint="j{i}" kp="{kp:.9g}" kv="{kv:.9g}" forcerange="{-MP:.9g} {MP:.9g}"/>'
                                             for i in range(n)) + "</actuator>")
    messages = []
    mujoco.set_mju_user_warning(messages.append)
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    data.ctrl[0] = HOLD_FACTOR * MP / LENGTH_M
    for _ in range(int(round(duration_s / DT_S))):
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    diverged = int(data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number) > 0
    return {"kp_Nm_rad": kp, "kv_Nms_rad": kv, "integrator": integrator, "diverged": diverged,
            "root_rotation_rad": None if diverged else -float(data.qpos[0]),
            "tip_sag_m": None if diverged else -float(data.site_xpos[model.site("tip").id][1]),
            "max_rotation_rad": None if diverged else float(np.abs(data.qpos).max())}


def portal_sites():
    cs, bs = PORTAL["column_segments"], PORTAL["beam_segments"]
    return (["base-left"] + [f"column-left-{i}" for i in range(1, cs)] + ["knee-left"]
            + [("mid-span" if i == bs // 2 else f"beam-{i}") for i in range(1, bs)] + ["knee-right"]
            + [f"column-right-{i}" for i in range(1, cs)] + ["base-right"])


def portal_xml(softness="stiff", solver="Newton", iterations=100):
    """The fixed-base portal of PortalScene: one kinematic tree from the left base along the frame to the right
    column's foot; the right base closes the loop with a connect equality at (L, 0) and a fixed tendon (the sum of
    every hinge angle: the foot segment's rotation against the ground) with frictionloss Mp. Sites 'H' (left knee)
    and 'V' (mid-span) carry the loads."""
    L, h, cs, bs = PORTAL["span_m"], PORTAL["height_m"], PORTAL["column_segments"], PORTAL["beam_segments"]
    names = portal_sites()[:-1]
    cl, bl = h / cs, L / bs
    # segment centres and their pivots in world coordinates, along the frame
    segs = [((0, (i + 0.5) * cl), (0, i * cl), cl, True) for i in range(cs)]
    segs += [(((i + 0.5) * bl, h), (i * bl, h), bl, False) for i in range(bs)]
    segs += [((L, h - (i + 0.5) * cl), (L, h - i * cl), cl, True) for i in range(cs)]
    parts, parent = [], (0.0, 0.0)
    for k, (centre, pivot, length, along_y) in enumerate(segs):
        inner = ""
        if k == cs - 1:
            inner += f'<site name="H" pos="0 {cl / 2:.9g} 0"/>'
        if k == cs + bs // 2 - 1:
            inner += f'<site name="V" pos="{bl / 2:.9g} 0 0"/>'
        if k == len(segs) - 1:
            inner += f'<site name="foot" pos="0 {-cl / 2:.9g} 0"/>'
        rel = (centre[0] - parent[0], centre[1] - parent[1])
        parts.append(_body(names[k], rel, length, along_y, (pivot[0] - centre[0], pivot[1] - centre[1]), inner))
        parent = centre
    joints = "".join(f'<joint joint="{n}" coef="1"/>' for n in names)
    return (_header(softness, solver, iterations, "portal") + f"""
  <worldbody><site name="origin" pos="0 0 0"/><site name="ground-right" pos="{L:.9g} 0 0"/>
    {''.join(parts)}{'</body>' * len(segs)}
  </worldbody>
  <equality><connect site1="foot" site2="ground-right"/></equality>
  <tendon><fixed name="base-right">{joints}</fixed></tendon>
  <actuator><general name="H" site="H" refsite="origin" gear="1 0 0 0 0 0"/>
            <general name="V" site="V" refsite="origin" gear="0 -1 0 0 0 0"/></actuator>
</mujoco>""")


class Run:
    """A model stepped with its loads at factor(t) x the actuators' reference forces; measures per step."""

    def __init__(self, xml, reference_forces):
        import mujoco  # noqa: PLC0415
        import numpy as np  # noqa: PLC0415
        self.mj, self.np = mujoco, np
        self.messages = []
        mujoco.set_mju_user_warning(self.messages.append)
        self.model = mujoco.MjModel.from_xml_string(xml)
        self.data = mujoco.MjData(self.model)
        self.reference = np.array(reference_forces, dtype=float)
        self.nj = self.model.njnt
        mujoco.mj_forward(self.model, self.data)
        self.coords0 = self.coords()
        self.load_work = 0.0
        self.dissipated = 0.0
        self.mp_path = 0.0  # Mp x the accumulated |change| of every joint (and tendon) coordinate
        self.root_dissipated = 0.0
        self.root_path = 0.0
        self.steps = 0
        self.max_abs = np.zeros(len(self.coords0))
        self.diverged_at_s = None  # when MuJoCo first found a blown-up acceleration (it then resets the state)

    def coords(self):
        """Joint angles (qpos) and tendon lengths (computed by the last forward pass: mj_step1 or mj_forward)."""
        return self.np.concatenate([self.data.qpos[: self.nj], self.data.ten_length])

    def rotations(self):
        return self.coords() - self.coords0

    def step(self, factor):
        mj, d = self.mj, self.data
        mj.mj_step1(self.model, d)  # kinematics of the current state: actuator lengths, tendon lengths
        length0, c0 = d.actuator_length.copy(), self.coords()
        d.ctrl[:] = factor * self.reference
        mj.mj_step2(self.model, d)
        n = d.nefc
        types, ids, force = d.efc_type[:n].copy(), d.efc_id[:n].copy(), d.efc_force[:n].copy()
        mj.mj_fwdPosition(self.model, d)  # the new state's lengths (mj_step1 of the next step recomputes them)
        dc = self.coords() - c0
        self.load_work += float(d.ctrl @ (d.actuator_length - length0))
        f = self.np.zeros(len(dc))
        dof = types == mj.mjtConstraint.mjCNSTR_FRICTION_DOF
        ten = types == mj.mjtConstraint.mjCNSTR_FRICTION_TENDON
        f[ids[dof]] = force[dof]  # hinge dof i is joint i (one dof each)
        f[self.nj + ids[ten]] = force[ten]
        self.dissipated -= float(f @ dc)
        self.mp_path += MP * float(self.np.abs(dc).sum())
        self.root_dissipated -= float(f[0] * dc[0])
        self.root_path += MP * abs(float(dc[0]))
        self.steps += 1
        if self.diverged_at_s is None and self.diverged():
            self.diverged_at_s = self.steps * DT_S
            return
        self.max_abs = self.np.maximum(self.max_abs, self.np.abs(self.rotations()))

    def kinetic(self):
        self.mj.mj_energyVel(self.model, self.data)
        return float(self.data.energy[1])

    def finite(self):
        return bool(self.np.all(self.np.isfinite(self.data.qpos)) and self.np.all(self.np.isfinite(self.data.qvel)))

    def diverged(self):
        return int(self.data.warning[self.mj.mjtWarning.mjWARN_BADQACC].number) > 0


def cantilever_run(n, cfg, factor, duration_s, stop=False, noslip=0):
    """A constant dead tip load factor x Mp/L for duration_s (stop: until the root stops, as CantileverScene does);
    noslip: MuJoCo's noslip_iterations (its unregularised post-pass over friction rows)."""
    softness, solver, iterations = cfg
    t0 = time.perf_counter()
    r = Run(cantilever_xml(n, softness, solver, iterations, noslip), [MP / LENGTH_M])
    steps = int(round(duration_s / DT_S))
    third = None
    max_kinetic, stopped = 0.0, None
    for k in range(steps):
        r.step(factor)
        if third is None and (k + 1) * DT_S >= duration_s / 3 - 1e-12:
            third = r.rotations().copy()
        if stop:
            root = -float(r.rotations()[0])
            ke = r.kinetic()
            max_kinetic = max(max_kinetic, ke)
            if root > 0.01 and (ke < 1e-4 * max_kinetic or root < r.max_abs[0] - 1e-3):
                stopped = float(r.max_abs[0])
                break
        if not r.finite() or r.diverged_at_s is not None:
            break
    wall = time.perf_counter() - t0
    rot = r.rotations()
    ke = r.kinetic()
    tip = r.data.site_xpos[r.model.site("tip").id]
    return {
        "root_rotation_rad": -float(rot[0]), "max_root_rotation_rad": float(r.max_abs[0]),
        "max_inner_rotation_rad": float(r.max_abs[1:].max()) if n > 1 else 0.0,
        "creep_rad": float(r.np.abs(rot - third).max()) if third is not None else float("nan"),
        "tip_sag_m": -float(tip[1]), "stop_rotation_rad": stopped if stop else None,
        "load_work_J": r.load_work, "kinetic_J": ke, "dissipated_J": r.dissipated,
        "mp_x_rotations_J": r.mp_path, "mp_x_end_rotations_J": MP * float(r.np.abs(rot).sum()),
        "root_dissipated_J": r.root_dissipated, "root_mp_x_rotation_J": r.root_path,
        "energy_residual_pct": 100.0 * (r.load_work - ke - r.dissipated) / r.load_work if r.load_work else 0.0,
        "steps": r.steps, "simulated_s": r.steps * DT_S, "wall_s": wall, "finite": r.finite(), "diverged": r.diverged(),
        "diverged_at_s": r.diverged_at_s, "mujoco_warning": r.messages[0].strip() if r.messages else "",
    }


def bisect(yields, low=BISECT[0], high=BISECT[1], to=BISECT[2]):
    """The smallest factor in [low, high] at which yields(factor) (to within 'to'); '<low' / '>high' outside."""
    if yields(low):
        return f"<{low:g}"
    if not yields(high):
        return f">{high:g}"
    while high - low > to:
        mid = 0.5 * (low + high)
        if yields(mid):
            high = mid
        else:
            low = mid
    return f"{0.5 * (low + high):.4f}"


def cantilever_collapse(n, cfg):
    """(root factor, any-joint factor): the smallest load factor at which the root (any joint) turns more than
    0.05 rad within 1 s of a constant load (GAME_SETTINGS.md's collapse factor for the any-joint criterion)."""
    cache = {}

    def run(f):
        if f not in cache:
            cache[f] = cantilever_run(n, cfg, f, BISECT[3])
        return cache[f]
    root = bisect(lambda f: run(f)["max_root_rotation_rad"] > BISECT[4])
    anyj = bisect(lambda f: max(run(f)["max_root_rotation_rad"], run(f)["max_inner_rotation_rad"]) > BISECT[4])
    return root, anyj, sum(1 for r in cache.values() if r["diverged_at_s"] is not None), len(cache)


def stop_rotation(factor):
    """Plastic analysis of the dead-load collapse: the root stops where factor sin(t) = t."""
    lo, hi = 1e-9, math.pi
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if factor * math.sin(mid) > mid:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def step_times(n, cfg, steps=1000, warmup=240):
    """Median and mean wall time of one mj_step [us] on the cantilever held at 0.9, after one second (like
    game_settings_benchmarks), each mj_step timed on its own (the Python call included)."""
    import mujoco  # noqa: PLC0415
    softness, solver, iterations = cfg
    mujoco.set_mju_user_warning(lambda text: None)  # divergence is read from data.warning; no MUJOCO_LOG.TXT
    model = mujoco.MjModel.from_xml_string(cantilever_xml(n, softness, solver, iterations))
    data = mujoco.MjData(model)
    data.ctrl[0] = HOLD_FACTOR * MP / LENGTH_M
    for _ in range(warmup):
        mujoco.mj_step(model, data)
    times = []
    clock = time.perf_counter_ns
    for _ in range(steps):
        t = clock()
        mujoco.mj_step(model, data)
        times.append(clock() - t)
    t = clock()
    mujoco.mj_step(model, data, nstep=steps)  # the same number of steps in one call: no Python per step
    batched = (clock() - t) / steps
    diverged = int(data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number) > 0
    return statistics.median(times) / 1e3, statistics.fmean(times) / 1e3, batched / 1e3, diverged


def portal_run(cfg, factor, duration_s, until_rad=None):
    """The portal at a constant load factor for duration_s (until_rad: or until a joint has turned that far).
    Site rotations as PortalScene measures them: body i + 1 against body i along the frame, the ground at both
    ends; so base-right is minus the tendon (the foot's angle against the ground)."""
    softness, solver, iterations = cfg
    t0 = time.perf_counter()
    r = Run(portal_xml(softness, solver, iterations), [PORTAL["H_N"], PORTAL["V_N"]])
    third = None
    for k in range(int(round(duration_s / DT_S))):
        r.step(factor)
        if third is None and (k + 1) * DT_S >= duration_s / 3 - 1e-12:
            third = r.rotations().copy()
        if not r.finite() or r.diverged_at_s is not None or (until_rad is not None and r.max_abs.max() >= until_rad):
            break
    rot = r.rotations()
    rot[-1] = -rot[-1]
    names = portal_sites()
    largest = float(r.np.abs(rot).max())
    mechanism = [n for n, x in zip(names, rot) if abs(x) >= 0.2 * largest] if largest > 0 else []
    ke = r.kinetic()
    foot = r.data.site_xpos[r.model.site("foot").id]
    return {
        "rotations": {n: float(x) for n, x in zip(names, rot)}, "max_rotation_rad": float(r.max_abs.max()),
        "mechanism": " ".join(mechanism), "simulated_s": r.steps * DT_S,
        "creep_rad": float(r.np.abs(rot - third).max()) if third is not None else float("nan"),
        "closure_gap_m": float(math.hypot(foot[0] - PORTAL["span_m"], foot[1])),
        "load_work_J": r.load_work, "kinetic_J": ke, "dissipated_J": r.dissipated, "mp_x_rotations_J": r.mp_path,
        "energy_residual_pct": 100.0 * (r.load_work - ke - r.dissipated) / r.load_work if r.load_work else 0.0,
        "steps": r.steps, "wall_s": time.perf_counter() - t0, "finite": r.finite(), "diverged": r.diverged(),
        "diverged_at_s": r.diverged_at_s,
    }


def portal_collapse(cfg):
    cache = {}

    def run(f):
        if f not in cache:
            cache[f] = portal_run(cfg, f, BISECT[3])
        return cache[f]
    return (bisect(lambda f: run(f)["max_rotation_rad"] > BISECT[4]), sum(1 for r in cache.values() if r["diverged_at_s"] is not None),
            len(cache))


# ---- the project's runs, in the same session -------------------------------------------------------------

PROJECT_SOLVERS = [("direct", "btDirectJointSolver"), ("sequential-impulse", "sequential impulse"), ("dantzig", "btMLCPSolver + Dantzig"),
                   ("pgs", "btMLCPSolver + PGS")]


def runner_json(runner, *flags):
    done = subprocess.run([runner, "--json", *flags], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise SystemExit(f"mujoco_structures: {runner} {' '.join(flags)} exited {done.returncode}: {done.stderr.strip()[:300]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def check_runner(runner):
    """The runner's Mp and Mp/L must be this model's."""
    out = runner_json(runner, "--scene=cantilever", "--load-ratio=0.5", "--duration=0.01")
    if abs(out["plastic_moment_Nm"] - MP) > 1e-6 * MP or abs(out["analytic_collapse_load_N"] - MP / LENGTH_M) > 1e-6 * MP:
        raise SystemExit(f"mujoco_structures: the runner's Mp {out['plastic_moment_Nm']} N m / collapse load "
                         f"{out['analytic_collapse_load_N']} N are not this model's {MP} / {MP / LENGTH_M}")


def project_cantilever(runner, n, solver):
    base = ["--scene=cantilever", f"--segments={n}", f"--solver={solver}", "--iterations=10"]
    hold = runner_json(runner, *base, f"--load-ratio={HOLD_FACTOR}", f"--duration={HOLD_S}")
    stop = runner_json(runner, *base, f"--load-ratio={STOP_FACTOR}", "--duration=10")
    ramp = runner_json(runner, *base, "--ramp-rate=0.02")
    cache = {}

    def run(f):
        if f not in cache:
            cache[f] = runner_json(runner, *base, f"--load-ratio={f:.6f}", f"--duration={BISECT[3]}")
        return cache[f]
    root = bisect(lambda f: run(f)["max_root_rotation_rad"] > BISECT[4])
    anyj = bisect(lambda f: max(run(f)["max_root_rotation_rad"], run(f)["max_inner_rotation_rad"]) > BISECT[4])
    return hold, stop, ramp, root, anyj


def project_bench(bench):
    """{(solver, segments): (cpu_us, wall_us)} from game_settings_benchmarks (median of 3 repetitions)."""
    out = subprocess.run([bench, "--benchmark_filter=si_10_iterations|direct|mlcp_dantzig", "--benchmark_min_time=0.5",
                          "--benchmark_repetitions=3", "--benchmark_report_aggregates_only=true", "--benchmark_format=json"],
                         capture_output=True, text=True, timeout=1200, check=True).stdout
    result = {}
    for r in json.loads(out)["benchmarks"]:
        if r.get("aggregate_name") != "median":
            continue
        _, kind, segments = r["run_name"].split("/")
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[r["time_unit"]]
        result[(kind, int(segments))] = (r["cpu_time"] * scale, r["real_time"] * scale)
    return result


# ---- the sweep, the CSV and the report -------------------------------------------------------------------

def fmt(v, pattern="{:.4g}"):
    if v is None or v == "":
        return ""
    if isinstance(v, str):
        return v
    if isinstance(v, float) and math.isnan(v):
        return "nan"
    return pattern.format(v)


def configs(quick):
    softs = ["stiff"] if quick else list(SOFTNESS)
    sols = [("Newton", 100)] if quick else SOLVERS
    return [(s, sol, it) for s in softs for sol, it in sols]


def sweep(args):
    import mujoco  # noqa: PLC0415
    rows, t_start = [], time.perf_counter()
    load_start = os.getloadavg()[0]
    bench = project_bench(args.bench) if args.bench else {}  # first: a benchmark that fails stops the sweep early
    cant_n = [4] if args.quick else [4, 8]
    for cfg in configs(args.quick):
        tag = dict(peer="mujoco", softness=cfg[0], solver=cfg[1], iterations=cfg[2])
        name = f"mujoco/{cfg[0]}/{cfg[1]}/{cfg[2]}"
        for n in (cant_n if args.quick else SEGMENTS_TIMED):
            h = cantilever_run(n, cfg, HOLD_FACTOR, HOLD_S)
            rows.append(dict(key=f"{name}/hold/{n}", case="hold", scene="cantilever", segments=n, factor=HOLD_FACTOR, **tag, **h))
        for n in cant_n:
            root, anyj, diverged, runs = cantilever_collapse(n, cfg)
            rows.append(dict(key=f"{name}/collapse/{n}", case="collapse", scene="cantilever", segments=n, **tag,
                             root_collapse_factor=root, any_joint_collapse_factor=anyj, diverged_runs=diverged, runs=runs))
            s = cantilever_run(n, cfg, STOP_FACTOR, 10.0, stop=True)
            rows.append(dict(key=f"{name}/stop/{n}", case="stop", scene="cantilever", segments=n, factor=STOP_FACTOR, **tag, **s,
                             analytic_stop_rotation_rad=stop_rotation(STOP_FACTOR)))
        for n in ([4, 8] if args.quick else SEGMENTS_TIMED):
            med, mean, batched, diverged = step_times(n, cfg, steps=200 if args.quick else 2000)
            rows.append(dict(key=f"{name}/time/{n}", case="time", scene="cantilever", segments=n, **tag, median_us=med, mean_us=mean,
                             batched_us=batched, diverged=diverged))
        if not args.quick:
            hold = portal_run(cfg, HOLD_FACTOR, HOLD_S)
            rows.append(dict(key=f"{name}/hold/portal", case="hold", scene="portal", factor=HOLD_FACTOR, **tag,
                             **{k: v for k, v in hold.items() if k != "rotations"}))
            factor, diverged, runs = portal_collapse(cfg)
            rows.append(dict(key=f"{name}/collapse/portal", case="collapse", scene="portal", **tag, any_joint_collapse_factor=factor,
                             diverged_runs=diverged, runs=runs))
            col = portal_run(cfg, 1.1, 1.0, until_rad=0.05)
            rows.append(dict(key=f"{name}/stop/portal", case="collapse-run", scene="portal", factor=1.1, **tag,
                             **{k: v for k, v in col.items() if k != "rotations"},
                             **{f"rot_{k}": v for k, v in col["rotations"].items()}))
        print(f"{name}: done ({time.perf_counter() - t_start:.0f} s)", file=sys.stderr)
    if not args.quick:
        for softness in ("default", "stiffest"):
            for n in (4, 8, 32):
                h = cantilever_run(n, (softness, "Newton", 100), HOLD_FACTOR, HOLD_S, noslip=100)
                rows.append(dict(key=f"mujoco/{softness}/Newton/100/noslip=100/hold/{n}", peer="mujoco", case="noslip", scene="cantilever",
                                 segments=n, factor=HOLD_FACTOR, softness=softness, solver="Newton", iterations=100, noslip_iterations=100, **h))
        for fraction in (1.0, 0.1):
            for integrator in ("Euler", "implicitfast"):
                a = actuator_alternative(4, fraction, integrator)
                rows.append(dict(key=f"mujoco/actuator/{fraction:g}/{integrator}/hold/4", peer="mujoco", case="alternative", scene="cantilever",
                                 segments=4, factor=HOLD_FACTOR, softness="", solver="Newton", iterations=100, stiffness_fraction=fraction, **a))
    if args.runner:
        check_runner(args.runner)
        for solver, _ in PROJECT_SOLVERS:
            tag = dict(peer="project", softness="", solver=solver, iterations=10)
            for n in cant_n:
                hold, stop, ramp, root, anyj = project_cantilever(args.runner, n, solver)
                keep = ("root_rotation_rad", "max_root_rotation_rad", "max_inner_rotation_rad", "creep_rad", "load_work_J", "kinetic_J",
                        "geometric_plastic_work_J", "booked_plastic_work_J", "energy_balance_error_pct", "solver_fallbacks", "steps", "wall_s")
                rows.append(dict(key=f"project/{solver}/hold/{n}", case="hold", scene="cantilever", segments=n, factor=HOLD_FACTOR, **tag,
                                 **{k: hold[k] for k in keep}))
                rows.append(dict(key=f"project/{solver}/collapse/{n}", case="collapse", scene="cantilever", segments=n, **tag,
                                 root_collapse_factor=root, any_joint_collapse_factor=anyj, ramp_collapse_factor=ramp["collapse_ratio"],
                                 ramp_mechanism=" ".join(map(str, ramp["mechanism"]))))
                rows.append(dict(key=f"project/{solver}/stop/{n}", case="stop", scene="cantilever", segments=n, factor=STOP_FACTOR, **tag,
                                 **{k: stop[k] for k in keep}, stop_rotation_rad=stop["stop_rotation_rad"],
                                 analytic_stop_rotation_rad=stop["analytic_stop_rotation_rad"]))
            if not args.quick:
                hold = runner_json(args.runner, "--scene=portal", f"--solver={solver}", "--iterations=10", "--ramp-rate=0",
                                   f"--load-factor={HOLD_FACTOR}", f"--duration={HOLD_S}")
                ramp = runner_json(args.runner, "--scene=portal", f"--solver={solver}", "--iterations=10")
                rows.append(dict(key=f"project/{solver}/hold/portal", case="hold", scene="portal", factor=HOLD_FACTOR, **tag,
                                 max_rotation_rad=hold["max_rotation_rad"], creep_rad=hold["creep_rad"]))
                rows.append(dict(key=f"project/{solver}/collapse/portal", case="collapse", scene="portal", **tag,
                                 ramp_collapse_factor=ramp["collapse_factor"], ramp_mechanism=" ".join(ramp["hinges"]),
                                 mechanism_matches=ramp["mechanism_matches"], solver_fallbacks=ramp["solver_fallbacks"]))
            print(f"project/{solver}: done ({time.perf_counter() - t_start:.0f} s)", file=sys.stderr)
    if args.bench:
        for (kind, n), (cpu, wall) in sorted(bench.items()):
            rows.append(dict(key=f"bench/{kind}/{n}", peer="project", case="time", scene="cantilever", segments=n, solver=kind,
                             iterations=10, cpu_us=cpu, wall_us=wall))
    machine = f"{platform.node()}, {platform.machine()}, {os.cpu_count()} CPUs, Python {platform.python_version()}, MuJoCo {mujoco.__version__}"
    load = f"{load_start:.2f} / {os.getloadavg()[0]:.2f}"
    for r in rows:
        r["machine"] = machine
        r["load_average"] = load  # 1-minute load average at the start / end of the sweep
        for k, v in list(r.items()):
            if isinstance(v, bool):
                r[k] = int(v)
    return rows, time.perf_counter() - t_start


def report(rows, seconds, command):
    """STRUCTURES-MUJOCO.md from the rows."""
    by = {r["key"]: r for r in rows}
    num = lambda r, k: (float(r[k]) if r.get(k) not in (None, "", "None") else None) if r else None  # noqa: E731
    gone = lambda r: f"diverged at {num(r, 'diverged_at_s'):.3g} s (reset)" if num(r, "diverged_at_s") is not None else ""  # noqa: E731
    machine = rows[0]["machine"]
    version = MUJOCO_VERSION
    softs = [s for s in SOFTNESS if any(r.get("peer") == "mujoco" and r.get("softness") == s for r in rows)]
    sols = [(s, int(i)) for s, i in SOLVERS if any(r.get("solver") == s and str(r.get("iterations")) == str(i) and r.get("peer") == "mujoco" for r in rows)]
    projects = [(s, label) for s, label in PROJECT_SOLVERS if f"project/{s}/hold/4" in by]
    seg_hold = sorted({int(r["segments"]) for r in rows if r.get("case") == "hold" and r.get("scene") == "cantilever" and r["peer"] == "mujoco"})
    seg_small = sorted({int(r["segments"]) for r in rows if r.get("case") == "stop" and r.get("scene") == "cantilever" and r["peer"] == "mujoco"})
    out = [f"""# The structures scenes in MuJoCo {version}, beside the project's solvers

Generated by `{command}` (`ci/models/mujoco_structures.py`, {seconds:.0f} s) on {machine}. Do not edit; the numbers are in
`report/structures-mujoco.csv`.

The project's cantilever (`build/bin/structures --scene=cantilever`: 2 m, 50 x 100 mm steel, Mp = {MP / 1e3:g} kN m,
n rigid segments, zero gravity, a dead tip load lambda Mp / L) as a MuJoCo model with the same segment masses and
inertias (`demos/structures/Cantilever.h`, `demos/plastic/BeamBuilder.cpp`), each joint a hinge with
`frictionloss = Mp`: MuJoCo's dry-friction joint, rigid-plastic by construction (a friction row bounded by Mp; no
force law, so what it turns it keeps), its dissipation readable from MuJoCo's own `efc_force`. (A position actuator
or joint spring with forcerange +-Mp would be an explicit elastic force that springs back unless the script moved
its reference each step: not used.) The tip load is a Cartesian actuator (site at the tip, refsite at the origin).
Timestep 1/240 s, Euler. MuJoCo's friction rows are soft; three softnesses of the friction rows (and of the
portal's loop closure): **default** (MuJoCo's: solref 0.02 1, solimp 0.9 0.95), **stiff** (time constant 2 steps,
impedance 0.99: the Charpy peer's) and **stiffest** (2 steps, impedance 0.9999, MuJoCo's upper bound). Solvers:
Newton (MuJoCo's default) and PGS, at MuJoCo's default 100 iterations and at 10. The project: `build/bin/structures`
at 10 iterations with each solver, run in the same session.
"""]
    out.append(summary(by, num, gone))
    alt = [r for r in rows if r.get("case") == "alternative"]
    if alt:
        out.append("""Why not the alternative: the same 4-segment cantilever without frictionloss, each joint a position actuator
(reference 0, forcerange +-Mp, kv critical for one segment), held at 0.9 Mp/L for 3 s, Newton, 100 iterations:

| kp | integrator | diverged | root [rad] | tip sag [m] |
| --- | --- | --- | --- | --- |""")
        for r in alt:
            d = str(r["diverged"]) in ("1", "True")
            out.append(f"| {float(r['stiffness_fraction']):g} EI/l = {float(r['kp_Nm_rad']):.3g} N m/rad | {r['integrator']} "
                       f"| {'yes (MuJoCo reset the state)' if d else 'no'} | {'' if d else fmt(num(r, 'root_rotation_rad'))} "
                       f"| {'' if d else fmt(num(r, 'tip_sag_m'))} |")
        out.append("\nAt the project's elastic stiffness the actuator is an explicit spring the step cannot carry; soft enough to be "
                   "stable it is an elastic joint that sags under the load, not a rigid-plastic one.\n")
    # (a) hold
    out.append(f"""## Hold at {HOLD_FACTOR} Mp/L for {HOLD_S:g} s (plastic analysis: nothing turns)

**root**: root rotation at the end (tip down positive); **inner**: the largest rotation of any other joint over the
run; **sag**: the tip's displacement down at the end; **creep**: the largest change of a joint's rotation from 1 s
to 3 s. Rotations from qpos (MuJoCo) and from the bodies (project). **diverged at t (reset)**: MuJoCo found a
blown-up acceleration at t (mjWARN_BADQACC) and reset the state to the rest pose; the run stops there.
""")
    for n in seg_hold:
        out.append(f"\n{n} segments:\n\n| model | solver | iterations | root [rad] | inner [rad] | tip sag [m] | creep 1-3 s [rad] |\n| --- | --- | --- | --- | --- | --- | --- |")
        for s in softs:
            for sol, it in sols:
                r = by.get(f"mujoco/{s}/{sol}/{it}/hold/{n}")
                if r and gone(r):
                    out.append(f"| MuJoCo, {s} | {sol} | {it} | {gone(r)} | | | |")
                elif r:
                    out.append(f"| MuJoCo, {s} | {sol} | {it} | {fmt(num(r, 'root_rotation_rad'))} | {fmt(num(r, 'max_inner_rotation_rad'))} "
                               f"| {fmt(num(r, 'tip_sag_m'))} | {fmt(num(r, 'creep_rad'))} |")
        for s, label in projects:
            r = by.get(f"project/{s}/hold/{n}")
            if r:
                out.append(f"| project | {label} | 10 | {fmt(num(r, 'root_rotation_rad'))} | {fmt(num(r, 'max_inner_rotation_rad'))} "
                           f"| (not in the runner's JSON) | {fmt(num(r, 'creep_rad'))} |")
    ns = [r for r in rows if r.get("case") == "noslip"]
    if ns:
        out.append("""
MuJoCo's noslip post-pass (`noslip_iterations="100"`: friction rows solved again without regularisation) does not
make the cantilever hold either (Newton, 100 iterations, the same 3 s at 0.9):

| softness | segments | root [rad] | inner [rad] | tip sag [m] | creep 1-3 s [rad] |
| --- | --- | --- | --- | --- | --- |""")
        for r in ns:
            cells = (f"{gone(r)} | | | " if gone(r) else f"{fmt(num(r, 'root_rotation_rad'))} | {fmt(num(r, 'max_inner_rotation_rad'))} "
                     f"| {fmt(num(r, 'tip_sag_m'))} | {fmt(num(r, 'creep_rad'))}")
            out.append(f"| {r['softness']} + noslip 100 | {r['segments']} | {cells} |")
    # (b) collapse
    out.append(f"""
## Collapse load (plastic analysis: 1.0 Mp/L, the hinge at the root)

Bisection on [{BISECT[0]}, {BISECT[1]}] to {BISECT[2]}: the smallest constant load factor at which the root
(**root**) or any joint (**any joint**, report/GAME_SETTINGS.md's definition) turns more than {BISECT[4]} rad within
{BISECT[3]:g} s. `<0.3`: it turns that far already at 0.3. **diverged**: bisection runs in which MuJoCo reset the state
(they count as turned if they had turned that far before). The project also with its own quasi-static ramp
(`--ramp-rate=0.02`, collapse confirmed when the held load turns the mechanism 0.05 rad; mechanism: the joints that
turned, 0 = root).
""")
    out.append("| segments | model | solver | iterations | root | any joint | diverged | project ramp (mechanism) |\n| --- | --- | --- | --- | --- | --- | --- | --- |")
    for n in seg_small:
        for s in softs:
            for sol, it in sols:
                r = by.get(f"mujoco/{s}/{sol}/{it}/collapse/{n}")
                if r:
                    out.append(f"| {n} | MuJoCo, {s} | {sol} | {it} | {r['root_collapse_factor']} | {r['any_joint_collapse_factor']} "
                               f"| {r['diverged_runs']} of {r['runs']} | |")
        for s, label in projects:
            r = by.get(f"project/{s}/collapse/{n}")
            if r:
                ramp = num(r, "ramp_collapse_factor")
                out.append(f"| {n} | project | {label} | 10 | {r['root_collapse_factor']} | {r['any_joint_collapse_factor']} | "
                           f"| {fmt(ramp, '{:.4f}') if ramp is not None else 'none'} ({r.get('ramp_mechanism', '')}) |")
    # (c) energy
    theta = stop_rotation(STOP_FACTOR)
    out.append(f"""
## Energy balance in a collapse: dead load {STOP_FACTOR} Mp/L until the root stops

Plastic analysis: the root stops at {STOP_FACTOR} sin(t) = t, t = {theta:.4f} rad, the load's work all dissipated by
the root hinge. **load work**: the load times its point's displacement; **kinetic** (mj_energyVel) at the end;
**dissipated**: MuJoCo's friction rows, -sum efc_force x dq; **Mp x rotations**: Mp x the accumulated |dq| of every
joint from qpos (equal to the dissipated energy only where a joint turns at the cap: a joint creeping below Mp
dissipates less); **root**: the root row's dissipation against Mp x its rotation; **residual**: (load work - kinetic -
dissipated) / load work. The project: kinetic and Mp x the sum of |joint rotations| from the bodies
(`energy_balance_error_pct` = residual with that in place of "dissipated"), its joints' booked work.
""")
    out.append("| segments | model | solver | it. | stop [rad] | load work [J] | kinetic [J] | dissipated [J] | Mp x rotations [J] | root: dissipated / Mp x rotation [J] | residual [%] |\n"
               "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for n in seg_small:
        for s in softs:
            for sol, it in sols:
                r = by.get(f"mujoco/{s}/{sol}/{it}/stop/{n}")
                if r and gone(r):
                    out.append(f"| {n} | MuJoCo, {s} | {sol} | {it} | {gone(r)} | | | | | | |")
                elif r:
                    out.append(f"| {n} | MuJoCo, {s} | {sol} | {it} | {fmt(num(r, 'stop_rotation_rad')) or 'did not stop'} | {fmt(num(r, 'load_work_J'), '{:.1f}')} "
                               f"| {fmt(num(r, 'kinetic_J'), '{:.3g}')} | {fmt(num(r, 'dissipated_J'), '{:.1f}')} | {fmt(num(r, 'mp_x_rotations_J'), '{:.1f}')} "
                               f"| {fmt(num(r, 'root_dissipated_J'), '{:.1f}')} / {fmt(num(r, 'root_mp_x_rotation_J'), '{:.1f}')} "
                               f"| {fmt(num(r, 'energy_residual_pct'), '{:+.3f}')} |")
        for s, label in projects:
            r = by.get(f"project/{s}/stop/{n}")
            if r:
                out.append(f"| {n} | project | {label} | 10 | {fmt(num(r, 'stop_rotation_rad'))} | {fmt(num(r, 'load_work_J'), '{:.1f}')} "
                           f"| {fmt(num(r, 'kinetic_J'), '{:.3g}')} | booked {fmt(num(r, 'booked_plastic_work_J'), '{:.1f}')} "
                           f"| {fmt(num(r, 'geometric_plastic_work_J'), '{:.1f}')} | | {fmt(num(r, 'energy_balance_error_pct'), '{:+.3f}')} |")
    # (d) time
    bench = {(r["solver"], int(r["segments"])): r for r in rows if r["key"].startswith("bench/")}
    seg_t = sorted({int(r["segments"]) for r in rows if r.get("case") == "time" and r["peer"] == "mujoco"})
    out.append(f"""
## Wall time per step: the cantilever held at {HOLD_FACTOR} Mp/L, after one second

MuJoCo: each `mj_step` timed on its own (time.perf_counter_ns around the Python call: the binding's overhead is
included) over 2000 steps, one run: median (mean) in us; then the next 2000 steps in one `mj_step(model, data,
nstep=2000)` call (no Python per step): **batched** mean. †: MuJoCo reset a diverged state during the timed steps
(the figure is for stepping whatever state it reset to). The project:
`build-bench/bin/game_settings_benchmarks` run in the same session (Google Benchmark, the same cantilever of plastic hinges at
0.9 Mp/L, 1/240 s: median of 3 repetitions of the mean step, wall time), and the ratio MuJoCo mean / project wall.
{machine}; a shared machine (1-minute load average {rows[0].get('load_average', '?')} at the start / end of the sweep, on
{os.cpu_count()} CPUs): compare within this table.
""")
    head = "| model | solver | it. | " + " | ".join(f"{n}" for n in seg_t) + " |"
    out.append(head + "\n|" + " --- |" * (3 + len(seg_t)))
    for s in softs:
        for sol, it in sols:
            cells = []
            for n in seg_t:
                r = by.get(f"mujoco/{s}/{sol}/{it}/time/{n}")
                dag = "†" if r and str(r.get("diverged")) in ("1", "True") else ""
                cells.append(f"{num(r, 'median_us'):.1f} ({num(r, 'mean_us'):.1f}){dag}" if r else "")
            out.append(f"| MuJoCo, {s} | {sol} | {it} | " + " | ".join(cells) + " |")
    for s in softs:
        for sol, it in sols:
            cells = [fmt(num(by.get(f"mujoco/{s}/{sol}/{it}/time/{n}"), "batched_us"), "{:.1f}") for n in seg_t]
            out.append(f"| MuJoCo, {s}, batched | {sol} | {it} | " + " | ".join(cells) + " |")
    names = {"si_10_iterations": "sequential impulse", "direct": "btDirectJointSolver", "mlcp_dantzig": "btMLCPSolver + Dantzig"}
    for kind in ("direct", "si_10_iterations", "mlcp_dantzig"):
        if any(k == kind for k, _ in bench):
            out.append(f"| project | {names[kind]} | 10 | " + " | ".join(fmt(num(bench.get((kind, n)), "wall_us"), "{:.1f}") for n in seg_t) + " |")
    if bench:
        out.append("\nMuJoCo per-call mean / project sequential impulse (wall):\n")
        out.append(head + "\n|" + " --- |" * (3 + len(seg_t)))
        for s in softs:
            for sol, it in sols:
                cells = []
                for n in seg_t:
                    r, b = by.get(f"mujoco/{s}/{sol}/{it}/time/{n}"), bench.get(("si_10_iterations", n))
                    cells.append(f"{num(r, 'mean_us') / num(b, 'wall_us'):.2f}" if r and b else "")
                out.append(f"| MuJoCo, {s} | {sol} | {it} | " + " | ".join(cells) + " |")
    # portal
    if any(r.get("scene") == "portal" for r in rows):
        out.append(f"""
## Portal frame (PortalScene defaults: span 4 m, height 3 m, 2 + 2 + 2 segments, H = 50 kN at the left knee, V = 75 kN at mid-span)

Plastic analysis: the combined mechanism at lambda = 1.0 (hinges base-left, mid-span, knee-right, base-right). In
MuJoCo the frame is one tree from the left base; the right base closes the loop with a `connect` equality at (L, 0)
and a fixed tendon (the sum of the hinge angles: the foot's rotation) with `frictionloss = Mp`. **hold**: load
factor {HOLD_FACTOR} for {HOLD_S:g} s, the largest joint rotation and creep 1-3 s; **collapse**: bisection as for the
cantilever (any joint); **at 1.1**: the load factor 1.1 held until a joint has turned 0.05 rad: the rotations of
the four predicted hinges, the joints that turned at least 20 % of the largest (**mechanism**), the energy residual
(load work - kinetic - dissipated) / load work and the loop closure's gap |foot - (L, 0)|. The project: its ramp (`--scene=portal`, 0.02/s from 0.9) and its hold (`--ramp-rate=0 --load-factor=0.9`).
""")
        out.append("| model | solver | it. | hold: largest [rad] | creep [rad] | collapse factor | at 1.1: base-left / mid-span / knee-right / base-right [rad] | mechanism | residual [%] | gap [m] |\n"
                   "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for s in softs:
            for sol, it in sols:
                h, c, k = (by.get(f"mujoco/{s}/{sol}/{it}/{x}/portal") for x in ("hold", "collapse", "stop"))
                if h:
                    rots = gone(k) or " / ".join(fmt(num(k, f"rot_{x}"), "{:+.3f}") for x in ("base-left", "mid-span", "knee-right", "base-right"))
                    held = f"{gone(h)} | " if gone(h) else f"{fmt(num(h, 'max_rotation_rad'))} | {fmt(num(h, 'creep_rad'))}"
                    factor = c["any_joint_collapse_factor"]
                    if str(c["diverged_runs"]) != "0":
                        factor += f" ({c['diverged_runs']} of {c['runs']} runs diverged)"
                    out.append(f"| MuJoCo, {s} | {sol} | {it} | {held} | {factor} | {rots} | {k.get('mechanism', '')} "
                               f"| {fmt(num(k, 'energy_residual_pct'), '{:+.3f}')} | {fmt(num(k, 'closure_gap_m'), '{:.2g}')} |")
        for s, label in projects:
            h, c = by.get(f"project/{s}/hold/portal"), by.get(f"project/{s}/collapse/portal")
            if h:
                ramp = num(c, "ramp_collapse_factor")
                out.append(f"| project | {label} | 10 | {fmt(num(h, 'max_rotation_rad'))} | {fmt(num(h, 'creep_rad'))} "
                           f"| ramp {fmt(ramp, '{:.4f}') if ramp is not None else 'none'} ({c.get('ramp_mechanism', '')}"
                           f"{', predicted' if str(c.get('mechanism_matches')) == '1' else ', not the predicted mechanism'}; "
                           f"{c.get('solver_fallbacks', 0)} SI fallbacks) | | | | |")
    return "\n".join(out) + "\n"


def summary(by, num, gone):
    """The findings, each number taken from the rows."""
    def hold(key):
        r = by.get(key)
        if not r:
            return "not run"
        return gone(r) or f"tip {num(r, 'tip_sag_m'):.3g} m down, root {num(r, 'root_rotation_rad'):.3g} rad"
    lines = ["## Summary", ""]
    lines.append(f"- Hold at 0.9 Mp/L, 3 s, Newton: MuJoCo's default friction rows, 4 segments: {hold('mujoco/default/Newton/100/hold/4')}; "
                 f"the stiffest rows: 4 segments {hold('mujoco/stiffest/Newton/100/hold/4')}, 8 segments "
                 f"{hold('mujoco/stiffest/Newton/100/hold/8')}, 128 segments {hold('mujoco/stiffest/Newton/100/hold/128')}. "
                 f"btDirectJointSolver, 8 segments: root {fmt(num(by.get('project/direct/hold/8'), 'root_rotation_rad'))} rad, creep "
                 f"{fmt(num(by.get('project/direct/hold/8'), 'creep_rad'))} rad. MuJoCo's frictionloss is a regularised (soft) friction row: "
                 "below Mp it turns at a rate that grows with the load, and none of the softnesses measured holds the cantilever, "
                 "up to impedance 0.9999 (MuJoCo's bound) at the 2-step time constant (the least MuJoCo's refsafe allows); the inner "
                 "joints turn more than the root.")
    first = []
    for soft in SOFTNESS:
        for solver, it in SOLVERS:
            gone_at = [n for n in SEGMENTS_TIMED if num(by.get(f"mujoco/{soft}/{solver}/{it}/hold/{n}"), "diverged_at_s") is not None]
            ran = [n for n in SEGMENTS_TIMED if f"mujoco/{soft}/{solver}/{it}/hold/{n}" in by]
            if ran:
                first.append(f"{soft} {solver} {it}: " + (f"from {min(gone_at)} segments" if gone_at else "none"))
    if first:
        lines.append("- Holds in which MuJoCo found a blown-up acceleration and reset the state (the smallest of 4-128 segments that did): "
                     + "; ".join(first) + ".")
    c4, c8 = by.get("mujoco/stiffest/Newton/100/collapse/4"), by.get("mujoco/stiffest/Newton/100/collapse/8")
    if c4 and c8:
        lines.append(f"- Collapse (root turns 0.05 rad in 1 s), stiffest rows, Newton: {c4['root_collapse_factor']} (4 segments), "
                     f"{c8['root_collapse_factor']} (8) against plastic analysis' 1.0; any joint: {c4['any_joint_collapse_factor']} / "
                     f"{c8['any_joint_collapse_factor']}. btDirectJointSolver: {by.get('project/direct/collapse/8', {}).get('root_collapse_factor', '')} (8).")
    e = by.get("mujoco/stiffest/Newton/100/stop/4")
    if e:
        lines.append(f"- Energy at 1.5 Mp/L, stiffest rows, 4 segments: load work {num(e, 'load_work_J'):.1f} J = kinetic {num(e, 'kinetic_J'):.3g} J "
                     f"+ friction rows {num(e, 'dissipated_J'):.1f} J (residual {num(e, 'energy_residual_pct'):+.3f} %); the root's row "
                     f"{num(e, 'root_dissipated_J'):.1f} J against Mp x its rotation from qpos {num(e, 'root_mp_x_rotation_J'):.1f} J; stops at "
                     f"{num(e, 'stop_rotation_rad'):.4f} rad (plastic analysis {stop_rotation(STOP_FACTOR):.4f}).")
    def same(solver):
        keys = [(f"mujoco/{s}/{solver}/10/hold/{n}", f"mujoco/{s}/{solver}/100/hold/{n}") for s in SOFTNESS for n in SEGMENTS_TIMED]
        keys = [(a, b) for a, b in keys if a in by and b in by]
        return bool(keys) and all(by[a].get("root_rotation_rad") == by[b].get("root_rotation_rad") and
                                  by[a].get("diverged_at_s") == by[b].get("diverged_at_s") for a, b in keys)
    lines.append(f"- Newton's hold figures at 10 iterations are {'the same as' if same('Newton') else 'not all the same as'} at 100; "
                 f"PGS's {'are the same' if same('PGS') else 'differ'}.")
    t = by.get("mujoco/stiffest/Newton/100/time/128")
    b = by.get("bench/si_10_iterations/128")
    if t and b:
        lines.append(f"- Cost, 128 segments: MuJoCo Newton (stiffest rows) {num(t, 'batched_us'):.0f} us per step batched, "
                     f"{num(t, 'median_us'):.0f} us per call; Bullet's sequential impulse at 10 iterations {num(b, 'wall_us'):.0f} us, "
                     f"btDirectJointSolver {num(by.get('bench/direct/128'), 'wall_us'):.0f} us (one run each, this machine).")
    p = by.get("mujoco/stiffest/Newton/100/collapse/portal")
    if p:
        lines.append(f"- Portal frame, stiffest rows, Newton: collapse factor {p['any_joint_collapse_factor']} (plastic analysis 1.0), mechanism "
                     f"{by.get('mujoco/stiffest/Newton/100/stop/portal', {}).get('mechanism', '')}; at MuJoCo's default rows "
                     f"{by.get('mujoco/default/Newton/100/collapse/portal', {}).get('any_joint_collapse_factor', '')}.")
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runner", help="build/bin/structures: the project's cantilever and portal with each solver, same session")
    ap.add_argument("--bench", help="build-bench/bin/game_settings_benchmarks (preset bench): the project's cost per step, same session")
    ap.add_argument("--csv", default="report/structures-mujoco.csv")
    ap.add_argument("--md", default="report/STRUCTURES-MUJOCO.md")
    ap.add_argument("--command", default="bash ci/peer_env.sh python3 ci/models/mujoco_structures.py --runner=build/bin/structures "
                    "--bench=build-bench/bin/game_settings_benchmarks")
    ap.add_argument("--quick", action="store_true", help="one setting (stiff, Newton, 100), 4 segments, no portal (tests)")
    ap.add_argument("--from-csv", metavar="CSV", help="no runs: the report from a CSV this script wrote")
    ap.add_argument("--print-xml", choices=["cantilever", "portal"], help="print the model (4 segments) and stop")
    args = ap.parse_args(argv)
    if args.print_xml:
        print(cantilever_xml(4) if args.print_xml == "cantilever" else portal_xml())
        return 0
    for tool in (args.runner, args.bench):
        if tool and not os.access(tool, os.X_OK):
            print(f"mujoco_structures: {tool} is not an executable file", file=sys.stderr)
            return 2
    if args.from_csv:
        rows = csvfile.read_rows(args.from_csv)
        if not rows:
            print(f"mujoco_structures: {args.from_csv} has no rows", file=sys.stderr)
            return 2
        seconds = float(rows[0]["sweep_s"])
    else:
        rows, seconds = sweep(args)
        for r in rows:
            r["sweep_s"] = f"{seconds:.1f}"
        first = ("key", "peer", "scene", "case", "segments", "softness", "solver", "iterations", "factor")
        csvfile.write_rows(args.csv, rows, first)
        rows = csvfile.read_rows(args.csv)  # the report is made from the CSV, as --from-csv makes it
    csvfile.write_whole(args.md, report(rows, seconds, args.command))
    print(f"{len(rows)} rows {'from ' + args.from_csv if args.from_csv else 'in ' + args.csv}; wrote {args.md}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
