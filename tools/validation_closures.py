"""Weinhart et al. 2012, Sects. 7 and 9, from the steady flows of the flow map: the flow rule
(Eq. 47, Table 1: beta, gamma), the bulk volume fraction (Eq. 52), the stress ratio K (Eq. 53) and
the shape factor alpha (Eq. 54, Table 2: d_lambda), each fitted with its standard error and each
also set against the paper's own closure at Talus' cases (no free parameter), with the paper's
err of Eq. 49 beside it; the check that the map's runs to t = 500 give the Froude numbers of runs
to the paper's t = 2000; and the figure of F against h / h_stop and the closures (Figs. 11-13)."""
import csv
import json
import math
from pathlib import Path

import numpy as np

# Weinhart et al. 2012, lambda = 1: Eq. (52b), Eq. (53), Table 2, and the errors of Eq. (49)
# it quotes for them (Eq. 52c, Sect. 9.2, Table 2, Table 1's err(F)).
PAPER = {"c0": 0.5985, "c1": 4.8, "c2": 40.85, "d0": 132.0, "d1": 21.50, "d_lambda": 6.678}
PAPER_ERR = {"F": 0.121, "bulk_volume_fraction": 0.002, "K": 0.013, "alpha": 0.01763}
BATCHES = 5  # batch means of a case's series: its Froude number's standard error


def kept_rows(chute_fits, study_dir: Path, table="sweep_runs.csv"):
    """The rows of a chute study's table (a flow map's sweep_runs.csv, written once all its cases
    are done; the staircase's hstop_runs.csv), and of its finished cases still missing from it,
    read from their kept summary.json."""
    rows = chute_fits._read(str(study_dir / table))
    seen = {(r["lambda"], r["H"], r["angle"]) for r in rows}
    for case in sorted(study_dir.glob("lambda*_H*_theta*")):
        lam, rest = case.name[len("lambda"):].split("_H")
        H, angle = rest.split("_theta")
        key = (float(lam), float(H), float(angle))
        summary_path = case / "summary.json"
        if key in seen or not summary_path.exists():
            continue
        s = json.loads(summary_path.read_text())
        if s.get("stop_reason") in ("interrupted", "blow_up"):
            continue
        row = {"lambda": key[0], "H": key[1], "angle": key[2], "flow_state": s.get("flow_state"),
               "arrested": int(s.get("stop_reason") == "arrested" or s.get("flow_state") == "arrested"),
               "arrest_time": s.get("chute", {}).get("arrest_time")}
        for k in ("h", "froude", "K", "alpha", "bulk_volume_fraction", "mean_velocity"):
            row[k] = s.get(k)
        rows.append(row)
    return rows


def with_long_runs(flowmap, long_rows):
    """The map's cases with each one that flowmap_long ran on to t = 2000 taken from there: the
    flows the flow rule and the closures are fitted through. Each row names its study."""
    longer = {(r["H"], r["angle"]): r for r in long_rows}
    return [dict(longer.get((r["H"], r["angle"]), r), study="flowmap_long" if (r["H"], r["angle"]) in longer
                 else "flowmap") for r in flowmap]


def steady(rows):
    return [r for r in rows if r.get("flow_state") == "steady" and r.get("h") not in ("", None)]


def case_folder(base: Path, study: str, r) -> Path:
    return base / "weinhart2012" / study / f"lambda{r['lambda']:g}_H{r['H']:g}_theta{r['angle']:g}"


def froude_error(folder: Path):
    """Standard error of a case's Froude number from the batch means of its averaging window's
    series (chute_series.csv, one row per block of time): consecutive blocks are correlated, batches
    of several blocks much less so. nan when the series is too short or missing."""
    path = folder / "chute_series.csv"
    if not path.exists():
        return math.nan
    with open(path) as f:
        F = np.array([float(r["froude"]) for r in csv.DictReader(f)])
    if len(F) < 2 * BATCHES:
        return math.nan
    means = [b.mean() for b in np.array_split(F, BATCHES)]
    return float(np.std(means, ddof=1) / math.sqrt(BATCHES))


