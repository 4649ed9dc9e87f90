#!/usr/bin/env python3
"""Numerical stability on stiff and extreme cases: every case below x methods 1-8, run by the console
runner, each classified by the runner's verdict (demos/charpy/CharpyVerdict.cpp).

  ci/stability.py [--runner=build/bin/charpy] [--runner-double=build-double/bin/charpy]
                  [--out-dir=report] [--jobs=N] [--shard=i/n] [--cases=NAME,...]

Writes OUT_DIR/stability.csv (one row per cell, the numbers behind each verdict) and
OUT_DIR/STABILITY.md (the matrix with symbols and a legend). Resumable like the sweep.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep import csvfile, runner  # noqa: E402

METHODS = ["rigid", "brittle", "spring", "spring2", "hinge-motor", "plastic-hinge", "elastic-plastic", "elastic-plastic2"]
NEW_METHODS = {"plastic-hinge", "elastic-plastic", "elastic-plastic2"}
DEFAULT_E0_J = 283.048663       # hammer energy at the default release angle (charpy --json: E0_J)
DEFAULT_SPEED_M_S = 4.41358004  # its impact speed (impact_speed_m_s)


def speed_flags(v_m_s):
    """Impact speed v through the hammer's energy, which goes with v^2 (the runner reports the real speed)."""
    return [f"--initial-energy={DEFAULT_E0_J * (v_m_s / DEFAULT_SPEED_M_S) ** 2:.6g}"]


