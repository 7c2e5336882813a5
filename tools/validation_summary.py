"""The report's first section: each headline number of the two papers beside Talus', whether it
meets the bar, and what has not run yet. Built from the same tables as the sections below it
(table1.json's record and the runout cases), so it cannot drift from them."""
import math

import validation_closures

# The estimates of Table 1's h_stop curve, in the order the report gives them: name suffix in
# table1.json, and the column heading.
HSTOP_ESTIMATES = [("_mle", "every case (max. likelihood, 68 %)"), ("", "interval midpoints (Eq. 35)"),
                   ("_with_paper_A", "interval midpoints, A held at Table 1's")]
# ... and of the flow rule: through which h_stop curve it was fitted.
FLOW_RULE_ESTIMATES = [("_with_paper_hstop", "Table 1's h_stop"), ("_mle", "the max.-likelihood h_stop"),
                       ("", "the interval fit's h_stop")]
FLOW_MAP_CASES = 16  # H = 10, 20, 30, 40 by theta = 22, 24, 26, 28 degrees
REALISATIONS = 3     # per aspect ratio (the small-system plan)
PAPER_FAMILIES = ("spheres", "crosses")
CLOSURES = {"bulk_volume_fraction": ("Eq. 52, bulk volume fraction", ("c0", "c1", "c2")),
            "K": ("Eq. 53, K = sigma_xx / sigma_zz", ("d0", "d1")),
            "alpha": ("Eq. 54, shape factor alpha", ("d_lambda",))}  # the paper's own contact models; the rest are Talus' variants


def within(value, paper, bar):
    """Whether `value` meets the bar about `paper`: ("deg", d) absolute, ("relative", r) of paper."""
    if bar is None or value is None:
        return None
    kind, size = bar
    return abs(value - paper) <= (size if kind == "deg" else size * abs(paper))


def bar_text(bar):
    if bar is None:
        return "no bar"
    kind, size = bar
    return f"{size:g}°" if kind == "deg" else f"{100 * size:g} %"


def estimate_text(table, name, suffix, paper, bar):
    if name == "A" and suffix == "_with_paper_A":
        return "(held)"
    v = table.get(name + suffix)
    if v is None:
        return "-"
    lo, hi = table.get(name + suffix + "_lo"), table.get(name + suffix + "_hi")
    spread = f" ({lo:.4g} to {hi:.4g})" if lo is not None and hi is not None else ""
    err = table.get(name + suffix + "_err")
    if not spread and err is not None:
        spread = f" ± {err:.2g}"
    verdict = within(v, paper, bar)
    mark = "" if verdict is None else (", meets the bar" if verdict else ", misses the bar")
    return f"{v:.4g}{spread}{mark}"


def closure_lines(closures):
    """Table 2's closures (Weinhart et al. 2012, Eqs. 52-54): each constant of Talus' fit beside the
    paper's, and the rms deviation of Talus' flows from the paper's closure beside the paper's own."""
    out = []
    for key, (label, names) in CLOSURES.items():
        b = closures.get(key)
        if not b:
            continue
        consts = []
        for n in names:
            if "params" not in b:
                break
            v, e, paper = float(b["params"][n]), float(b["se"][n]), validation_closures.PAPER[n]
            consts.append(f"{n} = {v:.4g} ± {e:.2g} (paper {paper:g}, {abs(v - paper) / e:.1f} standard errors)")
        out.append(f"| {label} | {'; '.join(consts) or 'too few angles'} | {b['paper_err']:.3f} | "
                   f"{validation_closures.PAPER_ERR[key]:.3f} |")
    if not out:
        return []
    return ["| Table 2 closure | Talus' fit | err(Talus - paper's closure) | paper's own err |", "|---|---|---|---|"] + out + [""]


