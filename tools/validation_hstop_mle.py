"""The h_stop curve (Weinhart et al. 2012, Eq. 35) from every case of the staircase at once, by
maximum likelihood: a case of height h at angle theta flows with probability
Phi((theta - theta_stop(h)) / sigma), sigma the scatter of one realisation's arrest about the
curve. The interval fits use two cases per height or angle and drop the rest; this reads the
thick layers' one-sided outcomes too (an arrest at H = 28 and a flow at H = 40 bound the curve at
20 degrees without an interval). Intervals of 68 % from the profile likelihood (a drop of 1/2 in
log-likelihood), which the curve's strong parameter correlations make asymmetric; the paper's
curve, with only its own sigma free, is set against the fit by a likelihood-ratio test."""
import math

import numpy as np

import validation_summary

NAMES = ("A", "delta1", "delta2")


def cases_of(rows):
    """(h, theta, flowing) of each staircase row with a measured height, sorted: where a ridge of
    curves fits the outcomes almost equally well, the order of the sum in the likelihood steers the
    minimiser along it, and the table's order (the staircase's, or the kept cases') would change the
    report."""
    out = []
    for r in rows:
        if r.get("h") in ("", None) or not math.isfinite(float(r["h"])):
            continue
        out.append((float(r["h"]), float(r["angle"]), 0 if int(r.get("arrested") or 0) else 1))
    return sorted(out)


def _nll(chute_fits, cases, A, d1, d2, log_sigma):
    from scipy.stats import norm
    if A <= 0 or not d1 < d2:
        return 1e12
    h = np.array([c[0] for c in cases])
    theta = np.array([c[1] for c in cases])
    flowing = np.array([c[2] for c in cases])
    z = (theta - chute_fits.theta_stop35(h, A, d1, d2)) / math.exp(log_sigma)
    return -float(np.sum(np.where(flowing == 1, norm.logcdf(z), norm.logcdf(-z))))


def _minimise(f, starts):
    from scipy.optimize import minimize
    best = None
    for x0 in starts:
        r = minimize(f, x0, method="Nelder-Mead", options={"maxiter": 40000, "xatol": 1e-7, "fatol": 1e-10})
        if best is None or r.fun < best.fun:
            best = r
    return best


def _best(chute_fits, cases, start):
    """(the negative log-likelihood, its minimum), or None (see fit)."""
    if len(cases) < 6 or len({c[2] for c in cases}) < 2:
        return None
    f = lambda p: _nll(chute_fits, cases, *p)  # noqa: E731
    starts = [[a, start[1], start[2], s] for a in (start[0], 2 * start[0]) for s in (-3.0, -1.5)]
    best = _minimise(f, starts)
    if math.exp(best.x[3]) < 1e-3:
        return None
    return f, best


def point_fit(chute_fits, cases, paper):
    """The maximum-likelihood curve without its intervals, {"params", "sigma"} or None as fit, and
    the likelihood-ratio statistic of against_paper. Where a range of curves separates the
    outcomes exactly, the best likelihood is 1 (sigma -> 0) and the fit None."""
    found = _best(chute_fits, cases, (paper["A"], paper["delta1"], paper["delta2"]))
    f = lambda q: _nll(chute_fits, cases, paper["A"], paper["delta1"], paper["delta2"], q[0])  # noqa: E731
    stat = 2 * (float(_minimise(f, [[-3.0], [-1.5], [0.0]]).fun) - (float(found[1].fun) if found else 0.0))
    if found is None:
        return None, stat
    best = found[1]
    return {"params": dict(zip(NAMES, map(float, best.x[:3]))), "sigma": math.exp(best.x[3])}, stat


def fit(chute_fits, cases, start=(3.355, 17.708, 32.78)):
    """The maximum-likelihood curve: {"params": {A, delta1, delta2}, "sigma", "nll", "interval":
    {name: (lo, hi)}, "n", "flowing"}; None with fewer than 6 cases or no overlap of outcomes to
    set a scale (a curve that separates every case has sigma -> 0 and no interval)."""
    found = _best(chute_fits, cases, start)
    if found is None:
        return None
    f, best = found
    interval = {}
    for k, name in enumerate(NAMES):
        interval[name] = (_bound(f, best, k, -1), _bound(f, best, k, +1))
    return {"params": dict(zip(NAMES, map(float, best.x[:3]))), "sigma": math.exp(best.x[3]), "nll": float(best.fun),
            "interval": interval, "n": len(cases), "flowing": sum(c[2] for c in cases)}