# name -> (what it checks, runner flags); the default scene is fy 400 MPa, dt 0.1 ms, 2 parts, 10 iterations.
CASES = {
    "default": ("fy 400 MPa, dt 0.1 ms, 2 parts, 10 iterations, 4.4 m/s", []),
    "fy100": ("yield stress 100 MPa", ["--fy=100e6"]),
    "fy800": ("yield stress 800 MPa (thesis fig. 3.5: spring explodes)", ["--fy=800e6"]),
    "fy2000": ("yield stress 2000 MPa", ["--fy=2000e6"]),
    "dt0.01ms": ("frame step 0.01 ms", ["--dt=1e-5"]),
    "dt1ms": ("frame step 1 ms", ["--dt=1e-3"]),
    "dt16.7ms": ("frame step 1/60 s", ["--dt=0.0166667"]),
    "dt33ms": ("frame step 33 ms", ["--dt=0.033"]),
    "dt1ms-nosub": ("frame step 1 ms, no contact substeps", ["--dt=1e-3", "--contact-substep=0"]),
    "dt16.7ms-nosub": ("frame step 1/60 s, no contact substeps (thesis: tunnelling)", ["--dt=0.0166667", "--contact-substep=0"]),
    "parts4": ("4 specimen parts", ["--parts=4"]),
    "parts8": ("8 parts", ["--parts=8"]),
    "parts16": ("16 parts", ["--parts=16"]),
    "parts32": ("32 parts (hammer : part mass about 1.4e5)", ["--parts=32"]),
    "v1": ("impact speed 1 m/s", speed_flags(1)),
    "v10": ("impact speed 10 m/s", speed_flags(10)),
    "v20": ("impact speed 20 m/s", speed_flags(20)),
    "v50": ("impact speed 50 m/s", speed_flags(50)),
    "it1": ("1 solver iteration", ["--iterations=1"]),
    "it100": ("100 solver iterations", ["--iterations=100"]),
    "slender": ("slender specimen 5 x 5 x 55 mm, 1 mm notch", ["--specimen-width=0.005", "--notch-depth=0.001"]),
    "nohammer": ("no hammer: the specimen under gravity only", ["--hammer-thickness=0"]),
    "stiff-E": ("elastic stiffness E = 2000 GPa (10x steel)", ["--youngs-modulus=2000e9"]),
    # the same numerics with btDirectJointSolver (patch 0019), which solves the specimen's joints and contacts together
    "direct": ("default scene, solver btDirectJointSolver", ["--solver=direct"]),
    "direct-dt1ms-nosub": ("frame step 1 ms, no contact substeps, direct solver", ["--solver=direct", "--dt=1e-3", "--contact-substep=0"]),
    "direct-dt0.1ms-nosub": ("frame step 0.1 ms, no contact substeps, direct solver", ["--solver=direct", "--contact-substep=0"]),
    "direct-dt16.7ms-nosub": ("frame step 1/60 s, no contact substeps, direct solver", ["--solver=direct", "--dt=0.0166667", "--contact-substep=0"]),
    "direct-parts8": ("8 parts, direct solver", ["--solver=direct", "--parts=8"]),
    "direct-parts16": ("16 parts, direct solver", ["--solver=direct", "--parts=16"]),
    "direct-parts32": ("32 parts, direct solver", ["--solver=direct", "--parts=32"]),
    # Bullet's own continuous collision detection on the parts (the hammer, a compound, cannot have it)
    "ccd-dt1ms-nosub": ("frame step 1 ms, no contact substeps, Bullet's CCD on the parts",
                        ["--dt=1e-3", "--contact-substep=0", "--ccd-motion-threshold=1e-3", "--ccd-swept-radius=4e-3"]),
    "ccd-dt16.7ms-nosub": ("frame step 1/60 s, no contact substeps, Bullet's CCD on the parts",
                           ["--dt=0.0166667", "--contact-substep=0", "--ccd-motion-threshold=1e-3", "--ccd-swept-radius=4e-3"]),
    # the direct solver with speculative box-box contacts (patch 0036)
    "direct-spec": ("default scene, direct solver, speculative contacts", ["--solver=direct", "--speculative-contacts"]),
    "direct-spec-sub0.06ms-dt16.7ms": ("frame step 1/60 s, contact substep 0.06 ms, direct solver, speculative contacts",
                                       ["--solver=direct", "--speculative-contacts", "--dt=0.0166667", "--contact-substep=6e-5"]),
    "direct-spec-dt1ms-nosub": ("frame step 1 ms, no contact substeps, direct solver, speculative contacts",
                                ["--solver=direct", "--speculative-contacts", "--dt=1e-3", "--contact-substep=0"]),
    # no contact substeps of the runner's: the world cuts its own steps where a pair in or near contact would move more
    # than the speculative reach (patch 0053, --world-contact-travel)
    "world-dt1ms": ("frame step 1 ms, no contact substeps, the world's contact stepping (0.3 mm), direct solver, speculative contacts",
                    ["--solver=direct", "--speculative-contacts", "--dt=1e-3", "--contact-substep=0", "--world-contact-travel=3e-4"]),
    "world-dt16.7ms": ("frame step 1/60 s, no contact substeps, the world's contact stepping (0.3 mm), direct solver, speculative "
                       "contacts",
                       ["--solver=direct", "--speculative-contacts", "--dt=0.0166667", "--contact-substep=0", "--world-contact-travel=3e-4"]),
    "world-dt1ms-parts32": ("32 parts, frame step 1 ms, no contact substeps, the world's contact stepping (0.14 mm, their reach), "
                            "direct solver, speculative contacts",
                            ["--solver=direct", "--speculative-contacts", "--dt=1e-3", "--contact-substep=0", "--world-contact-travel=1.4e-4",
                             "--parts=32"]),
    "world-dt0.1ms-step16.7ms": ("frame step 0.1 ms gathered into the world's fixed 1/60 s steps, no contact substeps, the world's "
                                 "contact stepping (0.3 mm), direct solver, speculative contacts",
                                 ["--solver=direct", "--speculative-contacts", "--dt=1e-4", "--contact-substep=0",
                                  "--world-contact-travel=3e-4", "--world-step=0.0166667"]),
    "world-dt16.7ms-parts32": ("32 parts, frame step 1/60 s, no contact substeps, the world's contact stepping (0.14 mm), direct "
                               "solver, speculative contacts",
                               ["--solver=direct", "--speculative-contacts", "--dt=0.0166667", "--contact-substep=0",
                                "--world-contact-travel=1.4e-4", "--parts=32"]),
    "world-dt16.7ms-it1": ("1 solver iteration, frame step 1/60 s, no contact substeps, the world's contact stepping (0.3 mm), direct "
                           "solver, speculative contacts",
                           ["--solver=direct", "--speculative-contacts", "--dt=0.0166667", "--contact-substep=0", "--world-contact-travel=3e-4",
                            "--iterations=1"]),
    "world-si-dt1ms": ("frame step 1 ms, no contact substeps, the world's contact stepping (0.3 mm), sequential impulse, speculative "
                       "contacts",
                       ["--speculative-contacts", "--dt=1e-3", "--contact-substep=0", "--world-contact-travel=3e-4"]),
    "world-si-dt16.7ms": ("frame step 1/60 s, no contact substeps, the world's contact stepping (0.3 mm), sequential impulse, "
                          "speculative contacts",
                          ["--speculative-contacts", "--dt=0.0166667", "--contact-substep=0", "--world-contact-travel=3e-4"]),
    # issue 25's coarse setting: 0.03 ms contact substeps, frames gathered out of contact into steps of up to 5 ms
    "direct-spec-sub0.03ms-free-dt16.7ms": ("frame step 1/60 s, contact substep 0.03 ms, free step 5 ms, direct solver, speculative contacts",
                                            ["--solver=direct", "--speculative-contacts", "--dt=0.0166667", "--contact-substep=3e-5",
                                             "--free-step=5e-3"]),
    "direct-spec-sub0.03ms-free-dt16.7ms-parts32": ("32 parts, frame step 1/60 s, contact substep 0.03 ms, free step 5 ms, direct solver, "
                                                    "speculative contacts",
                                                    ["--solver=direct", "--speculative-contacts", "--dt=0.0166667", "--contact-substep=3e-5",
                                                     "--free-step=5e-3", "--parts=32"]),
    "direct-spec-parts4": ("4 parts, direct solver, speculative contacts", ["--solver=direct", "--speculative-contacts", "--parts=4"]),
    "direct-spec-parts8": ("8 parts, direct solver, speculative contacts", ["--solver=direct", "--speculative-contacts", "--parts=8"]),
    "direct-spec-parts16": ("16 parts, direct solver, speculative contacts", ["--solver=direct", "--speculative-contacts", "--parts=16"]),
    "direct-spec-parts32": ("32 parts, direct solver, speculative contacts", ["--solver=direct", "--speculative-contacts", "--parts=32"]),
    # an edge of a box lying nearly across a face touches it at both ends (patch 0042, opt-in)
    "direct-edges-parts8": ("8 parts, direct solver, box edges across faces", ["--solver=direct", "--box-edges-across-faces", "--parts=8"]),
    "direct-edges-parts16": ("16 parts, direct solver, box edges across faces", ["--solver=direct", "--box-edges-across-faces", "--parts=16"]),
    "direct-edges-parts32": ("32 parts, direct solver, box edges across faces", ["--solver=direct", "--box-edges-across-faces", "--parts=32"]),
    "direct-spec-edges-parts16": ("16 parts, direct solver, speculative contacts, box edges across faces",
                                  ["--solver=direct", "--speculative-contacts", "--box-edges-across-faces", "--parts=16"]),
}
DOUBLE_CASES = {
    "double": ("default scene, BT_USE_DOUBLE_PRECISION build", []),
    "double-dt16.7ms": ("1/60 s, double precision", ["--dt=0.0166667"]),
}
# The new method on every case above: btDirectJointSolver, speculative contacts and the world's own contact steps
# (patch 0053) instead of the runner's substeps, with one travel for every case, within the smallest speculative
# reach of any of them (the 1.7 mm parts of parts32 reach 0.142 mm; the 2-part specimen 0.309 mm). The -nosub
# cases are their plain cases here (no substeps either way), so they are left out.
NEW_METHOD_FLAGS = ["--solver=direct", "--speculative-contacts", "--contact-substep=0", "--world-contact-travel=1.4e-4"]


