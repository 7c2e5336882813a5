"""Talus from Python: load a scenario, step it, read its particles and contacts as NumPy
arrays, and run the engine's analyses on it or on saved snapshot files.

    import talus
    sim = talus.load("examples/settling_box.toml", overrides={"contact.friction": 0.3})
    sim.run(steps=100)
    print(sim.positions.shape, sim.summary()["energies"]["kinetic_translational"])

The reference is docs/guide/python.md.
"""
from ._talus import BlowUpError, ScenarioError, Snapshot, __version__, read_snapshot, snapshot_files
from .collapse import measure_collapse
from .simulation import Simulation, load, resume

__all__ = [
    "BlowUpError",
    "ScenarioError",
    "Simulation",
    "Snapshot",
    "load",
    "measure_collapse",
    "read_snapshot",
    "resume",
    "snapshot_files",
]
