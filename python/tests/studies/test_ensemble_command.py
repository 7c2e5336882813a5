"""`python3 -m talus ensemble` runs the seeds of a tiny scenario through the talus executable,
alone, over MPI ranks and as a Slurm job array, and stops at bad input before any run. The
executable is this build's (TALUS_EXECUTABLE, set by ctest)."""
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import talus
from talus.studies import engine

REPOSITORY = Path(__file__).resolve().parents[3]
DROP = REPOSITORY / "tests" / "data" / "five_spheres_drop.toml"  # five spheres, a few ms


@pytest.fixture
def talus_executable():
    path = os.environ.get("TALUS_EXECUTABLE", str(REPOSITORY / "build" / "talus"))
    if not os.access(path, os.X_OK):
        pytest.skip(f"no talus executable at {path}")
    return path


@pytest.fixture
def drop(tmp_path):
    shutil.copyfile(DROP, tmp_path / "drop.toml")
    return tmp_path / "drop.toml"


def study(*args, cwd, env=None, launcher=()):
    """Runs `python3 -m talus ARGS` with this package first on the path."""
    environment = dict(os.environ if env is None else env)
    package_parent = str(Path(talus.__file__).resolve().parent.parent)
    environment["PYTHONPATH"] = os.pathsep.join([package_parent] + [p for p in [environment.get("PYTHONPATH")] if p])
    return subprocess.run([*launcher, sys.executable, "-m", "talus", *map(str, args)], cwd=cwd, env=environment,
                          capture_output=True, text=True, timeout=300)


def test_runs_every_seed_through_the_executable(tmp_path, drop, talus_executable):
    env = dict(os.environ, TALUS_BINARY=talus_executable)  # found without --talus
    done = study("ensemble", drop, "--seeds", 2, "--jobs", 2, "--out", tmp_path / "out", "--set", "run.end_time=0.001",
                 cwd=tmp_path, env=env)
    assert done.returncode == 0, done.stderr
    e = json.loads((tmp_path / "out" / "ensemble.json").read_text())
    assert e["runs"] == 2
    assert e["measurements"]["particles"]["mean"] == 5.0
    assert "verdict" not in e  # no regime in these summaries
    for k in (1, 2):  # each run got its own seed and the common override
        text = (tmp_path / "out" / f"seed_{k}" / "scenario.toml").read_text()
        assert f"seed = {k}" in text and "end_time = 0.001" in text


def test_bad_key_stops_before_any_run(tmp_path, drop, talus_executable):
    drop.write_text(drop.read_text().replace("[run]\n", "[run]\nend_tme = 0.001\n"))
    done = study("ensemble", drop, "--seeds", 2, "--out", tmp_path / "out", "--talus", talus_executable, cwd=tmp_path)
    assert done.returncode == 2
    assert f"{drop}:4" in done.stderr, done.stderr  # the file and line of the bad key
    assert "end_tme" in done.stderr
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_bad_grid_value_stops_a_sweep_before_any_run(tmp_path, drop, talus_executable):
    done = study("sweep", drop, "--grid", "run.end_time=-1,0.001", "--out", tmp_path / "out",
                 "--talus", talus_executable, cwd=tmp_path)
    assert done.returncode == 2
    assert "run.end_time" in done.stderr, done.stderr
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_finds_the_executable_beside_the_build(monkeypatch, talus_executable):
    built = Path(talus.__file__).resolve().parents[2] / "talus"  # build/python/talus -> build/talus
    if not built.is_file():
        pytest.skip("the package is not in a build tree")
    monkeypatch.delenv("TALUS_BINARY", raising=False)
    assert engine.find_talus() == str(built)
    assert engine.find_talus(talus_executable) == os.path.abspath(talus_executable)


@pytest.mark.skipif(shutil.which("mpirun") is None, reason="no mpirun")
def test_spreads_seeds_over_ranks(tmp_path, drop, talus_executable):
    # Rank 0 drives and runs one seed, rank 1 the others as they come; the ensemble is the same.
    done = study("ensemble", drop, "--seeds", 4, "--out", tmp_path / "out", "--set", "run.end_time=0.001",
                 "--talus", talus_executable, cwd=tmp_path,
                 launcher=("mpirun", "--oversubscribe", "--allow-run-as-root", "-n", "2"))
    assert done.returncode == 0, done.stdout + done.stderr
    assert "ensemble: 2 ranks" in done.stdout
    assert json.loads((tmp_path / "out" / "ensemble.json").read_text())["runs"] == 4
    for k in range(1, 5):
        assert (tmp_path / "out" / f"seed_{k}" / "summary.json").exists(), k


def test_slurm_array_runs_one_seed_per_task(tmp_path, drop, talus_executable):
    # The script is run task by task, as Slurm would; the last task alone writes the ensemble.
    done = study("ensemble", "drop.toml", "--seeds", 3, "--out", "out", "--set", "run.end_time=0.001",
                 "--talus", talus_executable, "--slurm", "ensemble.sbatch", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    script = (tmp_path / "ensemble.sbatch").read_text()
    assert "#SBATCH --array=0-2" in script
    assert f"--talus {talus_executable}" in script or f"--talus {os.path.abspath(talus_executable)}" in script
    assert not (tmp_path / "out" / "seed_1").exists()  # --slurm runs nothing
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # the script says where the package is
    for task in range(3):
        assert not (tmp_path / "out" / "ensemble.json").exists(), task
        ran = subprocess.run(["bash", "ensemble.sbatch"], cwd=tmp_path, env=dict(env, SLURM_ARRAY_TASK_ID=str(task)),
                             capture_output=True, text=True, timeout=300)
        assert ran.returncode == 0, ran.stdout + ran.stderr
        assert (tmp_path / "out" / f"seed_{task + 1}" / "summary.json").exists()
    assert json.loads((tmp_path / "out" / "ensemble.json").read_text())["runs"] == 3
