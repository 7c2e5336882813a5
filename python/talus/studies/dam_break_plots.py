"""Figures of the dam-break study (Huet et al. 2021) and of the hopper validation (Appendix B 2)
from results folders, as PNG files in the folder.

Usage: python3 -m talus plot DIR [--snapshot-times T1,T2,...]
  DIR a dam-break run   runout and height profiles (Fig. 5), speeds (Fig. 12), force network
                        (Fig. 14), force PDF (Fig. 15), fabric rose (Fig. 17), side snapshots (Figs. 6-8, needs
                        run.vtk_interval; times in s after the gate opened, default 0, 1, 2, 3, 5
                        and 8 tau_c), energies
  DIR an ensemble       every run's speed curve (Figs. 12-13), force PDF and fabric averaged over
                        the runs (Figs. 15, 17), runout and height ratios per run (Figs. 10-11)
  DIR a sweep           flow map (Fig. 9), runout ratio (Fig. 10), height ratio (Fig. 11),
                        centre-of-mass ratio (Fig. 24) against a; repose angle against the swept
                        value for a hopper sweep (Fig. 23)
  DIR a hopper run      the pile's surface profile with the fitted flanks"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from . import plot_timeseries
from .channel_runout_fits import CHANNEL_RUNOUT_FITS

MARKERS = {"collapsed": ("o", "tab:blue"), "fractured": ("s", "tab:green"), "stable": ("^", "tab:orange")}


def read_csv(path: Path):
    return np.genfromtxt(path, delimiter=",", names=True, ndmin=1)


def save(fig, path: Path) -> None:
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(path)


# The channel experiments Huet et al. 2021 compare with in Fig. 10 (channel_runout_fits.py), each
# branch drawn on its own range only.
def channel_runout_lines(ax, a_max: float) -> None:
    for fit, colour in zip(CHANNEL_RUNOUT_FITS, ("k", "tab:gray")):
        for branch, style in (("linear", "--"), ("power", ":")):
            a, y = fit.curve(branch, a_max)
            if a:
                ax.plot(a, y, style, color=colour, lw=1, label=fit.label(branch).replace("a^(2/3)", r"a$^{2/3}$"))


# ---------------------------------------------------------------- one dam-break run
def profiles(folder: Path, summary: dict) -> None:
    """Huet et al. 2021, Fig. 5: top-view column intensity with L_inf, and the height profile."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    runout = read_csv(folder / "runout_profile.csv")
    left.plot(runout["x"] * 100, runout["intensity"], "k-", label="column intensity")
    for key, style, label in [("runout", "--", "L$_\\infty$ (10 %)"), ("runout_low", ":", "20 %"), ("runout_high", "-.", "1 %")]:
        if key in summary:
            left.axvline(summary[key] * 100, color="tab:red", ls=style, label=label)
    left.axvline(summary.get("L0", 0) * 100, color="grey", lw=0.8, label="L$_0$")
    left.set_xlabel("x (cm)")
    left.set_ylabel("occupied fraction of the pixel column")
    left.legend(fontsize=8)
    heights = read_csv(folder / "height_profile.csv")
    right.plot(heights["y"] * 100, heights["initial_height"] * 100, color="grey", label="initial")
    right.plot(heights["y"] * 100, heights["final_height"] * 100, "k-", label="final")
    for key, style in [("final_height", "--"), ("final_height_q1", ":"), ("final_height_q3", ":")]:
        if key in summary:
            right.axhline(summary[key] * 100, color="tab:red", ls=style, lw=1)
    right.set_xlabel("y (cm)")
    right.set_ylabel("height (cm)")
    right.set_title("mean H$_\\infty$ (dashed), quartiles (dotted)", fontsize=9)
    right.legend(fontsize=8)
    save(fig, folder / "fig05_runout_height_profiles.png")


def speeds(ax, folder: Path, **style) -> None:
    data = read_csv(folder / "collapse_speeds.csv")
    if data.size:
        ax.plot(data["time_over_tau"], data["speed_over_sqrt_gH0"], **style)