def window_trend(folder: Path):
    """The drift of a case's Froude number across its averaging window: the slope of a line
    through its BATCHES batch means (per unit time) with the slope's standard error from their
    scatter about the line, and the window's length; None when the series is too short."""
    path = folder / "chute_series.csv"
    if not path.exists():
        return None
    with open(path) as f:
        rows = [(float(r["time"]), float(r["froude"])) for r in csv.DictReader(f)]
    if len(rows) < 2 * BATCHES:
        return None
    batches = np.array_split(np.array(rows), BATCHES)
    t = np.array([b[:, 0].mean() for b in batches])
    F = np.array([b[:, 1].mean() for b in batches])
    (slope, intercept), cov = np.polyfit(t, F, 1, cov=True)
    return {"slope": float(slope), "slope_err": float(math.sqrt(cov[0, 0])), "window": rows[-1][0] - rows[0][0],
            "F": float(F.mean())}


def trend_lines(rows, base: Path, checks=(), end_time=500.0, paper_end=2000.0):
    """Whether the steady flows still drift within their averaging window: each one's change of F
    across the window in its standard errors, and the change a drift that size would make by the
    paper's end time, against the flow rule's scatter (Table 1's err(F)). Evidence that the runs
    had settled, not a substitute for running them longer: a drift slower than the window shows
    escapes it. Where a drifting flow was run on to t = 2000 (`checks`, length_check), what it
    did is said beside what its drift foretold."""
    trends = []
    for r in rows:
        tr = window_trend(case_folder(base, "flowmap", r))
        if tr and tr["slope_err"] > 0:
            trends.append((r, tr))
    if not trends:
        return []
    z = [abs(tr["slope"]) / tr["slope_err"] for _, tr in trends]
    significant = [(r, tr) for (r, tr), zz in zip(trends, z) if zz > 2]
    worst_r, worst = max(trends, key=lambda rt: abs(rt[1]["slope"]) * (paper_end - end_time))
    reach = abs(worst["slope"]) * (paper_end - end_time)
    text = (f"Across each steady flow's averaging window ({trends[0][1]['window']:.0f} time units, {BATCHES} batch means "
            "of the per-block series, whose one-block profiles put h and F off the window's by a near-constant offset), "
            f"F drifts by {min(z):.1f} to {max(z):.1f} standard errors of the drift; "
            f"{len(significant)} of {len(trends)} flows drift by more than two")
    if significant:
        text += " (" + ", ".join(f"H = {r['H']:g} at {r['angle']:g}°: {tr['slope'] * 100:+.3f} per 100 time units"
                                 for r, tr in significant) + ")"
    text += (f". The largest drift, carried on to t = {paper_end:g}, would move F by {reach:.3f} "
             f"(H = {worst_r['H']:g} at {worst_r['angle']:g}°), against the flow rule's scatter err(F) = {PAPER_ERR['F']}")
    ran_on = {(c["H"], c["angle"]): c for c in checks}
    tested = [(r, tr, ran_on[(r["H"], r["angle"])]) for r, tr in significant if (r["H"], r["angle"]) in ran_on]
    if tested:
        text += ". Run on to t = %g: " % paper_end + "; ".join(
            f"H = {r['H']:g} at {r['angle']:g}°, whose drift foretold {tr['slope'] * (paper_end - end_time):+.3f}, "
            f"moved by {c['F_long'] - c['F_short']:+.3f} ({c['sigmas']:.1f} combined standard errors)"
            for r, tr, c in tested)
        settled = all(c["sigmas"] < 2 for _, _, c in tested)
        text += (": the drift within the window was a fluctuation, not a trend, and t = 500 was long enough for "
                 "that flow." if settled else ": the flow was still changing at t = 500.")
        untested = [(r, tr) for r, tr in significant if (r["H"], r["angle"]) not in ran_on]
        if untested:
            text += " Not yet run on: " + ", ".join(f"H = {r['H']:g} at {r['angle']:g}°" for r, _ in untested) + "."
    elif significant:
        text += (": flows still drifting at t = 500 are not yet steady in the paper's sense (F constant over its last "
                 "200 time units), and their F at t = 500 is a lower or upper bound, not the steady value.")
    else:
        text += ": within their errors the flows had settled by the start of the window."
    return [text, ""]


