"""Closure fits of Weinhart et al. 2012 with standard errors, from a chute sweep and h_stop search:
h_stop(theta) (Eq. 35 and Eq. 38), the flow rule F = beta h/h_stop - gamma (Eqs. 36, 47), the
friction law it implies (Eqs. 37, 50), the bulk density (Eq. 52), the stress ratio K (Eq. 53)
and the shape factor alpha (Eqs. 54-55). Angles in degrees, lengths in particle diameters d.
Each fit returns its parameters, their standard errors (square roots of the diagonal of the
least-squares covariance, scaled by the residual variance) and err of Eq. 49.

Usage: python3 -m talus fit DIR   (reads DIR/hstop_intervals.csv and DIR/sweep_runs.csv or
       DIR/hstop_runs.csv; fits each base roughness lambda found there; writes DIR/fits.json and
       DIR/fits.md, the analogue of Tables 1-2)
"""
import csv
import json
import math
import os
import sys

import numpy as np
from scipy.optimize import curve_fit

T = lambda deg: np.tan(np.radians(deg))  # noqa: E731

# Weinhart et al. 2012, Table 1, lambda = 1: the starting point of the h_stop fits.
TABLE1_LAMBDA1 = {"A": 3.355, "delta1": 17.708, "delta2": 32.780, "beta": 0.196, "gamma": 0.040}


def err(x):
    """Weinhart et al. 2012, Eq. (49): (sum x_i^2 / (N - 1))^(1/2)."""
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.sum(x * x) / (len(x) - 1))) if len(x) > 1 else float("nan")


def hstop35(theta, A, delta1, delta2):
    """Weinhart et al. 2012, Eq. (35): h_stop / d = A (tan d2 - tan theta) / (tan theta - tan d1)."""
    return A * (T(delta2) - T(theta)) / (T(theta) - T(delta1))


def theta_stop35(h, A, delta1, delta2):
    """Eq. (35) solved for theta: tan theta = (tan d2 + (h/A) tan d1) / (1 + h/A)."""
    x = np.asarray(h, dtype=float) / A
    return np.degrees(np.arctan((T(delta2) + x * T(delta1)) / (1 + x)))


def hstop38(theta, A, delta1, delta2):
    """Eq. (38), Pouliquen 1999: tan theta_stop = tan d1 + (tan d2 - tan d1) exp(-h / (A d)), i.e.
    h / (A d) = ln((tan d2 - tan d1) / (tan theta - tan d1)). (The extracted text prints the
    inverse ratio, which would make h negative for d1 < theta < d2; derived again here.)"""
    return A * np.log((T(delta2) - T(delta1)) / (T(theta) - T(delta1)))


def _fit(f, x, y, p0, bounds=(-np.inf, np.inf)):
    p, cov = curve_fit(f, x, y, p0=p0, bounds=bounds, maxfev=20000)
    se = np.sqrt(np.diag(cov)) if np.all(np.isfinite(cov)) else np.full(len(p), np.nan)
    return p, se, err(np.asarray(y) - f(x, *p))


def fit_hstop35(h, theta):
    """Eq. (35) through points (h_i, theta_i) (interval midpoints), minimising the horizontal
    (angle) distance as in Sect. 6. Returns ({A, delta1, delta2}, standard errors, err in deg)."""
    h, theta = np.asarray(h, float), np.asarray(theta, float)
    p0 = [TABLE1_LAMBDA1["A"], min(TABLE1_LAMBDA1["delta1"], theta.min() - 0.5), max(TABLE1_LAMBDA1["delta2"], theta.max() + 0.5)]
    bounds = ([1e-3, 0, theta.max()], [1e3, theta.min(), 89])
    p, se, e = _fit(theta_stop35, h, theta, p0, bounds)
    names = ["A", "delta1", "delta2"]
    return dict(zip(names, p)), dict(zip(names, se)), e