def speed_axes(ax) -> None:
    """Huet et al. 2021, Figs. 12-13: v_avg / sqrt(g H0) against t / tau_c, tau_c = sqrt(H0 / g)."""
    ax.set_xlabel(r"$t / \tau_c$")
    ax.set_ylabel(r"$v_{avg} / \sqrt{g H_0}$")
    ax.axhline(0.05, color="grey", lw=0.6, ls=":")  # Sec. IV B 2: "below 5 % of v0"


def force_pdf_axes(axes, tables, label_prefix=""):
    """Huet et al. 2021, Fig. 15: PDF of F_c / <F_c> before the gate opens, linear and log."""
    for scale, ax in zip((0, 1), axes):
        rows = [t[t["scale"] == scale] for t in tables]
        if len(tables) > 1:
            for r in rows:
                ax.plot(r["force_ratio"], r["density"], ".", color="tab:blue", ms=2, alpha=0.4)
        mean = np.mean([r["density"] for r in rows], axis=0)
        if scale == 1:  # empty bins have no logarithm
            mean = np.where(mean > 0, mean, np.nan)
        ax.plot(rows[0]["force_ratio"], mean, "k-", label=f"{label_prefix}mean of {len(tables)} run(s)")
        ax.set_xlabel(r"$F_c / \langle F_c \rangle$")
        ax.set_ylabel("PDF")
    axes[1].set_xscale("log")
    axes[1].set_yscale("log")
    axes[0].set_title("linear", fontsize=9)
    axes[1].set_title("logarithmic", fontsize=9)
    axes[0].legend(fontsize=8)


def force_network_figure(folder: Path):
    """Huet et al. 2021, Fig. 14: the contact network of the column before the gate opens, seen
    from the side. Each segment joins the centres of two bodies in contact, its colour and width
    set by F_c / <F_c>; (a) every contact, (b) those above five times the mean. Returns the
    counts of both panels."""
    from matplotlib.collections import LineCollection

    t = read_csv(folder / "force_network.csv")
    if t.size == 0:
        return 0, 0
    ratio = t["force"] / np.mean(t["force"])
    segments = np.stack([np.column_stack([t["x_i"], t["z_i"]]), np.column_stack([t["x_j"], t["z_j"]])], axis=1)
    x = np.concatenate([t["x_i"], t["x_j"]])
    z = np.concatenate([t["z_i"], t["z_j"]])
    top = max(5.0, float(np.max(ratio)))
    height = float(np.ptp(z)) or 1.0
    width = float(np.ptp(x)) or 1.0
    panel = max(3.0, 8 * width / height)
    fig, axes = plt.subplots(1, 3, figsize=(2 * panel + 1.2, 8), gridspec_kw={"width_ratios": [panel, panel, 0.25]})
    for ax, keep, title in zip(axes[:2], (ratio >= 0, ratio > 5), ("(a) all contacts", r"(b) $F_c > 5 \langle F_c \rangle$")):
        # Widths from a hairline at the weakest to 3 points at five times the mean and above.
        lines = LineCollection(segments[keep], array=ratio[keep], cmap="viridis",
                               linewidths=np.clip(0.15 + 0.57 * ratio[keep], 0.15, 3.0),
                               norm=matplotlib.colors.Normalize(0, top))
        ax.add_collection(lines)
        ax.set_xlim(x.min() - 0.02 * width, x.max() + 0.02 * width)
        ax.set_ylim(z.min() - 0.02 * height, z.max() + 0.02 * height)
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.set_title(f"{title}: {int(np.count_nonzero(keep))} of {len(ratio)}", fontsize=9)
    axes[0].set_ylabel("z (m)")
    fig.colorbar(lines, cax=axes[2], label=r"$F_c / \langle F_c \rangle$")
    fig.suptitle("contact network before the gate opens", fontsize=10)
    save(fig, folder / "fig14_force_network.png")
    return len(ratio), int(np.count_nonzero(ratio > 5))


def fabric_rose(folder: Path, tables, title: str) -> None:
    """Huet et al. 2021, Fig. 17: distribution of the branch-vector angle in the xz plane."""
    fig = plt.figure(figsize=(5, 5))
    ax = fig.add_subplot(projection="polar")
    theta = tables[0]["theta"]
    mean = np.mean([t["density"] for t in tables], axis=0)
    # A branch vector has no sign: theta and theta + pi are the same direction.
    full_theta = np.concatenate([theta, theta + np.pi, theta[:1]])
    full = np.concatenate([mean, mean, mean[:1]])
    ax.plot(full_theta, full, "k-")
    ax.fill(full_theta, full, alpha=0.2)
    ax.set_title(title, fontsize=9)
    save(fig, folder / "fig17_fabric_rose.png")


