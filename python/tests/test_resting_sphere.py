"""A sphere at rest on a floor: the contact force the floor exerts is its weight, the friction
force is zero, and the wall force the summary reports is the same force, reversed."""
import math

import numpy as np
import pytest

import talus
from conftest import SCENARIOS

MASS = 2500 * 4 / 3 * math.pi * 0.01**3  # kg, scenarios/resting_sphere.toml
G = 9.81


def test_the_floor_carries_the_weight():
    sim = talus.load(SCENARIOS / "resting_sphere.toml")
    sim.run_until(0.2)  # some 70 decay times of the dashpot
    c = sim.contacts()
    assert list(c["i"]) == [0] and list(c["j"]) == [-1] and sim.wall_names[c["wall"][0]] == "floor"
    np.testing.assert_allclose(c["normal"][0], [0, 0, 1], atol=1e-15)
    assert c["normal_force"][0, 2] == pytest.approx(MASS * G, rel=1e-6)
    assert np.abs(c["normal_force"][0, :2]).max() < 1e-12
    assert np.abs(c["tangential_force"][0]).max() < 1e-9 * MASS * G
    # The overlap of a linear spring: m g / k_n.
    assert c["overlap"][0] == pytest.approx(MASS * G / 1e4, rel=1e-6)
    assert c["point"][0] == pytest.approx([0, 0, -0.5 * c["overlap"][0]], abs=1e-12)
    floor = sim.summary()["wall_forces"]["floor"]
    assert floor == pytest.approx([0, 0, -MASS * G], rel=1e-6, abs=1e-12)
    assert sim.summary()["wall_contacts"] == 1