def _bound(f, best, k, side):
    """Where the profile likelihood of parameter k has dropped by 1/2 on one side of the best fit
    (nan if it does not within a factor 4 of the parameter's value)."""
    from scipy.optimize import brentq
    x_best = best.x[k]

    def drop(v):
        rest = [best.x[i] for i in range(4) if i != k]
        g = lambda q: f(list(q[:k]) + [v] + list(q[k:]))  # noqa: E731
        return _minimise(g, [rest]).fun - best.fun - 0.5

    step = 0.05 * abs(x_best) if x_best != 0 else 0.1
    lo_v, hi_v = x_best, x_best + side * step
    for _ in range(40):
        if drop(hi_v) > 0:
            return float(brentq(drop, min(lo_v, hi_v), max(lo_v, hi_v), xtol=1e-4 * abs(x_best)))
        lo_v, hi_v = hi_v, hi_v + side * step
        step *= 1.5
        if abs(hi_v - x_best) > 4 * abs(x_best) or (k == 0 and hi_v <= 0):
            break
    return math.nan


def against_paper(chute_fits, cases, fitted, paper):
    """The paper's curve with its own best sigma: (its sigma, the likelihood-ratio statistic
    2 (nll_paper - nll_fit), its p-value for 3 degrees of freedom)."""
    from scipy.stats import chi2
    f = lambda q: _nll(chute_fits, cases, paper["A"], paper["delta1"], paper["delta2"], q[0])  # noqa: E731
    r = _minimise(f, [[-3.0], [-1.5], [0.0]])
    stat = 2 * (float(r.fun) - fitted["nll"])
    return math.exp(r.x[0]), stat, float(chi2.sf(max(stat, 0.0), 3))


def half_width(interval):
    lo, hi = interval
    return 0.5 * (hi - lo) if math.isfinite(lo) and math.isfinite(hi) else math.nan


def lines(chute_fits, rows, paper, bars):
    """The report's paragraph, and the fit (None when there is none). `bars`: Table 1's agreement
    bars, {name: ("deg" | "relative", size)}."""
    cases = cases_of(rows)
    fitted = fit(chute_fits, cases)
    if not fitted:
        return [], None
    q, iv = fitted["params"], fitted["interval"]

    def show(name, digits):
        lo, hi = iv[name]
        v = q[name]
        return (f"{v:.{digits}f} (+{hi - v:.{digits}f} / -{v - lo:.{digits}f})" if math.isfinite(lo) and math.isfinite(hi)
                else f"{v:.{digits}f} (interval open)")

    sigma_p, stat, p = against_paper(chute_fits, cases, fitted, paper)
    within = []
    for name in NAMES:
        lo, hi = iv[name]
        diff = (f"{q[name] - paper[name]:+.2f}°" if bars[name][0] == "deg" else
                f"{100 * (q[name] / paper[name] - 1):+.0f} %")
        met = validation_summary.within(q[name], paper[name], bars[name])
        bar = validation_summary.bar_text(bars[name])
        within.append(f"{name} {diff}, {'within' if met else 'outside'} the {bar} bar, "
                      f"Table 1's value {'inside' if lo <= paper[name] <= hi else 'outside'} the interval")
    text = (f"**Every case at once** (maximum likelihood: a case at height h and angle theta flows with probability "
            f"Phi((theta - theta_stop(h)) / sigma), theta_stop from Eq. 35): the {fitted['n']} cases of the staircase "
            f"({fitted['flowing']} flowing) give A = {show('A', 2)}, delta1 = {show('delta1', 2)}°, delta2 = "
            f"{show('delta2', 2)}° (68 % profile-likelihood intervals) and a scatter sigma = {fitted['sigma']:.3f}° of one "
            f"realisation's arrest about the curve; Table 1: A = {paper['A']}, delta1 = {paper['delta1']}°, delta2 = "
            f"{paper['delta2']}° ({'; '.join(within)}). The paper's curve, with its own sigma ({sigma_p:.3f}°), "
            f"describes the outcomes worse: likelihood ratio 2 Delta(ln L) = {stat:.1f} for 3 parameters, "
            f"probability {p:.3f} of a larger value by the chi-squared law (the synthetic staircases below calibrate "
            "it). Unlike the interval fits this one reads the thick layers' "
            "single outcomes, which is what bounds A.")
    return ["", text], fitted
