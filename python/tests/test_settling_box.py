"""The settling box of examples/settling_box.toml from Python: its particle arrays, and the
analyses on a settled packing checked against what they must conserve."""
import math

import numpy as np
import pytest

import talus
from conftest import SETTLING_BOX

DENSITY, RADIUS = 2500.0, 0.001  # kg/m^3 and m, examples/settling_box.toml
BOX = (0.016, 0.016, 0.06)       # m


@pytest.fixture(scope="module")
def settled():
    """The box after 0.15 s, when the grains have landed (their contacts carry the weight)."""
    sim = talus.load(SETTLING_BOX)
    sim.run_until(0.15)
    return sim


def test_the_readme_example():
    sim = talus.load(str(SETTLING_BOX))
    sim.run(steps=100)
    assert sim.positions.shape == (750, 3)
    assert sim.steps == 100


def test_particle_arrays(settled):
    n = settled.particle_count
    assert n == 750
    assert settled.velocities.shape == settled.angular_velocities.shape == (n, 3)
    assert settled.orientations.shape == (n, 4)
    np.testing.assert_array_equal(np.sort(settled.ids), np.arange(n))
    assert settled.species_names == ["glass"] and not settled.species.any()
    np.testing.assert_array_equal(settled.radii, RADIUS)
    np.testing.assert_allclose(settled.masses, DENSITY * 4 / 3 * math.pi * RADIUS**3, rtol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(settled.orientations, axis=1), 1, rtol=1e-12)
    # Inside the box: no grain more than a tenth of a radius into a wall.
    assert (settled.positions > RADIUS * 0.9).all() and (settled.positions < np.array(BOX) - RADIUS * 0.9).all()
    assert settled.wall_names == ["x-", "x+", "y-", "y+", "floor", "top"]


def test_arrays_are_read_only(settled):
    for name in ("positions", "velocities", "angular_velocities", "orientations", "radii", "masses", "ids", "species"):
        array = getattr(settled, name)
        assert not array.flags.writeable, name
        with pytest.raises(ValueError):
            array[0] = 0


def test_snapshot_holds_the_same_particles_in_id_order(settled):
    snap = settled.snapshot()
    order = np.argsort(settled.ids)
    np.testing.assert_array_equal(snap.ids, np.arange(750))
    np.testing.assert_array_equal(snap.positions, settled.positions[order])
    np.testing.assert_array_equal(snap.velocities, settled.velocities[order])
    np.testing.assert_array_equal(snap.orientations, settled.orientations[order])
    assert snap.time == settled.time


def test_contact_forces_carry_the_weight(settled):
    """Once the grains have landed the walls carry their weight: the floor more than all of it,
    since the side walls' friction holds the packing down after its rebound; all walls together,
    the weight, to the 0.12 % that the packing still relaxes at 0.15 s."""
    c = settled.contacts()
    n = len(c["i"])
    assert n > 750
    for key in ("point", "normal", "force", "normal_force", "tangential_force"):
        assert c[key].shape == (n, 3), key
    np.testing.assert_allclose(c["normal_force"] + c["tangential_force"], c["force"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.einsum("ij,ij->i", c["tangential_force"], c["normal"]), 0, atol=1e-12)
    assert (np.einsum("ij,ij->i", c["normal_force"], c["normal"]) > 0).all()  # clamped: pushes only
    walls = c["j"] == -1
    assert (c["wall"][walls] >= 0).all() and (c["wall"][~walls] == -1).all()
    weight = settled.masses.sum() * 9.81
    assert c["force"][walls, 2].sum() == pytest.approx(weight, rel=2e-3)
    # The summary's wall forces are the forces of the particles on the walls: the same, reversed.
    wall_force = settled.summary()["wall_forces"]
    for w, name in enumerate(settled.wall_names):
        np.testing.assert_allclose(-c["force"][c["wall"] == w].sum(axis=0), wall_force[name], rtol=1e-9, atol=1e-12)


def test_coarse_grained_fields_conserve_mass_and_wall_forces(settled):
    """Lucy's kernel is normalised to 1 over its support (analysis/cg_function.h), so the depth
    profile of the density, integrated over z and multiplied by the box's cross-section (the
    averaged axes), is the total mass exactly, as long as the grid covers every kernel; and the
    boundary force density integrates to the walls' contact forces on the grains. The kernel is
    smooth but for a jump of its third derivative (at r = 0 and r = c), so the trapezoid rule
    errs by O((h / c)^4): 1.5e-7 of the mass at h = c / 13, well under 1e-6 at h = c / 40."""
    c = 0.002  # m, the Lucy cutoff: two radii
    h = c / 40
    n = int(np.ceil((settled.positions[:, 2].max() + 2 * c) / h)) + 1
    fields = settled.coarse_grain({"z": (-c, -c + (n - 1) * h, n)}, width=c, function="lucy")
    z, rho = fields["z"], fields["density"]
    assert rho.shape == (n,) and fields["stress"].shape == (n, 3, 3) and fields["velocity"].shape == (n, 3)
    area = BOX[0] * BOX[1]
    assert np.trapz(rho, z) * area == pytest.approx(settled.masses.sum(), rel=1e-6)
    # Each wall contact's kernel integrates to 1 to the same accuracy, so the sum of the side
    # walls' opposite pushes, which nearly cancel, is known to 1e-6 of their magnitudes.
    contacts = settled.contacts()
    on_walls = contacts["force"][contacts["j"] == -1]
    np.testing.assert_allclose(np.trapz(fields["boundary_force"], z, axis=0) * area, on_walls.sum(axis=0),
                               rtol=0, atol=1e-6 * np.abs(on_walls).sum())
    # At rest: no flow, and the stress vanishes above the packing.
    assert np.abs(fields["velocity"]).max() < 1e-3
    assert fields["stress"][-1, 2, 2] == 0


def test_force_pdf_and_fabric_agree_with_the_contacts(settled):
    c = settled.contacts()
    pairs = c["j"] >= 0
    forces = np.linalg.norm(c["force"][pairs], axis=1)
    pdf = settled.force_pdf(bins=20)
    assert pdf["samples"] == pairs.sum()
    assert pdf["mean_force"] == pytest.approx(forces.mean(), rel=1e-12)
    assert (np.diff(pdf["edges"]) * pdf["density"]).sum() == pytest.approx(1, rel=1e-12)
    log_pdf = settled.force_pdf(bins=20, scale="log")
    assert log_pdf["samples"] == pdf["samples"]

    # The fabric tensor from the branch vectors of the same contacts, joined by id.
    by_id = dict(zip(settled.ids, settled.positions))
    branches = np.array([by_id[j] - by_id[i] for i, j in zip(c["i"][pairs], c["j"][pairs])])
    n = branches / np.linalg.norm(branches, axis=1)[:, None]
    np.testing.assert_allclose(settled.fabric_tensor(), n.T @ n / len(n), rtol=0, atol=1e-12)
    assert np.trace(settled.fabric_tensor()) == pytest.approx(1, rel=1e-12)
    hist = settled.fabric_histogram(bins=18)
    assert (np.diff(hist["edges"]) * hist["density"]).sum() == pytest.approx(1, rel=1e-12)