def snapshots(folder: Path, summary: dict, times) -> None:
    """Huet et al. 2021, Figs. 6-8: side views of the column at chosen times after the gate opened,
    one strip sharing a window sized to the pile. Times past the run's last frame are left out
    and the last frame closes the strip, so no frame is shown twice."""
    if not (folder / "vtk" / "particles.pvd").exists():
        print(f"{folder}: no vtk/ frames (set run.vtk_interval) - no snapshots", file=sys.stderr)
        return
    from . import render  # VTK loads only when snapshots are drawn

    db = summary.get("dam_break", {})
    gate = db.get("gate_open_time", 0.0)
    if times is None:
        tau = db.get("time_scale", 0.0)
        times = [k * tau for k in (0, 1, 2, 3, 5, 8)]
    available = render.frame_times(folder)
    shown = []
    for t in times:
        nearest = next((f for f in available if f >= gate + t - 1e-9), available[-1])  # first frame at or after
        if nearest not in shown and gate + t <= available[-1] + 0.5 * (available[-1] - available[max(len(available) - 2, 0)]):
            shown.append(nearest)
    if available[-1] not in shown:
        shown.append(available[-1])
    window = render.pile_window(folder, shown, "side")
    (x0, x1), (z0, z1) = window
    # Tall narrow columns side by side in one row; a spread pile in two columns of panels.
    panel_height = 2.2
    panel_width = min(max(panel_height * (x1 - x0) / (z1 - z0), 1.2), 6.0)
    columns = len(shown) if panel_width < 3.5 else 2
    rows = -(-len(shown) // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(panel_width * columns + 0.6, (panel_height + 0.4) * rows),
                             squeeze=False)
    for ax in axes.flat[len(shown):]:
        ax.axis("off")
    for ax, frame_time in zip(axes.flat, shown):
        render.draw_on(ax, folder, frame_time, "side", window)
        ax.set_title(f"t = {frame_time - gate:.3g} s after the gate opened", fontsize=8)
        ax.tick_params(labelsize=6)
    axes[-1, 0].set_xlabel("x (m)", fontsize=7)
    axes[-1, 0].set_ylabel("z (m)", fontsize=7)
    fig.suptitle("Side views, coloured by speed (each panel to its own fastest particle)", fontsize=9)
    fig.tight_layout()
    save(fig, folder / "fig06_08_side_snapshots.png")


def run_figures(folder: Path, snapshot_times) -> None:
    summary = json.loads((folder / "summary.json").read_text())
    profiles(folder, summary)
    fig, ax = plt.subplots(figsize=(6, 4))
    speeds(ax, folder, color="k")
    speed_axes(ax)
    ax.set_title(f"a = {summary.get('aspect_ratio', float('nan')):.2f}, {summary.get('regime', '')}", fontsize=9)
    save(fig, folder / "fig12_speeds.png")
    if (folder / "force_network.csv").exists():
        force_network_figure(folder)
    if (folder / "force_pdf.csv").exists():
        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        force_pdf_axes(axes, [read_csv(folder / "force_pdf.csv")])
        save(fig, folder / "fig15_force_pdf.png")
    if (folder / "fabric.csv").exists():
        fabric_rose(folder, [read_csv(folder / "fabric.csv")], "branch vectors in the xz plane, before the gate opens")
    snapshots(folder, summary, snapshot_times)
    plot_timeseries.main(folder)