def flow_rule(chute_fits, rows, hs):
    """Eq. (47) through the steady flows, h_stop from Eq. (35) with the parameters hs."""
    if len(rows) < 3:
        return None
    p, se, e = chute_fits.fit_flow_rule([r["h"] for r in rows], [r["angle"] for r in rows],
                                        [r["froude"] for r in rows], hs)
    return {"params": p, "se": se, "err": e, "n": len(rows)}


def closures(chute_fits, rows, hs_paper):
    """Each closure's own fit (or None where the cases cannot determine it) and the rms deviation
    of Talus' cases from the paper's closure, as Eq. (49)."""
    out = {}
    theta = np.array([r["angle"] for r in rows], float)
    if len(rows) < 2:
        return out
    bulk = [r for r in rows if r.get("bulk_volume_fraction") not in ("", None)]
    if bulk:
        th = np.array([r["angle"] for r in bulk], float)
        phi = np.array([r["bulk_volume_fraction"] for r in bulk], float)
        block = {"paper_err": chute_fits.err(phi - chute_fits.density52(th, PAPER["c0"], PAPER["c1"], PAPER["c2"])),
                 "n": len(bulk)}
        if len(set(th)) >= 4:  # three parameters need four angles
            try:
                block.update(zip(("params", "se", "err"), chute_fits.fit_density(th, phi)))
            except (RuntimeError, ValueError):
                pass
        out["bulk_volume_fraction"] = block
    K = np.array([r["K"] for r in rows], float)
    block = {"paper_err": chute_fits.err(K - chute_fits.stress_ratio53(theta, PAPER["d0"], PAPER["d1"])), "n": len(rows)}
    if len(set(theta)) >= 3:
        block.update(zip(("params", "se", "err"), chute_fits.fit_stress_ratio(theta, K)))
    out["K"] = block
    h = np.array([r["h"] for r in rows], float)
    alpha = np.array([r["alpha"] for r in rows], float)
    try:
        predicted = chute_fits.shape_factor54(h, theta, PAPER["d_lambda"], hs_paper)
        block = {"paper_err": chute_fits.err(alpha - predicted), "n": len(rows)}
        block.update(zip(("params", "se", "err"), chute_fits.fit_shape_factor(h, theta, alpha, hs_paper)))
        out["alpha"] = block
    except (RuntimeError, ValueError):
        pass  # a flow thinner than its base layer: Eq. (54) has no profile there
    return out


def length_check(flowmap, long_rows, base: Path):
    """Each case of the long runs (t = 2000) beside the same (H, theta) of the map (t = 500):
    Froude numbers with their batch-mean errors and their difference in combined errors."""
    short = {(r["H"], r["angle"]): r for r in flowmap}
    out = []
    for r in long_rows:
        s = short.get((r["H"], r["angle"]))
        if not s or r.get("froude") in ("", None) or s.get("froude") in ("", None):
            continue
        e_long = froude_error(case_folder(base, "flowmap_long", r))
        e_short = froude_error(case_folder(base, "flowmap", s))
        combined = math.hypot(e_long, e_short)
        out.append({"H": r["H"], "angle": r["angle"], "F_short": s["froude"], "F_short_err": e_short,
                    "F_long": r["froude"], "F_long_err": e_long, "h_short": s["h"], "h_long": r["h"],
                    "states": (s["flow_state"], r["flow_state"]),
                    "sigmas": abs(r["froude"] - s["froude"]) / combined if combined > 0 else math.nan})
    return out