def new_method_cases(table):
    return {f"new-{name}": (f"{what}; the new method", [f for f in flags if not f.startswith("--contact-substep")] + NEW_METHOD_FLAGS)
            for name, (what, flags) in table.items()
            if not name.startswith(("direct", "ccd", "world")) and not name.endswith("-nosub")}


CASES.update(new_method_cases(CASES))
DOUBLE_CASES.update(new_method_cases(DOUBLE_CASES))
SYMBOLS = {"stable": "✓", "energy-gain": "↑E", "nan": "NaN", "blow-up": "✗", "tunnelling": "⇢", "came-apart": "⊘", "": "?"}
ACCURACY_SYMBOLS = {"did-not-pass": "⊥", "over-the-top": "⊤", "penetrated": "◐"}
CONVERGED_TOLERANCE = 0.05  # a stable run's loss more than 5 % from the converged (default) run of its method


# cases that change only the numerics (step, substeps, parts, iterations, stiffness of rigid-plastic joints,
# precision): the same specimen and impact, so the same converged loss as the default case
NUMERIC_PREFIXES = ("dt", "parts", "it", "stiff-E", "double", "direct", "ccd", "world")


def reference_case(case):
    """The converged run a case is compared with: the default case in its precision (the new method's cases: the new
    method's default case); None for a case that changes the physics (yield stress, speed, geometry), which has no
    converged run in the matrix."""
    prefix = "new-" if case.startswith("new-") else ""
    if not case[len(prefix):].startswith(NUMERIC_PREFIXES):
        return None
    return prefix + ("double" if case in DOUBLE_CASES else "default")


