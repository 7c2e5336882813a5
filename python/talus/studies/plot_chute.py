"""Figures of the chute study of Weinhart et al. 2012 from a results folder:
  a run with depth profiles (chute_profile*.csv): profiles.png with the volume fraction for
  every coarse-graining width (Fig. 6), the stresses with the lithostatic weight (Fig. 7) and the
  velocity with a Bagnold profile (Fig. 8), and energy_ratio.png, E_kin/<E_ela> against time (Fig. 3);
  a sweep or h_stop search (sweep_runs.csv, hstop_runs.csv): flow_map.png, flow states in the
  (theta, h) plane with the h_stop fits of fits.json (Figs. 4, 9, 10), and froude.png, F against
  h / h_stop (Fig. 11).
Usage: python3 -m talus plot DIR"""
import csv
import glob
import json
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import chute_fits, plot_timeseries  # noqa: E402

MARKERS = {"arrested": ("o", "k"), "steady": ("o", "none"), "accelerating": ("*", "C3"), "layered": ("x", "C0"),
           "oscillating": ("D", "none"), "decelerating": ("v", "C1"), "undetermined": ("?", "C7")}


def read_csv(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def profiles(folder: Path):
    summary = json.loads((folder / "summary.json").read_text())
    base, h = summary.get("base", 0.0), summary.get("h", None)
    fig, (ax_rho, ax_s, ax_u) = plt.subplots(1, 3, figsize=(13, 5), sharey=True)
    files = sorted(glob.glob(str(folder / "chute_profile*.csv")))
    w0 = summary.get("chute", {}).get("width", None)
    for f in files:
        m = re.search(r"_w([0-9.eE+-]+)\.csv$", f)
        w = float(m.group(1)) if m else w0
        d = read_csv(f)
        ax_rho.plot(d["volume_fraction"], d["z"] - base, label="w = %g" % w if w else "")
    ax_rho.set_xlabel(r"$\rho/\rho_p$")
    ax_rho.set_ylabel("z - b")
    ax_rho.legend(fontsize=8)
    d = read_csv(folder / "chute_profile.csv")
    z = d["z"] - base
    for name, label in [("stress_zz_planes", r"$\sigma_{zz}$"), ("stress_xx", r"$\sigma_{xx}$"),
                        ("stress_yy", r"$\sigma_{yy}$")]:
        ax_s.plot(d[name], z, label=label)
    ax_s.plot(-d["stress_xz_planes"], z, label=r"$-\sigma_{xz}$")
    ax_s.plot(d["lithostatic_zz"], z, "k:", label=r"$\int_z \rho g\cos\theta$ (Eq. 41)")
    ax_s.set_xlabel("stress")
    ax_s.legend(fontsize=8)
    dense = d["volume_fraction"] > 0.01  # the velocity of a few saltating grains means little
    ax_u.plot(np.where(dense, d["velocity_x"], np.nan), z, label="u")
    if h and summary.get("mean_velocity"):
        zz = np.linspace(0, h, 100)
        ax_u.plot(5 / 3 * summary["mean_velocity"] * (1 - ((h - zz) / h) ** 1.5), zz, "k--", label="Bagnold (Eq. 54a)")
    ax_u.set_xlabel("u")
    ax_u.legend(fontsize=8)
    if h:
        for ax in (ax_rho, ax_s, ax_u):
            ax.set_ylim(-2, h + 3)
    fig.suptitle("%s: %s, h = %.3g, F = %.3g" % (folder.name, summary.get("flow_state"), h or 0, summary.get("froude") or 0))
    fig.tight_layout()
    fig.savefig(folder / "profiles.png", dpi=120)
    plt.close(fig)
    if (folder / "timeseries.csv").exists():
        t = read_csv(folder / "timeseries.csv")
        fig, ax = plt.subplots(figsize=(7, 4))
        kin = t["kinetic_translational"] + t["kinetic_rotational"]
        ela = t["elastic_normal"] + t["elastic_tangential"]
        late = t["time"] >= 0.5 * t["time"][-1]
        ratio = kin / max(np.mean(ela[late]), 1e-300)
        ax.semilogy(t["time"], np.where(ratio > 0, ratio, np.nan))
        ax.axhline(1e-5, color="k", ls=":", lw=0.8)
        ax.set_xlabel("t")
        ax.set_ylabel(r"$E_{kin}/\langle E_{ela}\rangle$")
        fig.tight_layout()
        fig.savefig(folder / "energy_ratio.png", dpi=120)
        plt.close(fig)


def read_runs(folder: Path):
    rows = []
    for name in ("sweep_runs.csv", "hstop_runs.csv"):
        if (folder / name).exists():
            with open(folder / name) as f:
                rows += list(csv.DictReader(f))
    for r in rows:
        for k in ("lambda", "H", "angle", "h", "froude"):
            r[k] = float(r[k]) if r.get(k) not in (None, "") else np.nan
    return rows


def flow_map(folder: Path):
    rows = read_runs(folder)
    fits = json.loads((folder / "fits.json").read_text()) if (folder / "fits.json").exists() else []
    lams = sorted({r["lambda"] for r in rows})
    fig, ax = plt.subplots(figsize=(7, 5))
    seen = set()
    for r in rows:
        mk, fc = MARKERS.get(r["flow_state"], ("?", "C7"))
        y = r["h"] if np.isfinite(r["h"]) else r["H"]
        color = "C%d" % lams.index(r["lambda"])
        ax.scatter(r["angle"], y, marker=mk, facecolors=fc if fc != "none" else "none", edgecolors=color,
                   label=r["flow_state"] if r["flow_state"] not in seen else None)
        seen.add(r["flow_state"])
    for f in fits:
        color = "C%d" % lams.index(f["lambda"]) if f["lambda"] in lams else "k"
        if "hstop35" in f:
            p = f["hstop35"]["params"]
            th = np.linspace(p["delta1"] + 0.05, min(p["delta2"], 40), 200)
            ax.plot(th, chute_fits.hstop35(th, **p), "-", color=color, label="Eq. 35, lambda = %g" % f["lambda"])
        if "hstop38" in f:
            p = f["hstop38"]["params"]
            th = np.linspace(p["delta1"] + 0.05, p["delta2"], 200)
            ax.plot(th, chute_fits.hstop38(th, **p), ":", color=color, label="Eq. 38, lambda = %g" % f["lambda"])
    ax.set_ylim(0, max([r["H"] for r in rows] + [10]) * 1.2)
    ax.set_xlabel(r"$\theta$ (deg)")
    ax.set_ylabel("h")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(folder / "flow_map.png", dpi=120)
    plt.close(fig)
    hs1 = next((f["hstop35"]["params"] for f in fits if f["lambda"] == 1 and "hstop35" in f), None)
    if hs1:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for lam in lams:
            sel = [r for r in rows if r["lambda"] == lam and r["flow_state"] in ("steady", "layered", "oscillating")]
            x = [r["h"] / chute_fits.hstop35(r["angle"], **hs1) for r in sel]
            ax.scatter(x, [r["froude"] for r in sel], color="C%d" % lams.index(lam), label="lambda = %g" % lam, s=12)
            fit = next((f for f in fits if f["lambda"] == lam and "flow_rule" in f), None)
            if fit and x:
                xx = np.linspace(0, max(x) * 1.05, 50)
                ax.plot(xx, fit["flow_rule"]["params"]["beta"] * xx - fit["flow_rule"]["params"]["gamma"], color="C%d" % lams.index(lam))
        ax.set_xlabel(r"$h / h_{stop}(\theta; 1)$")
        ax.set_ylabel("F")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(folder / "froude.png", dpi=120)
        plt.close(fig)


def main(folder: Path):
    if (folder / "chute_profile.csv").exists():
        profiles(folder)
    if (folder / "sweep_runs.csv").exists() or (folder / "hstop_runs.csv").exists():
        flow_map(folder)
    if (folder / "timeseries.csv").exists():
        plot_timeseries.main(folder)

