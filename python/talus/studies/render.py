"""Draws a run's configuration at a chosen time as a PNG, seen from the side (x-z) or from the
top (x-y): true particle surfaces (shapes.vtu) or discs (spheres), coloured by speed.

Usage: python3 -m talus render RESULTS_DIR [--time T] [--view side|top] [--out FILE.png]
Reads RESULTS_DIR/vtk/*.pvd (written when the scenario sets run.vtk_interval)."""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PatchCollection, PolyCollection
from matplotlib.patches import Circle
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader


def frame(pvd: Path, time: float):
    """The series file closest to `time` and its time."""
    entries = [(float(d.get("timestep")), pvd.parent / d.get("file")) for d in ET.parse(pvd).getroot().iter("DataSet")]
    if not entries:
        sys.exit(f"render: {pvd} has no frames")
    if time == float("inf"):
        return entries[-1]
    return min(entries, key=lambda e: abs(e[0] - time))


def read(path: Path):
    # A frame of a run spread over ranks is a .pvtu joining one piece per rank.
    reader = vtkXMLPUnstructuredGridReader() if path.suffix == ".pvtu" else vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def frame_times(results) -> list:
    """Times of a run's VTK frames, in order."""
    pvd = Path(results) / "vtk" / "particles.pvd"
    return sorted(float(d.get("timestep")) for d in ET.parse(pvd).getroot().iter("DataSet"))


def pile_window(results, times, view: str = "side"):
    """The smallest window that holds the particles of every frame nearest to `times`, from the
    box's near wall on: panels of one figure share it, sized to the pile rather than the box."""
    vtk_dir = Path(results) / "vtk"
    axes = (0, 2) if view == "side" else (0, 1)
    lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
    for time in times:
        grid = read(frame(vtk_dir / "particles.pvd", time)[1])
        if not grid.GetNumberOfPoints():
            continue
        centres = vtk_to_numpy(grid.GetPoints().GetData())[:, axes]
        radius = vtk_to_numpy(grid.GetPointData().GetArray("radius"))[:, None]
        lo, hi = np.minimum(lo, (centres - radius).min(axis=0)), np.maximum(hi, (centres + radius).max(axis=0))
    walls = vtk_dir / "walls.pvd"
    if walls.exists():
        wall_points = read(frame(walls, times[0])[1]).GetPoints()
        if wall_points is not None and wall_points.GetNumberOfPoints():
            lo = np.minimum(lo, vtk_to_numpy(wall_points.GetData())[:, axes].min(axis=0))
    if not np.all(np.isfinite(lo + hi)):
        return None
    span = hi - lo
    return (lo[0], hi[0] + 0.05 * span[0]), (lo[1], hi[1] + 0.1 * span[1])


def box_window(vtk_dir: Path, time: float, axes):
    walls = vtk_dir / "walls.pvd"
    if not walls.exists():
        return None
    points = read(frame(walls, time)[1]).GetPoints()
    if points is None or not points.GetNumberOfPoints():
        return None
    xyz = vtk_to_numpy(points.GetData())
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)
    return (lo[axes[0]], hi[axes[0]]), (lo[axes[1]], hi[axes[1]])


def draw_on(ax, results, time: float = float("inf"), view: str = "side", window=None):
    """Draws the frame nearest to `time` on `ax`, within `window` ((x0, x1), (y0, y1); default: the
    frame's pile); returns the frame's time and its largest speed."""
    vtk_dir = Path(results) / "vtk"
    if not (vtk_dir / "particles.pvd").exists():
        sys.exit(f"render: no {vtk_dir}/particles.pvd (set run.vtk_interval in the scenario)")
    t, particles_file = frame(vtk_dir / "particles.pvd", time)
    axes = (0, 2) if view == "side" else (0, 1)
    depth = 1 if view == "side" else 2  # far particles are drawn first
    grid = read(particles_file)
    centres = vtk_to_numpy(grid.GetPoints().GetData()) if grid.GetNumberOfPoints() else np.zeros((0, 3))
    speed = np.linalg.norm(vtk_to_numpy(grid.GetPointData().GetArray("velocity")), axis=1) if len(centres) else np.zeros(0)
    vmax = max(float(speed.max()) if len(speed) else 0.0, 1e-12)
    cmap = plt.get_cmap("viridis")
    shapes_pvd = vtk_dir / "shapes.pvd"
    shape_index = vtk_to_numpy(grid.GetPointData().GetArray("shape")) if len(centres) else np.zeros(0)
    if shapes_pvd.exists():
        mesh = read(frame(shapes_pvd, t)[1])
        points = vtk_to_numpy(mesh.GetPoints().GetData())
        cell_speed = np.linalg.norm(vtk_to_numpy(mesh.GetCellData().GetArray("velocity")), axis=1)
        polygons, colours, order = [], [], []
        for c in range(mesh.GetNumberOfCells()):
            ids = [mesh.GetCell(c).GetPointId(k) for k in range(mesh.GetCell(c).GetNumberOfPoints())]
            polygons.append(points[ids][:, axes])
            colours.append(cmap(cell_speed[c] / vmax))
            order.append(points[ids][:, depth].mean() * (-1 if view == "side" else 1))
        sequence = np.argsort(order)[::-1] if view == "side" else np.argsort(order)
        ax.add_collection(PolyCollection([polygons[k] for k in sequence], facecolors=[colours[k] for k in sequence],
                                         edgecolors="k", linewidths=0.1))
    spheres = [k for k in range(len(centres)) if shape_index[k] == 0]
    radius = vtk_to_numpy(grid.GetPointData().GetArray("radius")) if len(centres) else np.zeros(0)
    discs = [Circle((centres[k, axes[0]], centres[k, axes[1]]), radius[k]) for k in spheres]
    ax.add_collection(PatchCollection(discs, facecolors=[cmap(speed[k] / vmax) for k in spheres], edgecolors="k", linewidths=0.2))
    # From the side, the frame is the pile's; from the top, the box's floor (its walls' extent).
    window = window or (pile_window(results, [t], view) if view == "side" else box_window(vtk_dir, t, axes))
    if window is not None:
        ax.set_xlim(*window[0])
        ax.set_ylim(*window[1])
    else:
        ax.autoscale_view()
    ax.set_aspect("equal")
    return t, vmax


def draw(results, time: float = float("inf"), view: str = "side", out=None) -> Path:
    """One frame as a PNG, framed on the pile, the picture as wide as the frame is."""
    fig, ax = plt.subplots(figsize=(8, 5))
    t, vmax = draw_on(ax, results, time, view)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    fig.set_size_inches(8, min(max(8 * (y1 - y0) / (x1 - x0) + 1.2, 2.6), 8))
    ax.set_xlabel("x (m)")
    ax.set_ylabel("z (m)" if view == "side" else "y (m)")
    ax.set_title(f"t = {t:.4g} s, coloured by speed (max {vmax:.3g} m/s)")
    out = Path(out) if out else Path(results) / f"render_{view}_{t:.4g}.png"
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return out