def length_effect_lines(checks, rule, chute_fits=None, rows=None, hs=None):
    """What running to t = 2000 would still do to the flow rule: the flows the fit takes at t = 500
    (all of them without `rows`, the fit's flows, each naming its study) scaled by the largest
    relative change the long runs showed, and beta fitted again (with every flow scaled, beta
    scales by the same factor: Eq. 47 is linear in F), to set against beta's standard error.
    `rule`: the flow rule with Table 1's h_stop `hs`."""
    moved = [c for c in checks if c["F_short"] > 0]
    if not moved or not rule:
        return []
    worst = max(moved, key=lambda c: abs(c["F_long"] / c["F_short"] - 1))
    rel = worst["F_long"] / worst["F_short"] - 1
    beta, beta_se = rule["params"]["beta"], rule["se"]["beta"]
    text = (f"The largest change from t = 500 to 2000 is {rel:+.1%} in F (H = {worst['H']:g} at {worst['angle']:g}°, "
            f"{worst['sigmas']:.1f} of its small batch errors). ")
    if rows is None:
        shift, which = abs(beta * rel), "Every flow's F"
    else:
        short = [r for r in rows if r.get("study") != "flowmap_long"]
        if not short:
            return [text + "Every flow of the fit ran to t = 2000.", ""]
        scaled = [dict(r, froude=r["froude"] * (1 + rel)) if r.get("study") != "flowmap_long" else r for r in rows]
        moved_rule = flow_rule(chute_fits, scaled, hs)
        shift = abs(moved_rule["params"]["beta"] - beta)
        gamma_shift = moved_rule["params"]["gamma"] - rule["params"]["gamma"]
        which = (f"The fit takes {len(rows) - len(short)} of its {len(rows)} flows from t = 2000. Were the other "
                 f"{len(short)} flows' F all {rel:+.1%} higher, gamma would move by {gamma_shift:+.4f} and beta "
                 f"by {moved_rule['params']['beta'] - beta:+.4f}")
        verdict = (f"within its standard error {beta_se:.3f}" if shift <= beta_se else
                   f"beyond its standard error {beta_se:.3f}: the flow rule needs more long runs")
        return [text + f"{which}, {verdict}.", ""]
    verdict = (f"within its standard error {beta_se:.3f}: t = 500 is long enough for the rest of the flow rule"
               if shift <= beta_se else f"beyond its standard error {beta_se:.3f}: the flow rule needs more long runs")
    return [text + f"{which} changed by that much would move beta (Table 1's h_stop) by {shift:.4f}, {verdict}.", ""]


def rule_deviation(chute_fits, rows, paper_hstop):
    """err(F - F_Table1) of Eq. (49) over steady flows: their spread about Table 1's flow rule (at
    Table 1's h_stop), to set beside the paper's err(F) = 0.121 of its own flows about it."""
    rule = chute_fits.TABLE1_LAMBDA1
    return chute_fits.err([r["froude"] - (rule["beta"] * r["h"] / float(chute_fits.hstop35(r["angle"], **paper_hstop))
                                          - rule["gamma"]) for r in rows])


def spread_verdict(spread, paper_spread, n):
    """Talus' rms deviation about the paper's rule against the paper's own, read with the sampling
    error of an rms over n flows (relative 1 / sqrt(2 n) for Gaussian deviations)."""
    rel = 1 / math.sqrt(2 * n)
    ratio = spread / paper_spread
    if ratio > 1 + 2 * rel:
        return f"Talus' flows scatter about Table 1's rule more than the paper's do ({ratio:.2f} times, beyond twice " \
               f"the {rel:.0%} sampling error of an rms over {n} flows)."
    if ratio < 1 - 2 * rel:
        return f"Talus' flows scatter about Table 1's rule less than the paper's do ({ratio:.2f} times)."
    return f"Talus' flows scatter about Table 1's rule as much as the paper's do ({ratio:.2f} times, within twice the " \
           f"{rel:.0%} sampling error of an rms over {n} flows)."