def fit_hstop38(theta, h):
    """Eq. (38) through points (theta_i, h_i), minimising the vertical (height) distance."""
    theta, h = np.asarray(theta, float), np.asarray(h, float)
    p0 = [5.0, theta.min() - 1.0, theta.max() + 2.0]
    bounds = ([1e-3, 0, theta.max()], [1e3, theta.min(), 89])
    p, se, e = _fit(hstop38, theta, h, p0, bounds)
    names = ["A", "delta1", "delta2"]
    return dict(zip(names, p)), dict(zip(names, se)), e


def fit_flow_rule(h, theta, F, hs):
    """Eqs. (36)/(47): F = beta h / h_stop(theta) - gamma, h_stop from Eq. (35) with `hs`."""
    x = np.asarray(h, float) / hstop35(np.asarray(theta, float), hs["A"], hs["delta1"], hs["delta2"])
    p, se, e = _fit(lambda x, b, g: b * x - g, x, np.asarray(F, float), [0.2, 0.0])
    return {"beta": p[0], "gamma": p[1]}, {"beta": se[0], "gamma": se[1]}, e


def friction_law(h, F, hs, beta, gamma):
    """Eqs. (37)/(50): mu = tan d1 + (tan d2 - tan d1) / (beta h / (A d (F + gamma)) + 1)."""
    return T(hs["delta1"]) + (T(hs["delta2"]) - T(hs["delta1"])) / (
        beta * np.asarray(h, float) / (hs["A"] * (np.asarray(F, float) + gamma)) + 1)


def density52(theta, c0, c1, c2):
    """Weinhart et al. 2012, Eq. (52a): rho_c / rho_p = c0 - exp((theta - c2) / c1), angles in deg.
    (The extracted text reads exp(theta - c2)/c1; with c1 = 4.8 deg only the exponent form gives
    the paper's bulk volume fractions near 0.57.)"""
    return c0 - np.exp((np.asarray(theta, float) - c2) / c1)


def fit_density(theta, phi):
    p, se, e = _fit(density52, theta, phi, [0.5985, 4.8, 40.85], ([0, 0.1, 0], [1, 100, 90]))
    names = ["c0", "c1", "c2"]
    return dict(zip(names, p)), dict(zip(names, se)), e


def stress_ratio53(theta, d0, d1):
    """Weinhart et al. 2012, Eq. (53): K = 1 + (theta - d1) / d0, angles in deg."""
    return 1 + (np.asarray(theta, float) - d1) / d0


def fit_stress_ratio(theta, K):
    p, se, e = _fit(stress_ratio53, theta, K, [132.0, 21.5])
    return {"d0": p[0], "d1": p[1]}, {"d0": se[0], "d1": se[1]}, e


def shape_factor54(h, theta, d_lambda, hs1, n=400):
    """Shape factor alpha = mean(u^2) / mean(u)^2 of the velocity model of Eqs. (54a-c): Bagnold
    strain in the bulk, constant strain in the top 5 d, strain falling linearly to 1/3 of its
    value at the base of a layer of thickness b_lambda = d_lambda h_stop(theta, 1) / h (in d,
    Eq. 54c), u(0) = 0. Heights in d, base at z = 0."""
    out = []
    for hi, th in zip(np.atleast_1d(np.asarray(h, float)), np.atleast_1d(np.asarray(theta, float))):
        z = np.linspace(0, hi, n)
        # Clamped: above delta2 Eq. (35) gives a negative h_stop, i.e. no base layer at all.
        bl = min(max(d_lambda * hstop35(th, hs1["A"], hs1["delta1"], hs1["delta2"]) / hi, 0.0), hi)
        dub = lambda zz: 1.5 * np.sqrt(np.maximum(hi - zz, 0.0))  # d/dz of (1 - ((h - z)/h)^1.5) h^1.5  # noqa: E731
        top = max(hi - 5, bl)
        strain = np.where(z < bl, dub(bl) * (1 - 2.0 / 3.0 * (bl - z) / max(bl, 1e-12)),
                          np.where(z < top, dub(z), dub(top)))
        u = np.concatenate([[0], np.cumsum(0.5 * (strain[1:] + strain[:-1]) * np.diff(z))])
        out.append(np.trapz(u * u, z) / hi / (np.trapz(u, z) / hi) ** 2)
    return np.array(out)


