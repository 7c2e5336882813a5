"""talus.Simulation: a scenario loaded and stepped from Python, with its particles as NumPy
arrays. The engine does the work (scenario/stepped_run.h); this layer adds the callbacks and
hands the analyses to a Snapshot of the present state."""
import math
import os
import warnings

import numpy as np

from . import _talus
from .overrides import assignments

_NO_LIMIT = 2**64 - 1  # steps: as many as the time limit needs


def load(path, overrides=None, *, restart=None, threads=None):
    """The scenario file at `path`, as `talus run PATH` would start it.

    overrides: {"contact.friction": 0.3, ...} or ["contact.friction=0.3", ...], as --set.
    restart: a checkpoint file to go on from, as `talus run --restart`.
    threads: OpenMP threads of this process (default: all cores).
    Raises talus.ScenarioError (a ValueError) with the engine's FILE:LINE: KEY: message lines.
    """
    restart = None if restart is None else os.fspath(restart)
    return Simulation(_talus.SteppedRun.load(os.fspath(path), assignments(overrides), restart, threads))


def resume(checkpoint, *, threads=None):
    """The run a checkpoint file holds, with the scenario stored in it, as `talus resume`."""
    return Simulation(_talus.SteppedRun.resume(os.fspath(checkpoint), threads))


def _count(value, name):
    if value != int(value) or value < 0:
        raise ValueError(f"{name} must be a whole number >= 0, got {value!r}")
    return int(value)


class Simulation:
    """A loaded scenario. Its particle arrays (positions, ...) are read-only views of the
    engine's memory, in the engine's order, which changes as it runs: match particles across
    steps by `ids`. A view keeps showing the state it was taken in."""

    def __init__(self, run):
        self._run = run
        if run.observers:
            warnings.warn(
                f"{', '.join(run.observers)}: the study's own phases and measurements run only under "
                "`talus run`; this Simulation steps the particles, walls and pours",
                stacklevel=3,
            )

    def __repr__(self):
        return f"<talus.Simulation: {self.particle_count} particles, t = {self.time:g} s, {self.steps} steps>"

    # Stepping.
    def run(self, steps, callback=None, every=1):
        """Runs `steps` time steps. With a callback, calls callback(self) after every `every`-th
        step of this call (steps // every times)."""
        self._advance(_count(steps, "steps"), math.inf, callback, every)

    def run_until(self, time, callback=None, every=1):
        """Runs until the time is within half a step of `time` (s); callbacks as in run()."""
        self._advance(_NO_LIMIT, float(time), callback, every)

    def _advance(self, steps, until, callback, every):
        if callback is None:
            self._run.run(steps, until)
            return
        every = _count(every, "every")
        if every == 0:
            raise ValueError("every must be at least 1")
        while steps > 0:
            chunk = min(every, steps)
            done = self._run.run(chunk, until)
            steps -= done
            if done == every:
                callback(self)
            if done < chunk:  # reached `until`
                return

    # The state now.
    time = property(lambda self: self._run.time, doc="s, simulated time")
    steps = property(lambda self: self._run.steps, doc="time steps run since the start")
    dt = property(lambda self: self._run.dt, doc="s, the time step")
    end_time = property(lambda self: self._run.end_time, doc="s, the scenario's run.end_time")
    gravity = property(lambda self: np.array(self._run.gravity), doc="m/s^2")
    particle_count = property(lambda self: self._run.particle_count, doc="particles of the world")
    species_names = property(lambda self: self._run.species_names, doc="species names, by index")
    wall_names = property(lambda self: self._run.wall_names, doc="wall names, by index")
    scenario_toml = property(lambda self: self._run.scenario_toml, doc="the scenario as loaded, overrides applied")

    positions = property(lambda self: self._run.positions, doc="(n, 3) m, centres of mass")
    velocities = property(lambda self: self._run.velocities, doc="(n, 3) m/s")
    angular_velocities = property(lambda self: self._run.angular_velocities, doc="(n, 3) rad/s, world frame")
    orientations = property(lambda self: self._run.orientations, doc="(n, 4) w, x, y, z: body to world")
    radii = property(lambda self: self._run.radii, doc="(n,) m, bounding radii")
    masses = property(lambda self: self._run.masses, doc="(n,) kg")
    ids = property(lambda self: self._run.ids, doc="(n,) global ids, stable for the whole run")
    species = property(lambda self: self._run.species, doc="(n,) species indices into species_names")

    def snapshot(self):
        """A talus.Snapshot of the particles and contacts now (copies, in id order)."""
        return self._run.snapshot()

    def contacts(self):
        """Every contact point now, as a dict of arrays (see Snapshot.contacts): i, j are global
        ids (j = -1 for a wall contact, `wall` its index into wall_names)."""
        return self.snapshot().contacts()

    def summary(self):
        """What summary.json would say of the run now (less the run loop's own records)."""
        return self._run.summary()

    def checkpoint(self, path):
        """Writes a checkpoint file that talus.resume() and `talus run --restart` go on from."""
        self._run.checkpoint(os.fspath(path))

    # The analyses, on the state now.
    def coarse_grain(self, grid, width, function="gaussian", cutoff=None):
        """Coarse-grained fields (Snapshot.coarse_grain)."""
        return self.snapshot().coarse_grain(grid, width, function, cutoff)

    def force_pdf(self, bins=50, scale="linear", min_ratio=0.0, max_ratio=0.0, merge_pairs=False,
                  include_walls=False):
        """PDF of the contact forces F / <F> (Snapshot.force_pdf)."""
        return self.snapshot().force_pdf(bins, scale, min_ratio, max_ratio, merge_pairs, include_walls)

    def fabric_tensor(self, merge_pairs=False):
        """<n n> of the unit branch vectors, 3 x 3 (Snapshot.fabric_tensor)."""
        return self.snapshot().fabric_tensor(merge_pairs)

    def fabric_xz(self, merge_pairs=False):
        """The fabric in the xz plane (Snapshot.fabric_xz)."""
        return self.snapshot().fabric_xz(merge_pairs)

    def fabric_histogram(self, bins=36, merge_pairs=False):
        """Branch-vector angles in the xz plane (Snapshot.fabric_histogram)."""
        return self.snapshot().fabric_histogram(bins, merge_pairs)