def rule_ratio_lines(chute_fits, rows, paper_hstop, base: Path, fit):
    """Each steady flow's F over Table 1's flow rule at its h / h_stop: whether Talus' flows
    fall short of the paper's by a shift (gamma) or by a factor (beta). `fit`: the flow rule
    fitted with Table 1's h_stop."""
    if not rows:
        return []
    cases = []
    for r in sorted(rows, key=lambda r: r["h"] / float(chute_fits.hstop35(r["angle"], **paper_hstop))):
        x = r["h"] / float(chute_fits.hstop35(r["angle"], **paper_hstop))
        rule = chute_fits.TABLE1_LAMBDA1["beta"] * x - chute_fits.TABLE1_LAMBDA1["gamma"]
        cases.append((r, x, r["froude"] / rule, froude_error(case_folder(base, r.get("study", "flowmap"), r)) / rule))
    listed = ", ".join(f"{c[2]:.2f} (H = {c[0]['H']:g}, {c[0]['angle']:g}°, h / h_stop = {c[1]:.2f}"
                       f"{', t = 2000' if c[0].get('study') == 'flowmap_long' else ''})" for c in cases)
    errs = [c[3] for c in cases if math.isfinite(c[3])]
    below = sum(1 for c in cases if math.isfinite(c[3]) and c[2] < 1 - 3 * c[3])
    text = f"Against Table 1's flow rule at each flow's own h / h_stop, F / F_Table1 = {listed}."
    if errs:
        text += (f" Each ratio's statistical error is at most {max(errs):.3f}; {below} of the {len(cases)} flows lie "
                 "more than three of their errors below the rule.")
    spread = rule_deviation(chute_fits, rows, paper_hstop)
    if math.isfinite(spread):
        text += (f" Their spread about the rule, err(F - F_Table1) of Eq. 49, is {spread:.3f}, against "
                 f"{PAPER_ERR['F']} for the paper's own steady flows about it. "
                 + spread_verdict(spread, PAPER_ERR["F"], len(rows)))
    if fit:
        g, g_se, b, b_se = fit["params"]["gamma"], fit["se"]["gamma"], fit["params"]["beta"], fit["se"]["beta"]
        if g_se > 0 and b_se > 0:
            zg, zb = abs(g - 0.040) / g_se, abs(b - 0.196) / b_se
            text += (f" The fit's gamma is {zg:.1f} standard errors from Table 1's 0.040 and its beta {zb:.1f} from "
                     f"0.196: the flows differ {'by a factor more than by a shift' if zb > zg else 'by a shift more than by a factor'}.")
    return [text + " The sensitivity checks below test the base damping convention, the time step and the base's realisation.", ""]


def pm(v, e, digits=4):
    return f"{v:.{digits}g} ± {e:.2g}" if math.isfinite(e) else f"{v:.{digits}g}"


