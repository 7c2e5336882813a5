"""A sphere in free fall follows the exact parabola: stepping from Python is the engine's own
integration, with the time and step count kept as the engine keeps them."""
import numpy as np
import pytest

import talus
from conftest import SCENARIOS

G = 9.81
Z0, U0 = 0.9, 0.1  # m and m/s, scenarios/free_fall.toml


def test_follows_the_parabola_step_by_step():
    sim = talus.load(SCENARIOS / "free_fall.toml")
    assert sim.particle_count == 1 and sim.dt == 1e-4
    for _ in range(10):
        sim.run(steps=100)
        t = sim.steps * sim.dt
        assert sim.time == pytest.approx(t, abs=1e-12)
        x, y, z = sim.positions[0]
        assert z == pytest.approx(Z0 - 0.5 * G * t**2, abs=1e-9)
        assert x == pytest.approx(U0 * t, abs=1e-9)
        assert y == 0
        assert sim.velocities[0] == pytest.approx([U0, 0, -G * t], abs=1e-9)
        assert not sim.angular_velocities.any()


def test_run_until_stops_within_half_a_step():
    sim = talus.load(SCENARIOS / "free_fall.toml")
    sim.run_until(0.05)
    assert sim.steps == 500
    sim.run_until(0.05)  # there already: no step
    assert sim.steps == 500
    sim.run_until(0.05004)  # less than half a step on: none either
    assert sim.steps == 500
    sim.run_until(sim.end_time)
    assert sim.steps == 1000
    assert sim.positions[0, 2] == pytest.approx(Z0 - 0.5 * G * 0.1**2, abs=1e-9)


def test_callback_every_k_steps_sees_the_state_after_those_steps():
    sim = talus.load(SCENARIOS / "free_fall.toml")
    seen = []
    sim.run(steps=250, callback=lambda s: seen.append((s.steps, s.positions[0, 2])), every=30)
    assert [steps for steps, _ in seen] == [30 * k for k in range(1, 9)]  # 250 // 30 calls
    for steps, z in seen:
        assert z == pytest.approx(Z0 - 0.5 * G * (steps * 1e-4) ** 2, abs=1e-9)
    calls = []
    sim.run_until(0.035, callback=lambda s: calls.append(s.steps), every=40)  # 100 steps on from 250
    assert calls == [290, 330] and sim.steps == 350


def test_bad_step_counts_are_refused():
    sim = talus.load(SCENARIOS / "free_fall.toml")
    with pytest.raises(ValueError):
        sim.run(steps=-1)
    with pytest.raises(ValueError):
        sim.run(steps=2.5)
    with pytest.raises(ValueError):
        sim.run(steps=10, callback=print, every=0)
    assert sim.steps == 0


def test_the_gravity_and_the_summary_are_the_engines():
    sim = talus.load(SCENARIOS / "free_fall.toml")
    sim.run(steps=200)
    np.testing.assert_array_equal(sim.gravity, [0, 0, -G])
    s = sim.summary()
    assert s["steps"] == 200 and s["particles"] == 1 and s["contacts"] == 0
    assert s["final_time"] == sim.time and s["time_step"] == sim.dt
    m = sim.masses[0]
    v = -G * sim.time
    assert s["energies"]["kinetic_translational"] == pytest.approx(0.5 * m * (U0**2 + v**2), rel=1e-12)
    assert s["talus_version"] == talus.__version__
