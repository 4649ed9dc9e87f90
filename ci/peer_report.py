"""The MuJoCo peer's part of REPORT.md (ci/charpy_report.py calls it): its series in the error-against-run-time
plot and its section of tables, from report/charpy-peer.csv (ci/peer_sweep.py).

Its discretisation error is measured against its own converged run (smallest timestep, most iterations), like
our methods'; its modelling error is that run against the analytic Mp * theta_pass of its own geometry
(analytic_J of its rows: with the anvil edge radius) and against our runner's analytic value. Runs in which
MuJoCo found a blown-up acceleration (it then resets the state to the rest pose and warns) are left out of
the plot and marked in the tables.
"""
import os

from sweep import csvfile

METHOD = "mujoco"


def number(row, column):
    try:
        return float(row[column])
    except (KeyError, TypeError, ValueError):
        return None


def read(path):
    """The peer's rows, or [] when there is no peer CSV."""
    return [r for r in csvfile.read_rows(path) if r.get("method") == METHOD] if path and os.path.exists(path) else []


def converged(peer):
    ok = [r for r in peer if r.get("diverged") != "1" and number(r, "energy_loss_J") is not None and number(r, "dt_ms")]
    return min(ok, key=lambda r: (-(number(r, "iterations") or 0), number(r, "dt_ms")), default=None)


def discretisation_error(row, ref):
    loss, base = number(row, "energy_loss_J"), number(ref, "energy_loss_J") if ref else None
    return None if loss is None or not base else 100.0 * (loss - base) / base


def plot_series(ax, peer):
    """The peer's runs (10 iterations and more) as one series: wall time against discretisation error."""
    ref = converged(peer)
    mine = [r for r in peer if r.get("diverged") != "1" and number(r, "wall_s") and discretisation_error(r, ref) is not None]
    if not mine:
        return
    version = peer[0].get("mujoco_version", "?")
    ax.scatter([max(number(r, "wall_s"), 1e-4) for r in mine], [max(abs(discretisation_error(r, ref)), 1e-2) for r in mine],
               s=40, marker="x", color="k", label=f"MuJoCo {version} peer (hinge frictionloss = Mp)")


# the new-method runs beside the peer: the direct solve with speculative contacts at this contact substep [s], as the
# sweep's contact_substep_s column writes it
COARSE_SUBSTEP = "6e-05"


