"""The particle arrays are views of the engine's memory that keep showing the state they were
taken in: the engine moves on with a copy, and holding views does not change the run."""
import numpy as np

import talus
from conftest import SETTLING_BOX


def test_a_view_keeps_its_state_across_steps():
    sim = talus.load(SETTLING_BOX)
    sim.run(steps=50)
    before, ids_before = sim.positions, sim.ids
    saved = before.copy()
    sim.run(steps=500)  # several list builds: the engine reorders and moves its arrays
    np.testing.assert_array_equal(before, saved)
    assert (sim.positions != before).any()
    np.testing.assert_array_equal(np.sort(ids_before), np.arange(750))


def test_views_taken_in_a_callback_make_a_trajectory():
    sim = talus.load(SETTLING_BOX)
    frames = []
    sim.run(steps=300, callback=lambda s: frames.append((s.ids, s.positions, s.snapshot())), every=100)
    assert len(frames) == 3
    for ids, positions, snap in frames:
        np.testing.assert_array_equal(positions[np.argsort(ids)], snap.positions)


def test_holding_views_does_not_change_the_run():
    plain, viewed = talus.load(SETTLING_BOX), talus.load(SETTLING_BOX)
    plain.run(steps=400)
    kept = []
    viewed.run(steps=400, callback=lambda s: kept.extend([s.positions, s.velocities, s.ids, s.orientations]), every=7)
    np.testing.assert_array_equal(plain.ids, viewed.ids)
    np.testing.assert_array_equal(plain.positions, viewed.positions)
    np.testing.assert_array_equal(plain.velocities, viewed.velocities)
    np.testing.assert_array_equal(plain.angular_velocities, viewed.angular_velocities)


def test_a_view_outlives_its_simulation():
    sim = talus.load(SETTLING_BOX)
    positions = sim.positions
    expected = positions.copy()
    del sim
    np.testing.assert_array_equal(positions, expected)