def accuracy(row, by_key):
    """(symbols, reason) of a stable run's accuracy; ('', '') when accurate or not stable."""
    if row.get("failure") or row.get("verdict") != "stable":
        return "", ""
    marks, reasons = "", []
    acc = row.get("accuracy", "")
    if acc in ACCURACY_SYMBOLS:
        marks += ACCURACY_SYMBOLS[acc]
        reasons.append(f"{acc}: {row.get('accuracy_reason', '')}")
    ref = by_key.get(f"{reference_case(row['case'])}/{row['method']}") if reference_case(row["case"]) else None
    if ref and not ref.get("failure") and ref is not row:
        loss, converged = float(row["energy_loss_J"]), float(ref["energy_loss_J"])
        if converged > 0 and abs(loss - converged) > CONVERGED_TOLERANCE * converged:
            marks += "≠"
            reasons.append(f"loss {loss:.1f} J is {100 * (loss - converged) / converged:+.0f} % off the default run's "
                           f"{converged:.1f} J of `{ref['key']}`")
    return marks, "; ".join(reasons)


def configurations(case_names, double_runner):
    out = []
    for case in case_names:
        table = DOUBLE_CASES if case in DOUBLE_CASES else CASES
        what, flags = table[case]
        # the direct solver's cases are issue 25's cells: the plastic methods (a chain of 32 brittle joints takes it
        # 60-80 ms a step, which the matrix does not wait for); the CCD cases measure Bullet's CCD for the same methods
        for method in (METHODS[4:] if case.startswith(("direct", "ccd", "world", "new-")) else METHODS):
            # the whole duration: a run may blow up after the specimen has passed the anvils
            c = {"key": f"{case}/{method}", "case": case, "method": method, "flags": [f"--method={method}", "--full-duration"] + flags}
            if case in DOUBLE_CASES:
                c["runner"] = double_runner
            out.append(c)
    return out