# ---------------------------------------------------------------- an ensemble of runs
def ensemble_figures(folder: Path) -> None:
    record = json.loads((folder / "ensemble.json").read_text())
    runs = sorted((int(d.name[5:]), d) for d in folder.glob("seed_*") if (d / "summary.json").exists())
    summaries = {seed: json.loads((d / "summary.json").read_text()) for seed, d in runs}
    title = f"{record.get('case', folder.name)}: {record['runs']} runs, {record.get('verdict', '')}"
    if any((d / "collapse_speeds.csv").exists() for _, d in runs):
        fig, ax = plt.subplots(figsize=(6, 4))
        for seed, d in runs:
            if (d / "collapse_speeds.csv").exists():
                regime = summaries[seed].get("regime", "collapsed")
                speeds(ax, d, color=MARKERS.get(regime, ("o", "k"))[1], lw=1, label=f"seed {seed} ({regime})")
        speed_axes(ax)
        ax.legend(fontsize=7)
        ax.set_title(title, fontsize=9)
        save(fig, folder / "fig12_speeds.png")
    pdfs = [read_csv(d / "force_pdf.csv") for _, d in runs if (d / "force_pdf.csv").exists()]
    if pdfs:
        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        force_pdf_axes(axes, pdfs)
        save(fig, folder / "fig15_force_pdf.png")
    roses = [read_csv(d / "fabric.csv") for _, d in runs if (d / "fabric.csv").exists()]
    if roses:
        fabric_rose(folder, roses, f"branch vectors in the xz plane, mean of {len(roses)} runs")
    flat = [s for s in summaries.values() if "dam_break" in s and "aspect_ratio" in s]
    if flat:
        fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
        for s in flat:
            db = s["dam_break"]
            m, c = MARKERS.get(s.get("regime"), ("o", "k"))
            a = s["aspect_ratio"]
            left.errorbar(a, db["runout_ratio"], yerr=[[db["runout_ratio"] - db["runout_ratio_low"]],
                                                         [db["runout_ratio_high"] - db["runout_ratio"]]], fmt=m, color=c)
            right.errorbar(a, db["height_ratio"], yerr=[[db["height_ratio"] - db["height_ratio_low"]],
                                                          [db["height_ratio_high"] - db["height_ratio"]]], fmt=m, color=c)
        channel_runout_lines(left, max(s["aspect_ratio"] for s in flat) * 1.3)
        left.set_xlabel(r"$a = H_0 / L_0$")
        left.set_ylabel(r"$(L_\infty - L_0) / L_0$")
        left.legend(fontsize=7)
        right.set_xlabel(r"$a = H_0 / L_0$")
        right.set_ylabel(r"$H_0 / H_\infty$")
        fig.suptitle(title, fontsize=9)
        save(fig, folder / "fig10_fig11_runs.png")


# ---------------------------------------------------------------- a sweep
def sweep_figures(folder: Path) -> None:
    sweep = json.loads((folder / "sweep.json").read_text())
    points = sweep["points"]
    if points and "repose_angle_mean" in points[0]:
        return repose_figure(folder, sweep)
    points = [p for p in points if "aspect_ratio_mean" in p]
    if not points:
        print(f"{folder}: no dam-break measurements in sweep.json", file=sys.stderr)
        return
    # Fig. 9: one marker per case at (L0, mean H0), by regime; intermittent cases stand out.
    fig, ax = plt.subplots(figsize=(6, 5))
    shown = set()
    for p in points:
        if p.get("verdict") == "intermittent":
            marker, colour, label = "X", "tab:red", "intermittent"
        else:
            regime = p.get("majority_regime", "collapsed")
            marker, colour = MARKERS.get(regime, ("o", "k"))
            label = f"repeatable, {regime}"
        ax.plot(p["L0_mean"] * 100, p["H0_mean"] * 100, marker, color=colour, ms=9,
                label=None if label in shown else label)
        shown.add(label)
        ax.annotate(f"{p.get('stable_fraction', 0):.0%} stable", (p["L0_mean"] * 100, p["H0_mean"] * 100),
                    textcoords="offset points", xytext=(6, 4), fontsize=7)
    ax.set_xlabel("L$_0$ (cm)")
    ax.set_ylabel("H$_0$ (cm)")
    ax.set_title(f"flow map, {sweep['seeds']} seeds per case", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, folder / "fig09_flow_map.png")
    a = np.array([p["aspect_ratio_mean"] for p in points])
    a_std = np.array([p["aspect_ratio_std"] for p in points])
    for key, name, ylabel, extra in [
            ("dam_break.runout_ratio", "fig10_runout_ratio.png", r"$(L_\infty - L_0) / L_0$", channel_runout_lines),
            ("dam_break.height_ratio", "fig11_height_ratio.png", r"$H_0 / H_\infty$", None),
            ("dam_break.com_ratio", "fig24_com_ratio.png", r"$\Delta x_{com} / x_{com,0}$", None)]:
        if f"{key}_mean" not in points[0]:
            continue
        fig, ax = plt.subplots(figsize=(6, 4.5))
        mean = np.array([p[f"{key}_mean"] for p in points])
        std = np.array([p[f"{key}_std"] for p in points])
        if f"{key}_low_mean" in points[0]:
            # Sec. III C: the bar of one measurement (20 % / 1 % runout thresholds, height quartiles).
            low = np.array([p[f"{key}_low_mean"] for p in points])
            high = np.array([p[f"{key}_high_mean"] for p in points])
            ax.errorbar(a, mean, yerr=[mean - low, high - mean], fmt="none", ecolor="grey", elinewidth=4, alpha=0.4,
                        label="measurement bar (mean over seeds)")
        ax.errorbar(a, mean, xerr=a_std, yerr=std, fmt="o", color="k", capsize=3, label="mean $\\pm$ std over seeds")
        if extra:
            extra(ax, float(a.max()) * 1.2)
        ax.set_xlabel(r"$a = H_0 / L_0$")
        ax.set_ylabel(ylabel)
        ax.legend(fontsize=7)
        save(fig, folder / name)


