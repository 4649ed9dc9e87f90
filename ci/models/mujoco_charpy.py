#!/usr/bin/env python3
"""The Charpy impact test in MuJoCo: a peer of our Bullet scene, built from the same parameters.

  ci/models/mujoco_charpy.py [--from-runner=build/bin/charpy] [--from-json=FILE] [--NAME=VALUE ...] [--json]
  ci/models/mujoco_charpy.py --list-parameters

The model: the 10 x 10 x 55 mm steel specimen as two rigid halves joined at the notch by a hinge (axis Y,
at mid-ligament) whose `frictionloss` is the plastic moment Mp = fy * b * h^2 / 4 (a rigid-plastic moment:
no rotation below Mp, a moment of Mp while it turns), resting on two anvils and a ledge under each, and the
pendulum hammer (a 0.5 x 0.25 x 0.02 m head of 19.5 kg on a pivot straight above the striker edge) placed
3 mm before the specimen with the impact speed. Geometry by default is ISO 148-1's: a striker edge of
2 mm radius (a capsule along Y at mid-span, a blade of its width behind it), anvils 40 mm apart with 1 mm
edge radius, impact speed 5.25 m/s (the standard's 5.0-5.5 m/s). Axes as in our scene: X horizontal
(the hammer comes from +X), Y up, Z along the specimen; the specimen's back (notch side) at x = 0.

Where the parameters come from, each later source overriding the earlier: the defaults above; the
runner's --json output (--from-runner runs it with its defaults, --from-json reads a saved one or a
parameter dump: a JSON object whose keys are parameter names, or the runner's own keys plastic_moment_Nm
and impact_speed_m_s; other keys are ignored, and so are the stepping ones, dt_s and iterations); the
--NAME=VALUE flags. --list-parameters prints them all with units.

Contacts are as close to our scene's as MuJoCo allows: frictionless (condim 1) unless --friction > 0,
inelastic (critically damped, dampratio 1), as stiff as MuJoCo lets a step be (time constant 2 steps,
impedance 0.99). The hinge's frictionloss row gets the same (solreffriction / solimpfriction).

Measured: the energy lost by the whole system (potential + kinetic of every body, start minus end: the
quantity our runner calls energy_loss_J), the energy lost by the hammer alone, the hinge's dissipated
energy Mp * (accumulated |rotation|), and the analytic Mp * theta_pass for this geometry (theta_pass as in
demos/charpy/CharpySection.cpp, with the anvil edge radius: the corner of a half reaches the tangent point
of the rounded edge when d sin(phi) + L/2 cos(phi) = g/2 + r (1 - sin(phi)), theta_pass = 2 phi). Wall
time covers building the model from its XML and stepping it, like the runner's wall_s (scene + steps).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

GRAVITY_M_S2 = 9.81
MUJOCO_VERSION = "4.0.0"  # the pinned version (ci/peer_env.sh installs it)

# name: (default, unit, what, lower bound, lower bound inclusive)
PARAMETERS = {
    "density_kg_m3": (7800.0, "kg/m^3", "specimen density", 0.0, False),
    "yield_stress_pa": (400e6, "Pa", "yield stress fy", 0.0, False),
    "plastic_moment_nm": (0.0, "N m", "hinge frictionloss; 0 = fy * b * h^2 / 4 of the ligament", 0.0, True),
    "friction": (0.0, "-", "Coulomb friction of every contact (0: frictionless, condim 1)", 0.0, True),
    "specimen_width_m": (0.010, "m", "b: specimen section side", 0.0, False),
    "specimen_length_m": (0.055, "m", "L: specimen length along Z", 0.0, False),
    "notch_depth_m": (0.002, "m", "notch depth at mid-span on the anvil side", 0.0, True),
    "specimen_bottom_y_m": (0.2, "m", "height of the specimen's bottom", -1e9, True),
    "anvil_gap_m": (0.040, "m", "g: open space between the anvils' edges", 0.0, False),
    "anvil_width_m": (0.040, "m", "each anvil along Z", 0.0, False),
    "anvil_edge_radius_m": (0.001, "m", "radius of the anvils' inner edges (0 = sharp)", 0.0, True),
    "striker_radius_m": (0.002, "m", "radius of the striker edge (a capsule along Y); 0 = the thesis' flat nose (a box as thick as the hammer)", 0.0, True),
    "hammer_mass_kg": (19.5, "kg", "hammer head mass", 0.0, False),
    "hammer_length_m": (0.5, "m", "head along X", 0.0, False),
    "hammer_height_m": (0.25, "m", "head along Y", 0.0, False),
    "hammer_thickness_m": (0.02, "m", "head along Z", 0.0, False),
    "hammer_draft_m": (0.04, "m", "striker (capsule and blade) in front of the head", 0.0, False),
    "hammer_arm_length_m": (0.5, "m", "arm from the head to the pivot (no mass, like our scene)", 0.0, True),
    "impact_speed_m_s": (5.25, "m/s", "striker speed at the start, 3 mm before the specimen", 0.0, False),
    "dt_s": (1e-4, "s", "MuJoCo timestep", 0.0, False),
    "iterations": (10, "-", "solver iterations (MuJoCo option iterations)", 1, True),
    "duration_s": (0.06, "s", "simulated time, like the runner's --duration", 0.0, False),
    "contact_timeconst_steps": (2.0, "steps", "solref time constant of contacts and hinge friction, in steps (>= 2)", 2.0, True),
    "contact_impedance": (0.99, "-", "solimp dmin = dmax of contacts and hinge friction (< 1)", 0.0, False),
}
INTEGER_PARAMETERS = {"iterations"}
START_GAP_M = 0.003       # like kStartGap_m in CharpyScene.cpp
NOSE_HEIGHT_M = 0.02      # striker along Y, like kNoseHeight_m
ANVIL_DEPTH_M = 0.04      # anvils along X, like kAnvilDepth_m
# the runner's --json keys that are parameters under another name
# the stepping is the peer's own: a runner's frame step and solver iterations are not taken from its JSON
STEPPING = ("dt_s", "iterations")
RUNNER_KEYS = {"plastic_moment_Nm": "plastic_moment_nm", "impact_speed_m_s": "impact_speed_m_s", "dt": "dt_s"}


class ParameterError(ValueError):
    """A parameter out of range or not a number; the message names it."""


def defaults():
    return {k: v[0] for k, v in PARAMETERS.items()}


def set_parameter(p, name, value):
    """p[name] = value, checked; raises ParameterError naming the parameter."""
    if name not in PARAMETERS:
        raise ParameterError(f"unknown parameter '{name}' (see --list-parameters)")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name}: '{value}' is not a number")
    if not math.isfinite(number):
        raise ParameterError(f"{name}: '{value}' is not a finite number")
    if name in INTEGER_PARAMETERS:
        if number != int(number):
            raise ParameterError(f"{name}: '{value}' is not a whole number")
        number = int(number)
    p[name] = number


def validate(p):
    """Every violated constraint as 'name: value is not ...' text; [] when valid."""
    errors = []
    for name, (_, unit, _, low, inclusive) in PARAMETERS.items():
        v = p[name]
        if v < low or (v == low and not inclusive):
            errors.append(f"{name}: {v:g} {unit} is not {'>=' if inclusive else '>'} {low:g}")
    if p["contact_impedance"] >= 1:
        errors.append(f"contact_impedance: {p['contact_impedance']:g} is not < 1")
    if p["notch_depth_m"] >= p["specimen_width_m"]:
        errors.append(f"notch_depth_m: {p['notch_depth_m']:g} m is not < specimen_width_m ({p['specimen_width_m']:g} m)")
    if p["anvil_gap_m"] >= p["specimen_length_m"]:
        errors.append(f"anvil_gap_m: {p['anvil_gap_m']:g} m is not < specimen_length_m ({p['specimen_length_m']:g} m): nothing to bend over")
    d = p["notch_depth_m"] + (p["specimen_width_m"] - p["notch_depth_m"]) / 2.0
    if p["anvil_gap_m"] / 2.0 <= d:
        errors.append(f"anvil_gap_m: {p['anvil_gap_m']:g} m is not > twice the hinge offset ({2 * d:g} m): the halves never pass")
    if p["striker_radius_m"] >= p["hammer_draft_m"]:
        errors.append(f"striker_radius_m: {p['striker_radius_m']:g} m is not < hammer_draft_m ({p['hammer_draft_m']:g} m)")
    if p["dt_s"] > p["duration_s"]:
        errors.append(f"dt_s: {p['dt_s']:g} s is not <= duration_s ({p['duration_s']:g} s)")
    return errors


def section(p):
    """(Mp [N m], hinge offset d from the back side [m], theta_pass [rad], analytic Mp * theta_pass [J])."""
    b = p["specimen_width_m"]
    h = b - p["notch_depth_m"]
    mp = p["plastic_moment_nm"] or p["yield_stress_pa"] * b * h * h / 4.0
    d = p["notch_depth_m"] + h / 2.0
    half_gap, half_length, r = p["anvil_gap_m"] / 2.0, p["specimen_length_m"] / 2.0, p["anvil_edge_radius_m"]
    lo, hi = 0.0, math.pi / 2.0
    for _ in range(100):  # f rises from half_gap + r - half_length < 0 to half_gap - d > 0: bisect
        mid = 0.5 * (lo + hi)
        f = half_gap + r * (1.0 - math.sin(mid)) - d * math.sin(mid) - half_length * math.cos(mid)
        if f < 0:
            lo = mid
        else:
            hi = mid
    theta = lo + hi
    return mp, d, theta, mp * theta


def hammer_geometry(p):
    """(arm drop from the pivot to the impact line [m], pivot -> head centre (x, y) at impact, inertia about
    the pivot [kg m^2], start angle [rad])."""
    L, H, T, m = p["hammer_length_m"], p["hammer_height_m"], p["hammer_thickness_m"], p["hammer_mass_kg"]
    arm_drop = H / 2.0 + p["hammer_arm_length_m"]
    tip_x = L / 2.0 + p["hammer_draft_m"]
    izz = m * (L * L + H * H) / 12.0
    inertia = izz + m * (tip_x * tip_x + arm_drop * arm_drop)
    start = math.asin(START_GAP_M / arm_drop)
    return arm_drop, (tip_x, -arm_drop), inertia, start, (m * (H * H + T * T) / 12.0, m * (L * L + T * T) / 12.0, izz)


def model_xml(p):
    """The MJCF text of the scene."""
    b, L, y0 = p["specimen_width_m"], p["specimen_length_m"], p["specimen_bottom_y_m"]
    mp, d, _, _ = section(p)
    g, aw, ra = p["anvil_gap_m"], p["anvil_width_m"], p["anvil_edge_radius_m"]
    rs = p["striker_radius_m"]
    arm_drop, (cx, cy), _, start, (ixx, iyy, izz) = hammer_geometry(p)
    y_mid = y0 + b / 2.0
    pivot = (b, y_mid + arm_drop)
    mu = p["friction"]
    condim = 3 if mu > 0 else 1
    tc = p["contact_timeconst_steps"] * p["dt_s"]
    imp = p["contact_impedance"]
    solref = f'solref="{tc:.9g} 1" solimp="{imp:.9g} {imp:.9g} 0.001"'
    # contype/conaffinity: world 1/1, specimen 3/3, hammer 2/2 -> hammer hits the specimen only
    world = []
    for side in (-1.0, 1.0):
        zin = g / 2.0 + ra           # inner z of the anvil's straight faces
        zout = g / 2.0 + aw
        zc = side * (zin + zout) / 2.0
        hz = (zout - zin) / 2.0
        yc, hy = y0 + b / 2.0, 2.0 * b
        world.append(f'<geom name="anvil{side:+.0f}" type="box" pos="{-ANVIL_DEPTH_M / 2:.9g} {yc:.9g} {zc:.9g}" '
                     f'size="{ANVIL_DEPTH_M / 2:.9g} {hy:.9g} {hz:.9g}"/>')
        if ra > 0:
            world.append(f'<geom name="edge{side:+.0f}" type="capsule" fromto="{-ra:.9g} {yc - hy:.9g} {side * zin:.9g} '
                         f'{-ra:.9g} {yc + hy:.9g} {side * zin:.9g}" size="{ra:.9g}"/>')
            world.append(f'<geom name="fill{side:+.0f}" type="box" pos="{-(ANVIL_DEPTH_M + ra) / 2:.9g} {yc:.9g} '
                         f'{side * (g / 2.0 + ra / 2.0):.9g}" size="{(ANVIL_DEPTH_M - ra) / 2:.9g} {hy:.9g} {ra / 2:.9g}"/>')
        world.append(f'<geom name="ledge{side:+.0f}" type="box" pos="{b:.9g} {y0 - 0.01:.9g} {zc:.9g}" size="{b:.9g} 0.01 {hz:.9g}"/>')
    half = L / 4.0
    blade_len = p["hammer_draft_m"] - rs
    if rs > 0:
        striker_geoms = (
            f'<geom name="striker" type="capsule" fromto="{rs:.9g} {-arm_drop - NOSE_HEIGHT_M / 2:.9g} 0 {rs:.9g} {-arm_drop + NOSE_HEIGHT_M / 2:.9g} 0" size="{rs:.9g}" mass="0" contype="2" conaffinity="2"/>\n'
            f'      <geom name="blade" type="box" pos="{rs + blade_len / 2:.9g} {-arm_drop:.9g} 0" size="{blade_len / 2:.9g} {NOSE_HEIGHT_M / 2:.9g} {rs:.9g}" mass="0" contype="2" conaffinity="2"/>')
    else:  # the thesis' flat nose: a box of the draft's length, as thick as the hammer
        striker_geoms = (
            f'<geom name="striker" type="box" pos="{p["hammer_draft_m"] / 2:.9g} {-arm_drop:.9g} 0" size="{p["hammer_draft_m"] / 2:.9g} {NOSE_HEIGHT_M / 2:.9g} {p["hammer_thickness_m"] / 2:.9g}" mass="0" contype="2" conaffinity="2"/>')
    return f"""<mujoco model="charpy-peer">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="{p['dt_s']:.12g}" iterations="{p['iterations']}" gravity="0 {-GRAVITY_M_S2} 0">
    <flag energy="enable"/>
  </option>
  <default>
    <geom condim="{condim}" friction="{mu:.9g} 0.005 0.0001" {solref} margin="0" contype="1" conaffinity="1"/>
    <joint solreffriction="{tc:.9g} 1" solimpfriction="{imp:.9g} {imp:.9g} 0.001"/>
  </default>
  <worldbody>
    {chr(10).join('    ' + w for w in world).strip()}
    <body name="halfA" pos="{b / 2:.9g} {y_mid:.9g} {-half:.9g}">
      <freejoint name="free"/>
      <geom name="specimenA" type="box" size="{b / 2:.9g} {b / 2:.9g} {half:.9g}" density="{p['density_kg_m3']:.9g}" contype="3" conaffinity="3"/>
      <body name="halfB" pos="0 0 {2 * half:.9g}">
        <joint name="notch" type="hinge" axis="0 1 0" pos="{d - b / 2:.9g} 0 {-half:.9g}" frictionloss="{mp:.9g}"/>
        <geom name="specimenB" type="box" size="{b / 2:.9g} {b / 2:.9g} {half:.9g}" density="{p['density_kg_m3']:.9g}" contype="3" conaffinity="3"/>
      </body>
    </body>
    <body name="hammer" pos="{pivot[0]:.9g} {pivot[1]:.9g} 0">
      <joint name="pivot" type="hinge" axis="0 0 1" pos="0 0 0"/>
      <inertial pos="{cx:.9g} {cy:.9g} 0" mass="{p['hammer_mass_kg']:.9g}" diaginertia="{ixx:.9g} {iyy:.9g} {izz:.9g}"/>
      <geom name="head" type="box" pos="{cx:.9g} {cy:.9g} 0" size="{p['hammer_length_m'] / 2:.9g} {p['hammer_height_m'] / 2:.9g} {p['hammer_thickness_m'] / 2:.9g}" mass="0" contype="2" conaffinity="2"/>
      {striker_geoms}
    </body>
  </worldbody>
