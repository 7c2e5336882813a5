"""How finely one h_stop staircase can resolve Table 1's A, delta1 and delta2, whichever code runs it.

Synthetic staircases walk the search of Weinhart et al. 2012, Sect. 6 (hstop_staircase.Staircase,
from H = 4 at 21 deg as the study does) on outcomes drawn from Table 1's curve: a case of height H
flows with probability Phi((theta - theta_stop(h)) / sigma) (Eq. 35 for theta_stop), h the flow
height of Talus' layers of that H (a line through the staircase's cases) and sigma the scatter of
one realisation's arrest about the curve that Talus' own cases give. Each synthetic staircase is
fitted as Talus' is: Eq. 35 through the interval midpoints, and every case at once by maximum
likelihood. The spread of those fits is what a staircase can tell when the paper's curve is true;
where Talus' fits fall in it says whether they disagree with Table 1 beyond that."""
import math

import numpy as np

import validation_hstop_mle
from validation_summary import within

REPLICAS = 200
SEED = 2012
START = {"H0": 4.0, "theta0": 21.0, "theta_min": 10.0, "max_cases": 60}  # the study's defaults (cli.py)


def height_line(rows):
    """h = a H + b through the staircase's cases (h measured as Eq. 42); None with under 3 heights."""
    pts = sorted((float(r["H"]), float(r["h"])) for r in rows if r.get("h") not in ("", None) and math.isfinite(float(r["h"])))
    if len({H for H, _ in pts}) < 3:
        return None
    a, b = np.polyfit([H for H, _ in pts], [h for _, h in pts], 1)
    return float(a), float(b)


def synthetic_staircase(staircase_class, chute_fits, paper, sigma, line, h_max, rng):
    """The rows (H, h, angle, arrested) of one staircase walked on outcomes drawn from `paper`'s curve."""
    walk = staircase_class(1.0, START["H0"], START["theta0"], h_max, START["theta_min"], START["max_cases"])
    rows = []
    while walk.case:
        _, H, theta = walk.case
        h = line[0] * H + line[1]
        z = (theta - float(chute_fits.theta_stop35(h, paper["A"], paper["delta1"], paper["delta2"]))) / sigma
        flows = rng.random() < 0.5 * math.erfc(-z / math.sqrt(2))  # Phi(z)
        rows.append({"lambda": 1.0, "H": H, "h": h, "angle": theta, "arrested": int(not flows)})
        walk.advance(not flows)
    return rows


def interval_fit(chute_fits, rows):
    ang = [r for r in chute_fits.arrest_intervals(rows) if r["kind"] == "angle"]
    if len(ang) < 3:
        return None
    try:
        p, _, _ = chute_fits.fit_hstop35([r["h"] for r in ang], [0.5 * (r["angle_lo"] + r["angle_hi"]) for r in ang])
    except RuntimeError:  # curve_fit found no minimum
        return None
    return p


INTERVALS, LIKELIHOOD = "interval midpoints (Eq. 35)", "every case (max. likelihood)"


def ensemble(staircase_class, chute_fits, paper, sigma, line, h_max, replicas, seed=SEED):
    """Over `replicas` synthetic staircases: {estimator label: {name: array of fitted values}}, and
    the array of likelihood-ratio statistics of Table 1's curve against the best one."""
    rng = np.random.default_rng(seed)
    out = {label: {name: [] for name in validation_hstop_mle.NAMES} for label in (INTERVALS, LIKELIHOOD)}
    stats = []
    for _ in range(replicas):
        rows = synthetic_staircase(staircase_class, chute_fits, paper, sigma, line, h_max, rng)
        likely, stat = validation_hstop_mle.point_fit(chute_fits, validation_hstop_mle.cases_of(rows), paper)
        stats.append(stat)
        for label, p in ((INTERVALS, interval_fit(chute_fits, rows)), (LIKELIHOOD, likely and likely["params"])):
            if p:
                for name in validation_hstop_mle.NAMES:
                    out[label][name].append(float(p[name]))
    return {label: {k: np.array(v) for k, v in values.items()} for label, values in out.items()}, np.array(stats)