def repose_figure(folder: Path, sweep: dict) -> None:
    """Huet et al. 2021, Fig. 23: repose angle against the swept value (mu_c)."""
    key = next(iter(sweep["grid"]))
    points = [p for p in sweep["points"] if p.get("repose_angle_mean") is not None]
    x = np.array([float(p[key]) for p in points])
    y = np.array([p["repose_angle_mean"] for p in points])
    e = np.array([p["repose_angle_std"] for p in points])
    order = np.argsort(x)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.errorbar(x[order], y[order], yerr=e[order], fmt="o-", color="k", capsize=3, label="Talus (mean $\\pm$ std over seeds)")
    if key == "contact.friction":
        ax.plot([0.5], [36], "s", color="tab:red", label="Huet et al. 2021: about 36 deg at $\\mu_c$ = 0.5")
        ax.set_xlabel(r"$\mu_c$ (particle-particle)")
    else:
        ax.set_xlabel(key)
    ax.set_ylabel("repose angle (deg)")
    ax.legend(fontsize=8)
    save(fig, folder / "fig23_repose_angle.png")


def pile_figure(folder: Path) -> None:
    summary = json.loads((folder / "summary.json").read_text())
    profile = read_csv(folder / "pile_profile.csv")
    h = summary.get("hopper", {})
    fig, ax = plt.subplots(figsize=(7, 3.5))
    ax.step(profile["position"] * 100, profile["height"] * 100, where="mid", color="k", label="surface")
    for side in ("left", "right"):
        s, c = h.get(f"{side}_slope"), h.get(f"{side}_intercept")
        angle = summary.get(f"repose_angle_{side}")
        if s is None or angle is None:
            continue
        x = profile["position"][(profile["position"] < h["apex"]) if side == "left" else (profile["position"] > h["apex"])]
        line = s * x + c
        keep = (line > 0) & (line <= summary["pile_height"])
        ax.plot(x[keep] * 100, line[keep] * 100, "--", color="tab:red", label=f"{side}: {angle:.1f} deg")
    ax.set_aspect("equal")
    ax.set_xlabel("x (cm)")
    ax.set_ylabel("height (cm)")
    ax.set_title(f"repose angle {summary.get('repose_angle') or float('nan'):.1f} deg", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, folder / "pile_profile.png")


def draw(folder: Path, times=None) -> None:
    """The figures of whatever study `folder` holds; `times` (s after the gate opened) are the
    side snapshots' times of a single run."""
    if (folder / "sweep.json").exists():
        sweep_figures(folder)
    elif (folder / "ensemble.json").exists():
        ensemble_figures(folder)
    elif (folder / "collapse_speeds.csv").exists():
        run_figures(folder, times)
    elif (folder / "pile_profile.csv").exists():
        pile_figure(folder)
        plot_timeseries.main(folder)
    else:
        sys.exit(f"talus plot: {folder} holds no dam-break, ensemble, sweep or hopper results")