</mujoco>
""", start


def _hammer_energy(model, data, hammer_id, pivot_dof, inertia_pivot):
    y = data.xipos[hammer_id][1]
    w = data.qvel[pivot_dof]
    return model.body_mass[hammer_id] * GRAVITY_M_S2 * y + 0.5 * inertia_pivot * w * w


def run(p):
    """One run: a dict of results (the same names as the runner's --json where they mean the same)."""
    errors = validate(p)
    if errors:
        raise ParameterError("\n".join(errors))
    import mujoco  # noqa: PLC0415 (only a run needs it)
    import numpy as np  # noqa: PLC0415

    mp, d, theta_pass, analytic = section(p)
    arm_drop, _, inertia_pivot, start_angle, _ = hammer_geometry(p)
    messages = []  # MuJoCo's warnings (it would print them and write MUJOCO_LOG.TXT into the working directory)
    mujoco.set_mju_user_warning(messages.append)
    t0 = time.perf_counter()
    xml, start = model_xml(p)
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    hammer = model.body("hammer").id
    pivot_q = model.jnt_qposadr[model.joint("pivot").id]
    pivot_v = model.jnt_dofadr[model.joint("pivot").id]
    notch_q = model.jnt_qposadr[model.joint("notch").id]
    data.qpos[pivot_q] = start
    data.qvel[pivot_v] = -p["impact_speed_m_s"] / arm_drop  # swings towards -X: negative about +Z
    mujoco.mj_forward(model, data)
    e0 = float(data.energy[0] + data.energy[1])
    h0 = _hammer_energy(model, data, hammer, pivot_v, inertia_pivot)
    steps = int(math.ceil(p["duration_s"] / p["dt_s"] - 1e-9))
    rotation = 0.0
    max_pen = 0.0
    q_prev = float(data.qpos[notch_q])
    qpos = data.qpos
    contact = data.contact
    # through the gap or over the top, told when a half gets wholly behind the anvils' front plane (x < 0),
    # like the runner: by the lowest point of that half then
    anvil_top = p["specimen_bottom_y_m"] + p["specimen_width_m"] / 2.0 + 2.0 * p["specimen_width_m"]
    halves = [(model.body(n).id, model.geom_size[model.geom("specimen" + n[-1]).id]) for n in ("halfA", "halfB")]
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
    passed = [False, False]
    over_top = False
    for _ in range(steps):
        mujoco.mj_step(model, data)
        q = float(qpos[notch_q])
        rotation += abs(q - q_prev)
        q_prev = q
        if data.ncon:
            pen = -float(contact.dist[: data.ncon].min())
            if pen > max_pen:
                max_pen = pen
        for i, (body, size) in enumerate(halves):
            if not passed[i] and data.xpos[body][0] < 0:
                corners = data.xpos[body] + (signs * size) @ data.xmat[body].reshape(3, 3).T
                if corners[:, 0].max() < 0:
                    passed[i] = True
                    over_top = over_top or bool(corners[:, 1].min() > anvil_top)
    mujoco.mj_forward(model, data)
    e_end = float(data.energy[0] + data.energy[1])
    wall = time.perf_counter() - t0
    finite = bool(np.all(np.isfinite(data.qpos)) and np.all(np.isfinite(data.qvel)))
    # MuJoCo resets the state to the model's rest pose when an acceleration blows up (and warns once)
    diverged = int(data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number) > 0
    h_end = _hammer_energy(model, data, hammer, pivot_v, inertia_pivot)
    loss = e0 - e_end
    return {
        "method": "mujoco",
        "mujoco_version": mujoco.__version__,
        "dt": p["dt_s"],
        "iterations": p["iterations"],
        "steps": steps,
        "wall_s": wall,
        "E0_J": e0,
        "E_end_J": e_end,
        "energy_loss_J": loss,
        "hammer_loss_J": h0 - h_end,
        "plastic_work_J": mp * rotation,
        "other_loss_J": loss - mp * rotation,
        "plastic_rotation_rad": rotation,
        "bend_angle_rad": float(qpos[notch_q]),
        "analytic_J": analytic,
        "theta_pass_rad": theta_pass,
        "plastic_moment_Nm": mp,
        "error_pct": 100.0 * (loss - analytic) / analytic,
        "plastic_work_error_pct": 100.0 * (mp * rotation - analytic) / analytic,
        "impact_speed_m_s": p["impact_speed_m_s"],
        "passed_anvils": all(passed),
        "over_the_top": over_top,
        "diverged": diverged,
        "mujoco_warning": messages[0].strip() if messages else "",
        "max_penetration_m": max_pen,
        "finite": finite,
        **{k: p[k] for k in ("friction", "striker_radius_m", "anvil_gap_m", "anvil_edge_radius_m", "hammer_mass_kg")},
    }


def from_runner_json(p, result):
    """Takes every parameter the runner's --json output (or a parameter dump) names: keys equal to a parameter
    name, and the runner's own names in RUNNER_KEYS. Returns the names taken."""
    if not isinstance(result, dict):
        raise ParameterError("runner JSON: not a JSON object")
    taken = []
    for key, value in result.items():
        name = RUNNER_KEYS.get(key, key)
        if name not in PARAMETERS or name in STEPPING:
            continue
        if isinstance(value, bool) or value is None:
            raise ParameterError(f"{name}: '{value}' is not a number")
        set_parameter(p, name, value)
        taken.append(name)
    return taken


def runner_json(runner, extra_flags=()):
    """The last line of `runner --json FLAGS` as a dict."""
    if not os.access(runner, os.X_OK):
        raise ParameterError(f"from-runner: {runner} is not an executable file (build it: cmake --build build --target charpy)")
    done = subprocess.run([runner, "--json", *extra_flags], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise ParameterError(f"from-runner: {runner} exited {done.returncode}: {done.stderr.strip()[:300]}")
    try:
        return json.loads(done.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        raise ParameterError(f"from-runner: {runner} printed no JSON line")


def parse_args(argv):
    """(parameters, options) from the command line; raises ParameterError naming a bad parameter."""
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--from-runner", metavar="RUNNER", help="take Mp, the impact speed and any geometry the runner's --json names")
    parser.add_argument("--from-json", metavar="FILE", help="take parameters from a saved --json line or a parameter dump")
    parser.add_argument("--json", action="store_true", help="print the result as one JSON line")
    parser.add_argument("--list-parameters", action="store_true")
    parser.add_argument("--print-xml", action="store_true", help="print the MJCF model and stop")
    for name, (default, unit, what, _, _) in PARAMETERS.items():
        parser.add_argument("--" + name.replace("_", "-"), dest=name, metavar=unit.upper().replace("/", "_").replace("^", ""),
                            help=f"{what} (default {default:g})")
    args = parser.parse_args(argv)
    p = defaults()
    if args.from_runner:
        from_runner_json(p, runner_json(args.from_runner))
    if args.from_json:
        try:
            with open(args.from_json) as f:
                text = f.read().strip()
            data = json.loads(text.splitlines()[-1] if text.startswith("{") and "\n" in text else text)
        except (OSError, ValueError, IndexError) as e:
            raise ParameterError(f"from-json: {args.from_json}: {e}")
        from_runner_json(p, data)
    for name in PARAMETERS:
        value = getattr(args, name)
        if value is not None:
            set_parameter(p, name, value)
    return p, args


def main(argv=None):
    try:
        p, args = parse_args(argv)
        if args.list_parameters:
            for name, (_, unit, what, _, _) in PARAMETERS.items():
                print(f"--{name.replace('_', '-'):28s} {p[name]:<12g} {unit:7s} {what}")
            return 0
        errors = validate(p)
        if errors:
            raise ParameterError("\n".join(errors))
        if args.print_xml:
            print(model_xml(p)[0])
            return 0
        r = run(p)
    except ParameterError as e:
        print(f"mujoco_charpy: {e}", file=sys.stderr)
        return 2
    if args.json:
        print(json.dumps(r))
    else:
        print(f"MuJoCo {r['mujoco_version']} Charpy peer, dt {r['dt']:g} s, {r['iterations']} iterations: {r['steps']} steps in "
              f"{r['wall_s']:.3f} s\n  energy loss {r['energy_loss_J']:.2f} J (hammer {r['hammer_loss_J']:.2f} J, hinge "
              f"frictionloss work {r['plastic_work_J']:.2f} J over {r['plastic_rotation_rad']:.3f} rad); analytic Mp * theta_pass = "
              f"{r['plastic_moment_Nm']:.2f} N m * {r['theta_pass_rad']:.4f} rad = {r['analytic_J']:.2f} J; error {r['error_pct']:+.2f} %\n"
              f"  passed anvils {'yes' if r['passed_anvils'] else 'no'}{' (over the top)' if r['over_the_top'] else ''}, "
              f"max penetration {r['max_penetration_m']:.3g} m, impact speed {r['impact_speed_m_s']:.3f} m/s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