def section(chute_fits, flowmap, long_rows, hs_talus, talus_determined, paper_hstop, base: Path, near_stop=()):
    """The report's lines on the flow map, the fits for table1.json ({"talus": block or None,
    "paper_hstop": block or None}) and the figure's path (None without steady flows). near_stop:
    the staircase's cases, whose steady flows near h_stop the figure shows as Fig. 11's dots (not
    fitted: they ran to t = 500 with a 20-unit average)."""
    rows = steady(with_long_runs(flowmap, long_rows))
    ran_on = sorted((r["H"], r["angle"]) for r in rows if r["study"] == "flowmap_long")
    lines = [f"**The flow map** (Sects. 7 and 9): {len(flowmap)} of its 16 cases (H = 10, 20, 30, 40; theta = 22, "
             "24, 26, 28°) have run, to t = 500, with depth profiles averaged over t in [400, 500]. "
             f"{len(steady(flowmap))} are steady at t = 500. The table gives them at t = 500; the fits below take "
             "a case from its run to t = 2000 (averaged over [1900, 2000], as the paper) where flowmap_long has one" +
             (" (" + ", ".join(f"H = {H:g} at {a:g}°" for H, a in ran_on) + ")" if ran_on else "") + ".", ""]
    if flowmap:
        lines += ["| H | theta | state | h (d) | F | h / h_stop (Table 1) | K | alpha | bulk volume fraction |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for r in sorted(flowmap, key=lambda r: (r["H"], r["angle"])):
            def num(k, fmt=".3f"):
                return format(r[k], fmt) if r.get(k) not in ("", None) else ""
            ratio = ""
            if r.get("h") not in ("", None):
                ratio = f"{r['h'] / float(chute_fits.hstop35(r['angle'], **paper_hstop)):.2f}"
            F = pm(r["froude"], froude_error(case_folder(base, "flowmap", r)), 3) if r.get("froude") not in ("", None) else ""
            lines.append(f"| {r['H']:g} | {r['angle']:g}° | {r['flow_state']} | {num('h', '.2f')} | {F} | {ratio} | "
                         f"{num('K')} | {num('alpha')} | {num('bulk_volume_fraction')} |")
        lines.append("")
    fits = {"talus": flow_rule(chute_fits, rows, hs_talus) if hs_talus and talus_determined else None,
            "paper_hstop": flow_rule(chute_fits, rows, paper_hstop)}
    if fits["paper_hstop"]:
        lines += ["The flow rule F = beta h / h_stop(theta) - gamma (Eq. 47) through the steady flows, with Talus' own "
                  "h_stop fit (Eq. 35) and with the paper's Table 1 curve, which Talus' arrest intervals bracket:", "",
                  "| h_stop from | flows | beta | gamma | err(F) |", "|---|---|---|---|---|"]
        for key, label in (("talus", "Talus' Eq. 35 fit"), ("paper_hstop", "Weinhart et al. 2012, Table 1")):
            b = fits[key]
            if b:
                lines.append(f"| {label} | {b['n']} | {pm(b['params']['beta'], b['se']['beta'])} | "
                             f"{pm(b['params']['gamma'], b['se']['gamma'])} | {b['err']:.3f} |")
            else:
                lines.append(f"| {label} | | not determined | | |")
        lines += ["", "Weinhart et al. 2012, Table 1: beta = 0.196, gamma = 0.040, err(F) = 0.121 (over all its "
                  "steady flows, H = 10 to 40).", ""]
        lines += rule_ratio_lines(chute_fits, rows, paper_hstop, base, fits["paper_hstop"])
    near = steady(near_stop)
    if len(near) >= 2:
        x = np.array([r["h"] / float(chute_fits.hstop35(r["angle"], **paper_hstop)) for r in near])
        d = np.array([r["froude"] for r in near]) - (0.196 * x - 0.040)
        lines += [f"The staircase's {len(near)} steady flows near h_stop (h / h_stop = {x.min():.2f} to {x.max():.2f} "
                  f"on Table 1's curve; t = 500, 20-unit averages) lie off Table 1's flow rule by {d.mean():+.3f} ± "
                  f"{d.std(ddof=1) / math.sqrt(len(d)):.3f} in F on average (the paper's err(F) over its steady flows "
                  "is 0.121).", ""]
    close = closures(chute_fits, rows, paper_hstop)
    if close:
        lines += ["Closures (Sect. 9.2) over the same steady flows: each one's fit where the cases determine it, "
                  "and the rms deviation (Eq. 49) of Talus' cases from the paper's closure with its constants:", "",
                  "| closure | Talus fit | Weinhart et al. 2012 | err(Talus - paper's closure) | paper's err |",
                  "|---|---|---|---|---|"]
        labels = {"bulk_volume_fraction": ("Eq. 52, bulk volume fraction", ("c0", "c1", "c2")),
                  "K": ("Eq. 53, K = sigma_xx / sigma_zz", ("d0", "d1")),
                  "alpha": ("Eq. 54, shape factor alpha", ("d_lambda",))}
        for key, (label, names) in labels.items():
            b = close.get(key)
            if not b:
                continue
            fit = ", ".join(f"{n} = {pm(b['params'][n], b['se'][n])}" for n in names) if "params" in b else \
                "too few angles"
            paper = ", ".join(f"{n} = {PAPER[n]:g}" for n in names)
            lines.append(f"| {label} | {fit} | {paper} | {b['paper_err']:.3f} | {PAPER_ERR[key]} |")
        lines.append("")
    checks = length_check(flowmap, long_rows, base)
    lines += ["**Run length.** The map's runs end at t = 500, the paper's at t = 2000. The same cases run to t = 2000 "
              "(flowmap_long; Froude numbers with batch-mean standard errors over the last 100 time units):", ""]
    if checks:
        lines += ["| H | theta | F, t = 500 | F, t = 2000 | h, t = 500 / 2000 | difference |", "|---|---|---|---|---|---|"]
        for c in checks:
            lines.append(f"| {c['H']:g} | {c['angle']:g}° | {pm(c['F_short'], c['F_short_err'], 3)} | "
                         f"{pm(c['F_long'], c['F_long_err'], 3)} | {c['h_short']:.2f} / {c['h_long']:.2f} | "
                         f"{c['sigmas']:.1f} sigma |")
        lines.append("")
        lines += length_effect_lines(checks, fits.get("paper_hstop"), chute_fits, rows, paper_hstop)
    else:
        lines += ["None has finished yet: until one has, the shorter runs are not shown to be long enough.", ""]
    lines += trend_lines(steady(flowmap), base, checks)
    figure = plot(chute_fits, rows, fits, paper_hstop, base / "weinhart2012", steady(near_stop)) if rows else None
    return lines, fits, figure


def plot(chute_fits, flowmap, fits, paper_hstop, out: Path, near_stop=()):
    """Fig. 11 (F against h / h_stop) and Figs. 12-13's closures against theta."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = steady(flowmap)
    fig, axes = plt.subplots(1, 4, figsize=(16, 4))
    x = np.array([r["h"] / float(chute_fits.hstop35(r["angle"], **paper_hstop)) for r in rows])
    F = np.array([r["froude"] for r in rows])
    ax = axes[0]
    if near_stop:
        ax.plot([r["h"] / float(chute_fits.hstop35(r["angle"], **paper_hstop)) for r in near_stop],
                [r["froude"] for r in near_stop], "k.", label="Talus, h_stop staircase (steady at t = 500)")
    for H in sorted({r["H"] for r in rows}):
        pick = [i for i, r in enumerate(rows) if r["H"] == H]
        ax.plot(x[pick], F[pick], "o", label=f"Talus, H = {H:g}")
    xs = np.linspace(0, max(x.max(), 1) * 1.1, 50)
    ax.plot(xs, 0.196 * xs - 0.040, "k-", lw=1, label="Table 1: 0.196 x - 0.040")
    b = fits.get("paper_hstop")
    if b:
        ax.plot(xs, b["params"]["beta"] * xs - b["params"]["gamma"], "r--", lw=1, label="Talus fit")
    ax.set(xlabel="h / h_stop(theta) (Table 1's curve)", ylabel="F = u / sqrt(g h cos theta)",
           title="flow rule (Fig. 11)")
    ax.legend(fontsize=7)
    theta = np.array([r["angle"] for r in rows])
    grid = np.linspace(20, 30, 100)
    for ax, key, curve, label in (
            (axes[1], "bulk_volume_fraction", chute_fits.density52(grid, PAPER["c0"], PAPER["c1"], PAPER["c2"]),
             "bulk volume fraction (Fig. 12)"),
            (axes[2], "K", chute_fits.stress_ratio53(grid, PAPER["d0"], PAPER["d1"]), "K = sigma_xx / sigma_zz"),
            (axes[3], "alpha", None, "shape factor alpha (Fig. 13)")):
        pts = [(r["angle"], r[key]) for r in rows if r.get(key) not in ("", None)]
        if pts:
            ax.plot(*zip(*pts), "o", label="Talus")
        if curve is not None:
            ax.plot(grid, curve, "k-", lw=1, label="Weinhart et al. 2012")
        else:
            predicted = chute_fits.shape_factor54([r["h"] for r in rows], theta, PAPER["d_lambda"], paper_hstop)
            ax.plot(theta, predicted, "kx", label="Eq. 54 with Table 2's d_lambda")
        ax.set(xlabel="theta (deg)", title=label)
        ax.legend(fontsize=7)
    fig.tight_layout()
    path = out / "flow_rule_lambda1.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path