def fit_shape_factor(h, theta, alpha, hs1):
    """d_lambda of Eq. (54c) for rough bases (lambda >= 5/6)."""
    h, theta = np.asarray(h, float), np.asarray(theta, float)
    p, se, e = _fit(lambda x, d: shape_factor54(h, theta, d, hs1), np.zeros(len(h)), np.asarray(alpha, float), [5.0],
                    ([0.0], [1e3]))
    return {"d_lambda": p[0]}, {"d_lambda": se[0]}, e


def shape_factor55(lam, n=2001):
    """alpha of the velocity profiles of Eq. (55) for smooth bases (lambda <= 2/3)."""
    zeta = np.linspace(0, 1, n)
    if lam == 0:
        return 1.0
    f = 5.0 / 3.0 - (1 - zeta) ** 2
    if abs(lam - 0.5) < 1e-9:
        f = 0.16 + 0.84 * f
    return float(np.trapz(f * f, zeta) / np.trapz(f, zeta) ** 2)


def fit_constant(y):
    y = np.asarray(y, float)
    m = float(np.mean(y))
    return m, float(np.std(y, ddof=1) / math.sqrt(len(y))) if len(y) > 1 else float("nan"), err(y - m)


def arrest_intervals(rows):
    """Angle intervals per (lambda, H) and height intervals per (lambda, theta) between the
    largest arrested and smallest flowing value of a staircase's cases (rows of hstop_runs.csv,
    finished or not); heights h measured from sigma_zz (Eq. 42)."""
    out = []
    by = {}
    for r in rows:
        by.setdefault((r["lambda"], r["H"]), []).append(r)
    for (lam, H), rs in sorted(by.items()):
        arr = [r for r in rs if r["arrested"]]
        flo = [r for r in rs if not r["arrested"]]
        if arr and flo:
            a = max(arr, key=lambda r: r["angle"])
            f = min(flo, key=lambda r: r["angle"])
            if a["angle"] < f["angle"]:
                hs = [x["h"] for x in (a, f) if x["h"] not in (None, "")]
                out.append({"lambda": lam, "kind": "angle", "H": H, "h": sum(hs) / len(hs) if hs else "",
                            "angle_lo": a["angle"], "angle_hi": f["angle"], "h_lo": "", "h_hi": ""})
    by = {}
    for r in rows:
        by.setdefault((r["lambda"], r["angle"]), []).append(r)
    for (lam, th), rs in sorted(by.items()):
        arr = [r for r in rs if r["arrested"]]
        flo = [r for r in rs if not r["arrested"]]
        if arr and flo:
            a = max(arr, key=lambda r: r["H"])
            f = min(flo, key=lambda r: r["H"])
            if a["H"] < f["H"]:
                out.append({"lambda": lam, "kind": "height", "H": "", "h": "", "angle_lo": th, "angle_hi": th,
                            "h_lo": a["h"] if a["h"] is not None else "", "h_hi": f["h"] if f["h"] is not None else ""})
    return out



# --- the command line -----------------------------------------------------------------------