def lines(staircase_class, chute_fits, rows, paper, bars, sigma, talus, talus_test):
    """The report's paragraph and table, and its verdict in a sentence or two. `talus`: {estimator
    label: {name: value}}, Talus' own fits; `talus_test`: the likelihood-ratio statistic of Table 1's
    curve against Talus' cases and its chi-squared p-value (validation_hstop_mle.against_paper)."""
    talus_stat, chi2_p = talus_test
    line = height_line(rows)
    if line is None or not sigma:
        return [], ""
    out = [f"**What one staircase can resolve.** {REPLICAS} synthetic staircases, each walking the search of Sect. 6 "
           f"from H = {START['H0']:g} at {START['theta0']:g}° to H = 40 on outcomes drawn from Table 1's curve with the "
           f"scatter sigma = {sigma:.3f}° that Talus' cases give (h = {line[0]:.3f} H {line[1]:+.2f}, as Talus' layers), "
           "fitted as Talus' staircase is. The spread is what the method resolves if the paper's curve is true; the "
           "last column places Talus' fit in it.", "",
           "| fit | quantity | Table 1 | 16 to 84 % of the synthetic fits | within the bar | Talus | Talus' percentile |",
           "|---|---|---|---|---|---|---|"]
    fits, stats = ensemble(staircase_class, chute_fits, paper, sigma, line, 40.0, REPLICAS)
    outside, shares = [], {label: {} for label in fits}
    for label, values in fits.items():
        for name in validation_hstop_mle.NAMES:
            v = values[name]
            if len(v) == 0:
                continue
            lo, hi = np.percentile(v, [16, 84])
            share = shares[label][name] = 100 * np.mean([within(x, paper[name], bars[name]) for x in v])
            mine = talus.get(label, {}).get(name)
            percentile = 100 * np.mean(v < mine) if mine is not None else None
            where = f"{percentile:.0f}" if percentile is not None else "-"
            if percentile is not None and not 5 <= percentile <= 95:
                outside.append(f"{name} of the {label} fit ({percentile:.0f})")
            mine_text = f"{mine:.4g}" if mine is not None else "-"
            out.append(f"| {label} | {name} | {paper[name]:g} | {lo:.4g} to {hi:.4g} | {share:.0f} % of "
                       f"{len(v)} | {mine_text} | {where} |")
    fitted = len(fits[LIKELIHOOD]["A"])
    resolved = ("Drawn from Table 1's curve itself, one staircase's interval fit meets the bars on " +
                ", ".join(f"{name} in {share:.0f} %" for name, share in shares[INTERVALS].items()) + " of cases. ")
    verdict = (resolved + ("Every fit of Talus' staircase lies within the central 90 % of the synthetic ones: Talus' "
                           "staircase agrees with Table 1's curve as closely as a staircase drawn from that curve does, "
                           "parameter by parameter." if not outside else
                           "Outside the central 90 % of the synthetic fits (percentile): " + ", ".join(outside) + ".") +
               f" Jointly, the likelihood ratio of Table 1's curve against the best one reaches Talus' "
               f"{talus_stat:.1f} in {100 * np.mean(stats >= talus_stat):.0f} % of the synthetic staircases (the "
               f"chi-squared law for 3 parameters says {100 * chi2_p:.1f} %).")
    out += ["", f"The maximum-likelihood fit exists for {fitted} of the {REPLICAS} synthetic staircases; in the others "
            "a range of curves separates the arrested cases from the flowing ones exactly (sigma -> 0), and the fit is "
            "not unique. Close to that limit a ridge of curves fits almost as well: the order in which the cases "
            "enter the likelihood moved a few of the synthetic fits by up to 0.3° along it (now fixed by sorting them), "
            "so the shares of maximum-likelihood fits within a bar are uncertain by a few per cent. " + verdict, ""]
    return out, verdict
