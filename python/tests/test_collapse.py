"""The dam break's measurements from Python, on a small collapse of beads that a removed gate
releases (scenarios/sphere_collapse.toml)."""
import numpy as np
import pytest

import talus
from conftest import SCENARIOS

L0, LENGTH, WIDTH = 0.02, 0.12, 0.024  # m


@pytest.fixture(scope="module")
def collapse():
    sim = talus.load(SCENARIOS / "sphere_collapse.toml")
    sim.run_until(0.29)  # settled behind the gate, which goes at 0.3 s
    initial = sim.snapshot()
    sim.run_until(0.9)   # at rest again
    return sim, initial, sim.snapshot()


def test_the_column_collapses_as_channel_experiments_do(collapse):
    """Channel experiments: (L_inf - L0) / L0 = 1.2 a (Lube et al. 2005, a < 1.8) to 1.8 a
    (Lajeunesse et al. 2005, a < 3). Beads with rolling resistance and these soft, damped
    contacts run out 1.5 a; the test allows 0.8 a to 2 a."""
    sim, initial, final = collapse
    assert initial.mean_speeds()["translational"] < 1e-3 and final.mean_speeds()["translational"] < 1e-6
    m = talus.measure_collapse(initial, final, initial_length=L0, box_length=LENGTH, width=WIDTH, shapes_of=sim)
    a = m["aspect_ratio"]
    assert a == pytest.approx(m["H0"] / L0, rel=1e-12) and 1.5 < a < 2.5
    assert m["runout_ratio"] == pytest.approx((m["runout"] - L0) / L0, rel=1e-12)
    assert m["runout_low"] <= m["runout"] <= m["runout_high"] and not m["runout_reached_box_end"]
    assert 0.8 * a < m["runout_ratio"] < 2.0 * a
    assert m["height_ratio"] == pytest.approx(m["H0"] / m["final_height"], rel=1e-12) and m["height_ratio"] > 1.2
    assert m["regime"] == "collapsed" and m["particle_size"] == 0.004
    # The centre of mass: the mass-weighted mean of the mobile particles, moved forward and down.
    com = (initial.masses[:, None] * initial.positions).sum(axis=0) / initial.masses.sum()
    np.testing.assert_allclose(m["com_initial"], com, rtol=1e-12)
    np.testing.assert_allclose(initial.centre_of_mass(), com, rtol=1e-12)
    assert m["com_displacement"][0] > 0.5 * L0 and m["com_displacement"][2] < 0
    assert m["com_ratio"] == pytest.approx(m["com_displacement"][0] / m["com_initial"][0], rel=1e-12)


def test_spheres_are_their_own_bounding_spheres(collapse):
    sim, initial, final = collapse
    args = dict(initial_length=L0, box_length=LENGTH, width=WIDTH)
    shaped = talus.measure_collapse(initial, final, shapes_of=sim, **args)
    plain = talus.measure_collapse(initial, final, **args)
    for key in ("H0", "final_height", "runout", "runout_low", "runout_high", "regime"):
        assert shaped[key] == plain[key], key
