"""Checkpoints written from Python go on bit for bit, in Python (talus.resume) and under the
command line (`talus run --restart`); snapshot files read back as the live state."""
import json
import subprocess
import tomllib

import numpy as np

import talus
from conftest import SETTLING_BOX


def by_id(sim):
    order = np.argsort(sim.ids)
    return sim.positions[order], sim.velocities[order], sim.angular_velocities[order]


def test_resume_goes_on_bit_for_bit(tmp_path):
    sim = talus.load(SETTLING_BOX, overrides={"contact.friction": 0.3})
    sim.run(steps=300)
    sim.checkpoint(tmp_path / "state.h5")
    sim.run(steps=300)
    resumed = talus.resume(tmp_path / "state.h5")
    assert resumed.steps == 300 and tomllib.loads(resumed.scenario_toml)["contact"]["friction"] == 0.3
    resumed.run(steps=300)
    assert resumed.time == sim.time
    for a, b in zip(by_id(sim), by_id(resumed)):
        np.testing.assert_array_equal(a, b)
    # load(..., restart=) does the same with a scenario file.
    restarted = talus.load(SETTLING_BOX, overrides={"contact.friction": 0.3}, restart=tmp_path / "state.h5")
    restarted.run(steps=300)
    np.testing.assert_array_equal(by_id(restarted)[0], by_id(sim)[0])


def test_the_command_line_goes_on_from_a_python_checkpoint(tmp_path, talus_executable):
    """`talus run --restart` runs to run.end_time; Python, from the same checkpoint, to the same
    time: the same state, which the run's own final checkpoint holds."""
    overrides = {"run.end_time": 0.02}
    sim = talus.load(SETTLING_BOX, overrides=overrides)
    sim.run(steps=200)
    sim.checkpoint(tmp_path / "state.h5")
    out = tmp_path / "run"
    subprocess.run([talus_executable, "run", str(SETTLING_BOX), "--set", "run.end_time=0.02", "--restart",
                    str(tmp_path / "state.h5"), "--out", str(out), "--quiet", "--threads", "2"], check=True)
    sim.run_until(sim.end_time)
    final = talus.resume(out / "checkpoints" / "latest.h5")
    assert final.steps == sim.steps
    for a, b in zip(by_id(sim), by_id(final)):
        np.testing.assert_array_equal(a, b)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["steps"] == sim.steps and summary["restarted_from"]["step"] == 200


def test_a_python_run_is_the_command_lines_run(tmp_path, talus_executable):
    out = tmp_path / "run"
    subprocess.run([talus_executable, "run", str(SETTLING_BOX), "--set", "run.end_time=0.01", "--out", str(out),
                    "--quiet", "--threads", "2"], check=True)
    sim = talus.load(SETTLING_BOX, overrides={"run.end_time": 0.01})
    sim.run_until(sim.end_time)
    final = talus.resume(out / "checkpoints" / "latest.h5")
    for a, b in zip(by_id(sim), by_id(final)):
        np.testing.assert_array_equal(a, b)
    summary = json.loads((out / "summary.json").read_text())
    mine = sim.summary()
    for key in ("final_time", "steps", "particles", "contacts", "wall_contacts", "energies", "wall_forces", "derived"):
        assert mine[key] == summary[key], key


def test_a_snapshot_file_reads_back_the_live_state(tmp_path):
    sim = talus.load(SETTLING_BOX)
    sim.run(steps=3000)
    live = sim.snapshot()
    live.save(tmp_path / "snapshot.h5")
    saved = talus.read_snapshot(tmp_path / "snapshot.h5")
    assert saved.time == live.time and saved.particle_count == 750
    np.testing.assert_array_equal(saved.positions, live.positions)
    for key, value in live.contacts().items():
        np.testing.assert_array_equal(saved.contacts()[key], value, err_msg=key)
    np.testing.assert_array_equal(saved.fabric_tensor(), sim.fabric_tensor())
    grid = {"z": (0.0, 0.02, 21)}
    np.testing.assert_array_equal(saved.coarse_grain(grid, 0.001)["density"], sim.coarse_grain(grid, 0.001)["density"])
