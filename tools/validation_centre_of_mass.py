"""Huet et al. 2021, Appendix C (Fig. 24): the centre of mass's final displacement against the
aspect ratio. Its Delta x / x0 = (x_inf - x0) / x0 rises as a^2 below a = H0 / L0 of about 3 and
as a^(2/3) above (Eqs. C1, C3), a transition the runout ratio hides for the crosses (slope about 1
throughout, Fig. 10) and Lajeunesse et al. 2005 see in the spheres' runout (1, then 2/3).

Each quantity gets one broken power law through every run, continuous at the paper's a = 3:
log y = c + n_low min(log(a/3), 0) + n_high max(log(a/3), 0), least squares, the slopes' standard
errors from the fit's covariance (the runs' scatter about the law sets the residual)."""
import math

import numpy as np

KNEE = 3.0  # Huet et al. 2021, Appendix C: the transition 'around H0/L0 = 3'
FAMILIES = ("crosses", "crosses_manifold", "spheres")
PAPER = {  # by particle kind: both families of crosses answer to the paper's crosses
    ("crosses", "com_ratio"): "2 and 2/3 (Fig. 24)",
    ("crosses", "runout_ratio"): "about 1, no visible transition (Fig. 10)",
    ("spheres", "com_ratio"): "2 and 2/3 ('presumably true for any particle shape')",
    ("spheres", "runout_ratio"): "1 and 2/3 (Lajeunesse et al. 2005)",
}
LABELS = {"com_ratio": "Delta x / x0 (centre of mass)", "runout_ratio": "(L_inf - L0) / L0"}


def distinct_aspect_ratios(log_a, tolerance=0.05):
    """How many aspect ratios the values of log(a) hold: the realisations of one column differ
    in a by a fraction of a percent (each settles to its own H0), columns of the study by 10 % or
    more, so values closer than `tolerance` in log(a) are one."""
    xs = sorted(log_a)
    return sum(1 for k, x in enumerate(xs) if k == 0 or x - xs[k - 1] > tolerance)


def broken_power_fit(points, knee=KNEE):
    """(c, n_low, n_high) and their standard errors through (a, y) pairs, or None when either
    side of the knee has fewer than two distinct aspect ratios (its slope is then not measured)."""
    pts = [(math.log(a / knee), math.log(y)) for a, y in points if a > 0 and y > 0]
    low = distinct_aspect_ratios([x for x, _ in pts if x <= 0])
    high = distinct_aspect_ratios([x for x, _ in pts if x >= 0])
    if low < 2 or high < 2 or len(pts) < 4:
        return None
    design = np.array([[1.0, min(x, 0.0), max(x, 0.0)] for x, _ in pts])
    y = np.array([v for _, v in pts])
    coef, *_ = np.linalg.lstsq(design, y, rcond=None)
    dof = len(pts) - 3
    residual = float(np.sum((y - design @ coef) ** 2)) / dof
    cov = residual * np.linalg.inv(design.T @ design)
    se = np.sqrt(np.diag(cov))
    return {"c": float(coef[0]), "n_low": float(coef[1]), "n_high": float(coef[2]),
            "c_err": float(se[0]), "n_low_err": float(se[1]), "n_high_err": float(se[2]), "runs": len(pts)}


def particles_of(family):
    return "spheres" if family == "spheres" else "crosses"


def run_points(runs_by_family, family, key):
    """(a, y) of every run of a family that did not stand: runs_by_family maps a family to its
    summary dicts. A column that stood moved by the creep of a few crosses, which on log axes
    would set the slope by itself, and the paper's Fig. 24 (log axes) cannot show it."""
    out = []
    for s in runs_by_family.get(family, []):
        if s.get("regime") == "stable":
            continue
        a, y = s.get("aspect_ratio"), s.get("dam_break", {}).get(key)
        if isinstance(a, (int, float)) and isinstance(y, (int, float)) and math.isfinite(a) and math.isfinite(y):
            out.append((a, y))
    return out


def lines_and_fits(runs_by_family):
    """The report's table of slopes below and above a = 3, and the fits by (family, key)."""
    fits = {}
    rows = []
    for family in FAMILIES:
        for key in ("com_ratio", "runout_ratio"):
            pts = run_points(runs_by_family, family, key)
            fit = broken_power_fit(pts)
            if not fit:
                continue
            fits[(family, key)] = fit
            rows.append(f"| {family} | {LABELS[key]} | {fit['runs']} | {fit['n_low']:.2f} ± {fit['n_low_err']:.2f} | "
                        f"{fit['n_high']:.2f} ± {fit['n_high_err']:.2f} | {PAPER[(particles_of(family), key)]} |")
    if not rows:
        return [], fits
    lines = ["The centre of mass (Appendix C, Fig. 24): the final displacement of the column's centre of mass, "
             "Delta x / x0 = (x_inf - x0) / x0 with x0 = L0 / 2, against a, beside the runout ratio. One power law "
             "through every run that did not stand, broken at the paper's a = 3 and continuous there (slopes with "
             "their standard errors):", "",
             "| particles | quantity | runs | slope below a = 3 | slope above | the paper |", "|---|---|---|---|---|---|"]
    lines += rows
    lines.append("")
    verdicts = []
    for family in FAMILIES:
        fit = fits.get((family, "com_ratio"))
        if not fit:
            continue
        low = abs(fit["n_low"] - 2.0) / fit["n_low_err"] if fit["n_low_err"] > 0 else float("inf")
        high = abs(fit["n_high"] - 2.0 / 3.0) / fit["n_high_err"] if fit["n_high_err"] > 0 else float("inf")
        whose = "the paper's crosses" if particles_of(family) == "crosses" else "what the paper expects of any shape (it shows no spheres)"
        verdicts.append(f"the {family} centre of mass lies {low:.1f} standard errors from slope 2 below a = 3 and "
                        f"{high:.1f} from 2/3 above, {whose}")
    if verdicts:
        lines += ["Against Eqs. C1 and C3 (slopes 2 and 2/3): " + "; ".join(verdicts) + ".", ""]
    return lines, fits


def plot(runs_by_family, fits, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    style = {"crosses": ("s", "k"), "crosses_manifold": ("s", "tab:purple"), "spheres": ("o", "tab:blue")}
    for family, (marker, colour) in style.items():
        pts = run_points(runs_by_family, family, "com_ratio")
        if not pts:
            continue
        ax.plot([a for a, _ in pts], [y for _, y in pts], marker, color=colour, ms=4, ls="none", label=family)
        fit = fits.get((family, "com_ratio"))
        if fit:
            grid = np.exp(np.linspace(math.log(min(a for a, _ in pts)), math.log(max(a for a, _ in pts)), 60))
            x = np.log(grid / KNEE)
            y = np.exp(fit["c"] + fit["n_low"] * np.minimum(x, 0) + fit["n_high"] * np.maximum(x, 0))
            ax.plot(grid, y, "-", color=colour, lw=1,
                    label=f"{family}: slopes {fit['n_low']:.2f}, {fit['n_high']:.2f}")
    ax.axvline(KNEE, color="grey", ls=":", lw=1)
    ax.set(xscale="log", yscale="log", xlabel="a = H0/L0", ylabel="Delta x / x0",
           title="Huet et al. 2021, Fig. 24 (paper: slopes 2, then 2/3)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