def write_markdown(rows, case_names, path, command):
    by_key = {r["key"]: r for r in rows}
    lines = [
        "# Numerical stability on stiff and extreme cases",
        "",
        f"Generated by `{command}`. Each cell is one run of the console runner with the case's flags;",
        "the numbers behind each verdict are in `stability.csv` (verdict_reason, max_energy_gain_J,",
        "max_booked_excess_J, max_speed_m_s, max_distance_m, max_penetration_m, energy_loss_J, plastic_work_J).",
        "",
        "Legend: ✓ stable · ↑E energy gain (total energy more than 1 % of E0 above E0, or, methods 6-8, the",
        "plastic work the joints booked more than 1 % of E0 beyond the energy lost at some time: flow no force",
        "paid for, `max_booked_excess_J`) · NaN NaN/inf ·",
        "✗ blow-up (a body faster than max(100 m/s, 20 x impact speed), or farther than that speed carries it in the run and 20 m) ·",
        "⇢ tunnelling (a rigid specimen passed the anvils, or the hammer swung through losing < 5 % of Mp*theta_pass) ·",
        "⊘ came apart (methods 6-8: the unbroken specimen passed the anvils bent less than half of theta_pass end",
        "to end, with plastic work less than half of the energy lost: its joints let go in the solver).",
        "Accuracy of a stable run, beside its symbol: ⊥ did not pass the anvils · ⊤ went over the anvils, not",
        "through the gap · ◐ a contact penetrated more than 10 % of the specimen width · ≠ the loss is more than",
        "5 % off the default run of the same method (the default case, in the same precision; it is not the converged loss, which report/REPORT.md gives).",
        "Cells show the symbols and the energy loss in J.",
        "",
        "| case | " + " | ".join(METHODS) + " |",
        "|---|" + "---|" * len(METHODS),
    ]
    def cell(r):
        if not r:
            return ""
        if r.get("failure"):
            return "run failed"
        marks, _ = accuracy(r, by_key)
        return f"{SYMBOLS.get(r.get('verdict', ''), '?')}{marks} {float(r['energy_loss_J']):.0f}"

    new_cases = [c for c in case_names if c.startswith("new-")]
    for case in case_names:
        if case in new_cases:
            continue
        what = (DOUBLE_CASES.get(case) or CASES[case])[0]
        lines.append(f"| {case}: {what} | " + " | ".join(cell(by_key.get(f"{case}/{m}")) for m in METHODS) + " |")
    if new_cases:
        new_rows = [by_key[f"{c}/{m}"] for c in new_cases for m in METHODS[5:] if f"{c}/{m}" in by_key]
        # accurate, or in front of the anvils where the case changes the physics (no converged run to be off)
        held = [r for r in new_rows if not r.get("failure") and r.get("verdict") == "stable"
                and accuracy(r, by_key)[0] in ("", "⊥" if reference_case(r["case"]) is None else "")]
        lines += ["", "## The new method on every case", "",
                  "Each case above but the solver and contact variants (and the -nosub cases, which are their plain cases",
                  f"here) run with `{' '.join(NEW_METHOD_FLAGS)}`: the specimen's joints",
                  "and contacts in one direct solve (btDirectJointSolver, patch 0019), speculative contacts (patch 0036)",
                  "and the world's own internal steps within which no pair in or near contact moves more than 0.14 mm",
                  "(patch 0053) in place of the runner's contact substeps; one travel for every case, within the smallest",
                  "reach of any (the 1.7 mm parts of parts32: 0.142 mm). ≠ is against this table's default case. Each cell:",
                  "symbols and the energy loss in J; the last column the internal steps to the 60 ms end.",
                  f"Methods 6-8: {len(held)} of {len(new_rows)} cells stable and accurate (⊥ only where the case changes",
                  "the physics so that the hammer cannot break through: fy800, fy2000, v1, nohammer).", "",
                  "| case | " + " | ".join(METHODS[4:]) + " | steps |", "|---|" + "---|" * (len(METHODS[4:]) + 1)]
        for case in new_cases:
            what = (DOUBLE_CASES.get(case) or CASES[case])[0].replace("; the new method", "")
            steps = [int(r["steps"]) for m in METHODS[4:] for r in [by_key.get(f"{case}/{m}")]
                     if r and r.get("steps") not in (None, "")]
            span = (f"{min(steps)}" if min(steps) == max(steps) else f"{min(steps)}-{max(steps)}") if steps else ""
            lines.append(f"| {case}: {what} | " + " | ".join(cell(by_key.get(f"{case}/{m}")) for m in METHODS[4:])
                         + f" | {span} |")
    bad = [r for r in rows if r["method"] in NEW_METHODS and r.get("verdict") != "stable"]
    lines += ["", "## Cells where a new constraint (methods 6-8) is not stable", ""]
    if bad:
        lines += [f"- `{r['key']}`: {r.get('verdict', r.get('failure'))}: {r.get('verdict_reason', '')}" for r in bad]
        # the same case and method under the new method (the -nosub and ccd cases: their plain case there)
        def counterpart(r):
            plain = r["case"][len("ccd-"):] if r["case"].startswith("ccd-") else r["case"]
            plain = plain[:-len("-nosub")] if plain.endswith("-nosub") else plain
            return by_key.get(f"new-{plain}/{r['method']}")
        pairs = [(r, counterpart(r)) for r in bad if not r["case"].startswith("new-")]
        held = [(r, n) for r, n in pairs if n and n.get("verdict") == "stable"]
        if pairs:
            lines += ["", f"The same case and method under the new method (the section above; a -nosub or ccd case as its plain case): "
                      f"{len(held)} of {len(pairs)} stable"
                      + (": " + "; ".join(f"`{n['key']}` {float(n['energy_loss_J']):.1f} J" for _, n in held) if held else "") + "."]
        if any(r["case"].endswith("-nosub") for r in bad):
            lines += ["", "Cases ending in -nosub are runs with the contact substeps switched off (`--contact-substep=0`):",
                      "the hammer's striker moves 4.4 mm (1 ms) or 74 mm (1/60 s) per step against a 10 mm specimen",
                      "and 7.5 mm of anvil overlap, so contacts are found too late, whatever the joint. With the",
                      "default substeps the same frame steps are stable (cases dt1ms, dt16.7ms, dt33ms)."]
        gains = [r for r in bad if r.get("verdict") == "energy-gain"]
        if gains:
            direct = [r for r in rows if r["case"].startswith("direct") and r["method"] in NEW_METHODS and not r.get("failure")]
            worst = max((float(r.get("max_booked_excess_J") or 0) for r in direct), default=0)
            lines += ["", "Energy gains of the new constraints"
                      + (" are all under sequential impulse" if all(not r["case"].startswith("direct") for r in gains) else "")
                      + ": its contacts keep their Baumgarte correction as",
                      "velocity (its split pass takes only penetrations past 4 cm), energy no force paid for, and the",
                      "yielding joints book the flow it makes. The direct solve moves the correction to the positions",
                      "(patch 0038) and books its flow only as far as the losses of the call pay for it (patch 0041):",
                      f"the most any direct case books beyond its loss is {worst:.2g} J."]
        if any(r.get("verdict") == "came-apart" and not r["case"].endswith("-nosub") for r in bad):
            lines += ["", "Came apart with the default substeps: many light parts (at 32 parts each is 1.7 mm long and",
                      "weighs 1.3 g) under the 19.5 kg hammer. The solver's iterations do not hold such a chain, the",
                      "parts are pushed apart without bending, and the joints book little or no plastic work for it,",
                      "since they book only what they did at their cap."]
    else:
        lines.append("None.")
    ccd = [c for c in case_names if c.startswith("ccd-")]
    if ccd:
        lines += ["", "Cases starting with ccd are the same runs with Bullet's own continuous collision detection on the",
                  "specimen's parts (`--ccd-motion-threshold`, `--ccd-swept-radius`: a part whose centre moves more than",
                  "the threshold in a step is swept as a sphere from its centre; where the sweep meets a surface the step",
                  "moves it more than the allowed penetration into, which the scene sets to the parts' 0.5 mm margin",
                  "instead of Bullet's 0.04 m, the part is stopped there and given a predictive contact). The hammer",
                  "cannot have it: Bullet sweeps convex shapes only, and the hammer is a compound. Each cell against",
                  "the same case without CCD:", ""]
        for case in ccd:
            plain = case[len("ccd-"):]
            pairs = []
            for m in METHODS[4:]:
                a, b = by_key.get(f"{case}/{m}"), by_key.get(f"{plain}/{m}")
                if not a or not b or a.get("failure") or b.get("failure"):
                    continue
                same = (a.get("energy_loss_J") == b.get("energy_loss_J") and a.get("plastic_work_J") == b.get("plastic_work_J")
                        and a.get("steps") == b.get("steps"))
                pairs.append(f"{m} {float(a['energy_loss_J']):.2f} J against {float(b['energy_loss_J']):.2f} J"
                             + (" (the same steps, loss and plastic work)" if same else ""))
            lines.append(f"- `{case}` ({' '.join(CASES[case][1][-2:])}): " + ("; ".join(pairs) if pairs else "no pair run") + ".")
    if any(c.startswith("direct") for c in case_names):
        lines += ["", "Cases starting with direct are the same runs with `--solver=direct` (btDirectJointSolver, patch",
                  "0019), which solves the specimen's joints and its contacts with the hammer and the anvils in one",
                  "direct solve: the 21 g halves between the 19.5 kg hammer and the anvils are held whatever their mass",
                  "ratio, where sequential impulse's iterations move each by its mass over the hammer's an iteration.",
                  "Cases starting with direct-spec add `--speculative-contacts` (patch 0036): box pairs get contacts",
                  "before they overlap, within the contact breaking threshold (0.3 mm for the specimen's boxes), so no",
                  "part sinks into an anvil within a step that closes less than that; with them a part's edge across a",
                  "face touches it at both ends (patch 0042, as `--box-edges-across-faces` in the direct-edges cases)",
                  "and the world is stepped to the striker's touch, so `direct-spec-edges-parts16` is `direct-spec-parts16`.",
                  "The direct-spec-sub0.03ms-free cases are issue 25's coarse setting at 1/60 s frames: 0.03 ms contact",
                  "substeps, and out of contact frames gathered into steps of up to 5 ms (`--free-step`); the whole 60 ms",
                  "run takes 93 internal steps in two parts and 104-108 in 32 (`steps` in stability.csv)."]
    world = [c for c in case_names if c.startswith("world-")]
    if world:
        steps = [int(r["steps"]) for r in rows if r["case"] in world and r.get("steps") not in (None, "")]
        lines += ["", "Cases starting with world turn the runner's contact substeps off (`--contact-substep=0`) and have the",
                  "world cut its own internal steps instead (`--world-contact-travel`, btDiscreteDynamicsWorld::",
                  "setContactStepping, patch 0053): each frame is cut into steps within which no pair in or near contact",
                  "moves more than the travel (by a bound of its relative motion: a compound's children one by one, the",
                  "points of one near the other, the closing along their boxes' axes, their contacts' normals and their",
                  "nearest direction; the forces of the step are not in it but for the spin a body lost in the last two steps),",
                  "here the speculative contacts' reach, so that they hold what closes in a step; far from contact the frame is",
                  "one step; `--world-step` gathers short frames into the world's fixed steps (upstream's fixed-step",
                  "`stepSimulation`). The runner's `--free-step`, touch and release steps are not used." + (f" They take {min(steps)}-{max(steps)} internal steps to the 60 ms end (`steps`" if steps else ""),
                  "in stability.csv). Cases starting with world-si do so under sequential impulse."]
    inaccurate, stopped = [], []
    for r in rows:
        if r["method"] not in METHODS[4:]:
            continue
        marks, reason = accuracy(r, by_key)
        if marks == "⊥":
            stopped.append(f"`{r['key']}`")
        elif marks:
            inaccurate.append(f"- `{r['key']}`: {reason}")
    lines += ["", "## Stable but not accurate (methods 5-8)", "",
              "Over the anvils instead of through the gap, a contact deeper than 10 % of the specimen, or, in cases",
              "that change only the numerics, a loss more than 5 % off the default case of the same method:", ""]
    lines += inaccurate or ["None."]
    lines += ["", "Stable runs in which the unbroken specimen did not pass the anvils (no fracture energy to compare;",
              "physical where the hammer's energy is short of what the section needs, e.g. fy800, fy2000, v1, nohammer): "
              + (", ".join(stopped) if stopped else "none") + "."]
    lines += ["", "## Energy bookkeeping of the new constraints", "",
              "Cells (methods 6-8) where the plastic work they report disagrees with the energy balance at the end:",
              "more than 105 % of the energy lost, or none although the specimen passed the anvils. An excess at",
              "any time above 1 % of E0 is already an energy gain in the verdict (above).", ""]
    book = []
    for r in rows:
        if r["method"] not in NEW_METHODS or r.get("failure"):
            continue
        work, loss = float(r["plastic_work_J"]), float(r["energy_loss_J"])
        if work > 1.05 * max(loss, 0) + 1e-6 or (work == 0 and r.get("passed_anvils") in ("1", "True")):
            book.append(f"- `{r['key']}`: plastic work {work:.1f} J, energy loss {loss:.1f} J")
    lines += book or ["None."]
    upstream = [r for r in rows if r["method"] not in NEW_METHODS and r.get("verdict") not in ("stable", None)]
    lines += ["", "## Upstream methods (1-5) that are not stable, as they are", ""]
    lines += [f"- `{r['key']}`: {r['verdict']}: {r.get('verdict_reason', '')}" for r in upstream] or ["None."]
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)
    return bad


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runner", default="build/bin/charpy")
    parser.add_argument("--runner-double", default="", help="a charpy built with BP_USE_DOUBLE_PRECISION=ON")
    parser.add_argument("--out-dir", default="report")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--shard", default="1/1")
    parser.add_argument("--cases", default="", help="comma-separated case names (default: all)")
    parser.add_argument("--command", default="bash ci/stability.sh")
    args = parser.parse_args(argv)
    names = [c for c in args.cases.split(",") if c] or list(CASES) + (list(DOUBLE_CASES) if args.runner_double else [])
    unknown = [c for c in names if c not in CASES and c not in DOUBLE_CASES]
    if unknown:
        parser.error(f"--cases: unknown {', '.join(unknown)} (valid: {', '.join(list(CASES) + list(DOUBLE_CASES))})")
    if any(c in DOUBLE_CASES for c in names) and not args.runner_double:
        parser.error("--cases: the double-precision cases need --runner-double=PATH")
    todo = runner.in_shard(configurations(names, args.runner_double), runner.parse_shard(args.shard))
    csv_path = os.path.join(args.out_dir, "stability.csv")
    rows = runner.run_all(args.runner, todo, csv_path, args.jobs, first_columns=("key", "case", "method", "verdict", "verdict_reason", "accuracy", "accuracy_reason"))
    bad = write_markdown(rows, names, os.path.join(args.out_dir, "STABILITY.md"), args.command)
    print(f"{len(rows)} cells in {csv_path}; new constraints not stable in {len(bad)} cells")
    return 0


if __name__ == "__main__":
    sys.exit(main())
