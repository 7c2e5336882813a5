"""The report's check of Talus' speed approximations: each one's dam breaks against the same
columns with every contact computed, realisation for realisation at the same gate positions
(GJK from last step's simplex against a cold start; recycled manifold points against computed
ones). An approximation is fit to be a default when its differences stay within the scatter."""
import math

# (approximated family, reference family, what the approximation is)
PAIRS = [
    ("crosses_gjk_warm", "crosses", "GJK started from last step's simplex (contact.gjk_warm_start)"),
    ("crosses_manifold_recycle", "crosses_manifold",
     "manifold points recycled from their anchors for 10 um (contact.manifold_recycle)"),
]


def mean_err(xs):
    n = len(xs)
    m = sum(xs) / n
    if n < 2:
        return m, float("nan")
    return m, math.sqrt(sum((x - m) ** 2 for x in xs) / (n - 1) / n)


def observables(summary):
    db = summary.get("dam_break", {})
    return {"runout ratio (L_inf - L0)/L0": db.get("runout_ratio"), "height ratio H0/H_inf": db.get("height_ratio"),
            "coordination at the end": summary.get("coordination_number")}


def difference(runs, ref_runs, name):
    a = [observables(r)[name] for r in runs]
    b = [observables(r)[name] for r in ref_runs]
    if None in a or None in b or len(a) < 2 or len(b) < 2:
        return None
    (ma, ea), (mb, eb) = mean_err(a), mean_err(b)
    err = math.hypot(ea, eb)
    return ma - mb, err


# (approximated, reference, what): one realisation each, so the difference has no scatter of its own
SINGLE_COLUMNS = [
    ("crosses_large_recycle", "crosses_large", "the 12,000-cross column (Fig. 14) with recycled points"),
]


def single_column_lines(runs_by_family):
    """Markdown lines: one column run both ways, its observables side by side. The scatter
    between realisations is that of the small columns' pairs above, relative to their means,
    at best: a larger column averages over more crosses."""
    out = []
    for family, reference, what in SINGLE_COLUMNS:
        runs, ref = runs_by_family.get(family, []), runs_by_family.get(reference, [])
        if len(runs) != 1 or len(ref) != 1 or runs[0]["L0"] != ref[0]["L0"]:
            continue
        a, b = observables(runs[0]), observables(ref[0])
        cells = [f"{name} {a[name]:.3g} against {b[name]:.3g} ({100 * (a[name] / b[name] - 1):+.1f} %)"
                 for name in a if a[name] is not None and b[name]]
        regimes = f"{runs[0].get('regime', '')} against {ref[0].get('regime', '')}"
        out.append(f"- {what}, L0 = {runs[0]['L0']:g} m, one run of `{family}` against one of `{reference}`: "
                   + "; ".join(cells) + f". Regimes: {regimes}. Steps from the pour to rest: {runs[0]['steps']:,} "
                   f"against {ref[0]['steps']:,}.")
    return out


def lines(runs_by_family):
    """Markdown lines: per pair and common gate position, the differences of the observables
    with their combined standard errors, and the regimes."""
    out = []
    for family, reference, what in PAIRS:
        runs, ref = runs_by_family.get(family, []), runs_by_family.get(reference, [])
        for gate in sorted({r["L0"] for r in runs}):
            at = [r for r in runs if r["L0"] == gate]
            ref_at = [r for r in ref if r["L0"] == gate]
            if len(at) < 2 or len(ref_at) < 2:
                continue
            cells = []
            for name in observables(at[0]):
                d = difference(at, ref_at, name)
                if d:
                    z = abs(d[0]) / d[1] if d[1] > 0 else float("inf")
                    cells.append(f"{name} {d[0]:+.3g} ± {d[1]:.2g} ({z:.1f} combined standard errors)")
            regimes = lambda rs: ", ".join(sorted(r.get("regime", "") for r in rs))
            out.append(f"- {what}, L0 = {gate:g} m, `{family}` ({len(at)} runs) minus `{reference}` "
                       f"({len(ref_at)} runs): " + "; ".join(cells) + f". Regimes: {regimes(at)} against "
                       f"{regimes(ref_at)}.")
    out += single_column_lines(runs_by_family)
    if out:
        out = ["", "**Approximations against every contact computed.** Each approximation's dam breaks minus the "
               "same columns' with every contact computed (mean ± combined standard error):", ""] + out + [""]
    return out