def _read(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in list(r.items()):
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


def fit_all(intervals, runs, lam):
    out = {"lambda": lam}
    iv = [r for r in intervals if r["lambda"] == lam]
    ang = [r for r in iv if r["kind"] == "angle" and r["h"] != ""]
    hgt = [r for r in iv if r["kind"] == "height" and r["h_lo"] != "" and r["h_hi"] != ""]
    hs = None
    if len(ang) >= 3:
        hs, se, e = fit_hstop35([r["h"] for r in ang], [0.5 * (r["angle_lo"] + r["angle_hi"]) for r in ang])
        out["hstop35"] = {"params": hs, "se": se, "err_deg": e, "n": len(ang)}
    if len(hgt) >= 3:
        p, se, e = fit_hstop38([r["angle_lo"] for r in hgt], [0.5 * (r["h_lo"] + r["h_hi"]) for r in hgt])
        out["hstop38"] = {"params": p, "se": se, "err": e, "n": len(hgt)}
    steady = [r for r in runs if r["lambda"] == lam and r.get("flow_state") == "steady" and r.get("h") not in ("", None)]
    if hs and len(steady) >= 3:
        p, se, e = fit_flow_rule([r["h"] for r in steady], [r["angle"] for r in steady], [r["froude"] for r in steady], hs)
        out["flow_rule"] = {"params": p, "se": se, "err": e, "n": len(steady)}
        mu = friction_law([r["h"] for r in steady], [r["froude"] for r in steady], hs, p["beta"], p["gamma"])
        out["friction_law"] = {"err_mu": err(mu - T(np.array([r["angle"] for r in steady])))}
        if lam >= 5.0 / 6.0 - 1e-9 and len(steady) >= 2:
            try:
                p, se, e = fit_shape_factor([r["h"] for r in steady], [r["angle"] for r in steady],
                                            [r["alpha"] for r in steady], hs)
                out["shape_factor"] = {"params": p, "se": se, "err": e}
            except ValueError:
                pass  # a flow thinner than its base layer (h <= b_lambda): Eq. (54) has no profile there
    if len(steady) >= 3:
        bulk = [r for r in steady if r.get("bulk_volume_fraction") not in ("", None)]
        if len(bulk) >= 4:
            p, se, e = fit_density([r["angle"] for r in bulk], [r["bulk_volume_fraction"] for r in bulk])
            out["density"] = {"params": p, "se": se, "err": e, "n": len(bulk)}
        p, se, e = fit_stress_ratio([r["angle"] for r in steady], [r["K"] for r in steady])
        out["stress_ratio"] = {"params": p, "se": se, "err": e, "n": len(steady)}
        if lam <= 2.0 / 3.0 + 1e-9:
            m, s, e = fit_constant([r["alpha"] for r in steady])
            out["shape_factor"] = {"params": {"alpha": m}, "se": {"alpha": s}, "err": e, "eq55": shape_factor55(lam)}
    return out


def markdown(fits):
    def pm(block, key):
        if not block:
            return "-"
        return "%.4g ± %.2g" % (block["params"][key], block["se"][key])
    lines = ["| lambda | delta1 | delta2 | A | beta | gamma | err(F) |", "|---|---|---|---|---|---|---|"]
    for f in fits:
        h, r = f.get("hstop35"), f.get("flow_rule")
        lines.append("| %g | %s | %s | %s | %s | %s | %s |" % (f["lambda"], pm(h, "delta1"), pm(h, "delta2"), pm(h, "A"),
                     pm(r, "beta"), pm(r, "gamma"), "%.3g" % r["err"] if r else "-"))
    lines += ["", "| lambda | alpha or d_lambda | err | c0 | c1 | c2 | d0 | d1 |", "|---|---|---|---|---|---|---|---|"]
    for f in fits:
        s, d, k = f.get("shape_factor"), f.get("density"), f.get("stress_ratio")
        sk = None if not s else ("alpha" if "alpha" in s["params"] else "d_lambda")
        lines.append("| %g | %s | %s | %s | %s | %s | %s | %s |" % (
            f["lambda"], pm(s, sk) if s else "-", "%.3g" % s["err"] if s else "-", pm(d, "c0"), pm(d, "c1"),
            pm(d, "c2"), pm(k, "d0"), pm(k, "d1")))
    return "\n".join(lines) + "\n"


def fit_folder(folder):
    """Fits every lambda of a sweep / h_stop folder; writes fits.json and fits.md into it."""
    intervals = _read(os.path.join(folder, "hstop_intervals.csv"))
    runs = _read(os.path.join(folder, "sweep_runs.csv")) + _read(os.path.join(folder, "hstop_runs.csv"))
    lams = sorted({r["lambda"] for r in intervals} | {r["lambda"] for r in runs})
    fits = [fit_all(intervals, runs, lam) for lam in lams]
    clean = json.loads(json.dumps(fits, default=float))
    for name, text in (("fits.json", json.dumps(clean, indent=2) + "\n"), ("fits.md", markdown(fits))):
        tmp = os.path.join(folder, name + ".tmp")
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, os.path.join(folder, name))
    sys.stdout.write(markdown(fits))
