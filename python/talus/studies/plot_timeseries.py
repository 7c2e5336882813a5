"""Plots a run's energies and contact count against time: DIR/timeseries.csv -> DIR/energies.png."""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(folder: Path) -> None:
    data = np.genfromtxt(folder / "timeseries.csv", delimiter=",", names=True)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for name, label in [("kinetic_translational", "kinetic (translation)"),
                        ("kinetic_rotational", "kinetic (rotation)"),
                        ("elastic_normal", "elastic (normal)"),
                        ("elastic_tangential", "elastic (tangential)")]:
        values = np.abs(data[name])
        if np.any(values > 0):
            top.semilogy(data["time"], np.where(values > 0, values, np.nan), label=label)
    top.set_ylabel("energy (J)")
    top.legend(fontsize=8)
    bottom.semilogy(data["time"], np.where(data["max_speed"] > 0, data["max_speed"], np.nan), label="largest speed")
    bottom.semilogy(data["time"], np.where(data["mean_speed"] > 0, data["mean_speed"], np.nan), label="mean speed")
    bottom.set_ylabel("speed (m/s)")
    bottom.set_xlabel("time (s)")
    bottom.legend(fontsize=8)
    fig.suptitle(folder.name)
    fig.tight_layout()
    fig.savefig(folder / "energies.png", dpi=120)