def section(peer, ours, ours_converged=None):
    """Markdown: the peer beside our plastic-hinge method, per frame step (10 iterations): the default (sequential
    impulse, 0.01 ms contact substeps), the direct solve with speculative contacts at COARSE_SUBSTEP, and sequential
    impulse without substeps. ours_converged (method -> its converged row) gives our runs' discretisation error."""
    if not peer:
        return ""
    ref = converged(peer)
    version = peer[0].get("mujoco_version", "?")
    analytic = number(peer[0], "analytic_J")
    our_analytic = next((number(r, "analytic_J") for r in ours if number(r, "analytic_J")), None)
    f = lambda v, pattern: "" if v is None else pattern.format(v)  # noqa: E731
    mm = lambda column: f(1000 * number(peer[0], column) if number(peer[0], column) is not None else None, "{:g}")  # noqa: E731
    pick = lambda dt, sub, solver="", contacts="": next((r for r in ours if r.get("method") == "plastic-hinge"  # noqa: E731
                                                         and r.get("dt_ms") == dt and r.get("iterations") == "10"
                                                         and r.get("contact_substep_s") == sub and r.get("reference") != "1"
                                                         and (r.get("solver") or "") in ((solver,) if solver else ("", "sequential-impulse"))
                                                         and (r.get("contacts") or "") == contacts), None)
    ours_ref = (ours_converged or {}).get("plastic-hinge")
    disc = lambda r: discretisation_error(r, ours_ref) if r and ours_ref else None  # noqa: E731
    lines = ["| frame step [ms] | peer loss [J] | peer hinge work [J] | peer error vs analytic [%] | peer discretisation error [%] "
             "| peer steps | peer wall [s] | peer passed | ours (plastic-hinge) loss [J] | steps | wall [s] "
             f"| ours direct, speculative, {float(COARSE_SUBSTEP) * 1000:g} ms: loss [J] | discretisation error [%] | steps | wall [s] "
             "| ours without substeps: loss [J] | wall [s] |",
             "|" + "---|" * 17]
    for r in sorted((r for r in peer if r.get("iterations") == "10"), key=lambda r: number(r, "dt_ms")):
        diverged = r.get("diverged") == "1"
        passed = "diverged (reset)" if diverged else ("over the top" if r.get("over_the_top") == "1" else
                                                      ("yes" if r.get("passed_anvils") == "1" else "no"))
        a, b = pick(r["dt_ms"], "1e-05"), pick(r["dt_ms"], "0")
        c = pick(r["dt_ms"], COARSE_SUBSTEP, "direct", "speculative")
        col = lambda row, column, pattern: f(number(row, column) if row else None, pattern)  # noqa: E731
        lines.append(
            f"| {r['dt_ms']} | {f(number(r, 'energy_loss_J'), '{:.1f}')} | {f(number(r, 'plastic_work_J'), '{:.1f}')} "
            f"| {f(number(r, 'error_pct'), '{:+.1f}')} | {'' if diverged else f(discretisation_error(r, ref), '{:+.2f}')} "
            f"| {col(r, 'steps', '{:.0f}')} | {f(number(r, 'wall_s'), '{:.4f}')} | {passed} "
            f"| {col(a, 'energy_loss_J', '{:.1f}')} | {col(a, 'steps', '{:.0f}')} | {col(a, 'wall_s', '{:.4f}')} "
            f"| {col(c, 'energy_loss_J', '{:.1f}')} | {f(disc(c), '{:+.1f}')} | {col(c, 'steps', '{:.0f}')} | {col(c, 'wall_s', '{:.4f}')} "
            f"| {col(b, 'energy_loss_J', '{:.1f}')} | {col(b, 'wall_s', '{:.4f}')} |")
    by_key = {(r["dt_ms"], r["iterations"]): number(r, "energy_loss_J") for r in peer}
    diffs = [abs(v - by_key[(dt, "10")]) for (dt, it), v in by_key.items()
             if it != "10" and v is not None and by_key.get((dt, "10")) is not None]
    ref_text = (f"`{ref['key']}`: {number(ref, 'energy_loss_J'):.1f} J, {number(ref, 'error_pct'):+.1f} % against its analytic "
                f"{analytic:.2f} J" + (f", {100.0 * (number(ref, 'energy_loss_J') - our_analytic) / our_analytic:+.1f} % against our "
                                      f"runner's {our_analytic:.2f} J" if our_analytic else "")) if ref else "none"
    striker_radius = number(peer[0], "striker_radius_m")
    striker = ("the thesis' flat striker nose (a box as thick as the hammer)" if striker_radius == 0
               else f"a striker edge of {mm('striker_radius_m')} mm radius")
    anvils = ("sharp edges" if number(peer[0], "anvil_edge_radius_m") == 0 else f"edges of {mm('anvil_edge_radius_m')} mm radius")
    return f"""

## Peer: MuJoCo {version} (same frame steps, timed the same way)

The same Charpy test in MuJoCo (`ci/models/mujoco_charpy.py`, swept by `ci/peer_sweep.py` into `charpy-peer.csv`, parameters
from {peer[0].get('parameters_from', '?')}): two rigid halves joined at the notch by a hinge whose `frictionloss` is
Mp = {f(number(peer[0], 'plastic_moment_Nm'), '{:.2f}')} N m, {striker}, anvils
{mm('anvil_gap_m')} mm apart with {anvils}, a {f(number(peer[0], 'hammer_mass_kg'), '{:g}')} kg hammer at
{f(number(peer[0], 'impact_speed_m_s'), '{:.2f}')} m/s; contact friction {f(number(peer[0], 'friction'), '{:g}')}, inelastic contacts as
stiff as MuJoCo allows (time constant 2 steps). MuJoCo's timestep is the frame step (no contact substeps). Its analytic Mp * theta_pass
with its anvil edge radius is {f(analytic, '{:.2f}')} J (theta_pass {f(number(peer[0], 'theta_pass_rad'), '{:.4f}')} rad). Converged run
{ref_text}. Hinge work = Mp * accumulated |hinge rotation|. 50 iterations change the peer's loss by at most
{max(diffs) if diffs else 0:.2g} J (MuJoCo's solver converges before either cap). Wall time: building the model and all steps, one run
at a time in one Python process (the MuJoCo call per step included).

{chr(10).join(lines)}"""