def weinhart_lines(table, paper_values, bars, glance):
    out = ["**Weinhart et al. 2012, Table 1 (lambda = 1).** The bar: 0.5° on the angles, 10 % on A and beta.", "",
           "| quantity | Table 1 | bar | " + " | ".join(f"h_stop from {label}" for _, label in HSTOP_ESTIMATES) + " |",
           "|---|---|---|" + "---|" * len(HSTOP_ESTIMATES)]
    for name in ("delta1", "delta2", "A"):
        cells = [estimate_text(table, name, suffix, paper_values[name], bars[name]) for suffix, _ in HSTOP_ESTIMATES]
        out.append(f"| {name} | {paper_values[name]:g} | {bar_text(bars[name])} | " + " | ".join(cells) + " |")
    out += ["", "| quantity | Table 1 | bar | " + " | ".join(f"flow rule through {label}" for _, label in
                                                        FLOW_RULE_ESTIMATES) + " |",
            "|---|---|---|" + "---|" * len(FLOW_RULE_ESTIMATES)]
    for name in ("beta", "gamma"):
        cells = [estimate_text(table, name, suffix, paper_values[name], bars[name]) for suffix, _ in FLOW_RULE_ESTIMATES]
        out.append(f"| {name} | {paper_values[name]:g} | {bar_text(bars[name])} | " + " | ".join(cells) + " |")
    staircase = ("complete" if table.get("staircase_complete") else
                 f"not complete (it has climbed to H = {table.get('staircase_max_H', 0):g} of 40)")
    resolution = glance.get("resolution", "")
    out += [""] + closure_lines(glance.get("closures", {}))
    out += [(resolution + " " if resolution else "") +
            f"The h_stop staircase is {staircase}; the flow map has {table.get('flow_map_cases', 0)} of its "
            f"{FLOW_MAP_CASES} cases. The sections below say where the estimates disagree and what was tested.", ""]
    return out


def huet_lines(cases, fits, moving_fits, channel_fits, memory=None):
    out = ["**Huet et al. 2021, small systems.**", ""]
    spheres = sorted((c for c in cases if c["family"] == "spheres"), key=lambda c: c["aspect_ratio"])
    between = 0
    for c in spheres:
        held = [v for v in (f.runout_ratio(c["aspect_ratio"]) for f in channel_fits) if v is not None]
        between += len(held) > 1 and min(held) <= c["runout_ratio"] <= max(held)
    if spheres:
        out.append(f"- Spheres: {between} of {len(spheres)} aspect ratios ({spheres[0]['aspect_ratio']:.2g} to "
                   f"{spheres[-1]['aspect_ratio']:.2g}) have their runout between the two channel experiments' fits.")
    for fam in ("crosses", "crosses_manifold"):
        if fam not in fits:
            continue
        K, n, K_err, n_err = fits[fam]
        off = abs(n - 1) / n_err if n_err > 0 else math.inf
        text = (f"- {fam}: runout exponent n = {n:.3g} ± {n_err:.2g} over every aspect ratio, {off:.1f} standard errors "
                f"from the paper's n of about 1 ({'consistent' if off < 2 else 'not consistent'})")
        if fam in moving_fits:
            (_, n, _, n_err), left, _ = moving_fits[fam]
            off = abs(n - 1) / n_err if n_err > 0 else math.inf
            text += (f"; without a = {', '.join(f'{a:.2g}' for a in left)}, where a realisation stood, n = {n:.3g} ± "
                     f"{n_err:.2g} ({'consistent' if off < 2 else 'not consistent'})")
        out.append(text + ".")
    if memory:
        out.append(memory)
    thin = [c for c in cases if c["family"] in PAPER_FAMILIES and c["runs"] < REALISATIONS]
    if thin:
        out.append("- Fewer than " + f"{REALISATIONS} realisations so far: " +
                   ", ".join(f"{c['family']} at L0 = {c['L0']:.3g} m ({c['runs']})" for c in thin) + ".")
    return out + [""]


def lines(table, paper_values, bars, glance, cases, fits, moving_fits, channel_fits, memory=None):
    """`glance`: {"resolution": what one staircase resolves of Table 1's curve, in a sentence;
    "closures": validation_closures.closures of the steady flows}, either may be missing; `memory`:
    the line of validation_memory.glance, or None."""
    out = ["## At a glance", ""]
    if table:
        out += weinhart_lines(table, paper_values, bars, glance)
    if cases:
        out += huet_lines(cases, fits, moving_fits, channel_fits, memory)
    return out
