"""`python3 -m talus flowmap --continue-from` runs a finished sweep's cases on to a later end time
from their final checkpoints, and ends with the results of a sweep run from the start to that
time (the same averaging window, the same bits). The executable is this build's
(TALUS_EXECUTABLE, set by ctest)."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import talus

REPOSITORY = Path(__file__).resolve().parents[3]
CHUTE = REPOSITORY / "tests" / "data" / "small_chute.toml"
# talus_executable: the fixture of python/tests/conftest.py.


def flowmap(out, end_time, talus_executable, *extra):
    environment = dict(os.environ)
    package_parent = str(Path(talus.__file__).resolve().parent.parent)
    environment["PYTHONPATH"] = os.pathsep.join([package_parent] + [p for p in [environment.get("PYTHONPATH")] if p])
    done = subprocess.run([sys.executable, "-m", "talus", "flowmap", str(CHUTE), "--lambda", "1", "--heights", "4",
                           "--angles", "24", "--end-time", str(end_time), "--average", "1", "--jobs", "1",
                           "--out", str(out), "--talus", talus_executable, *extra],
                          env=environment, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads((out / "lambda1_H4_theta24" / "summary.json").read_text())


def test_continued_sweep_ends_as_a_sweep_from_the_start(tmp_path, talus_executable):
    reference = flowmap(tmp_path / "reference", 6, talus_executable)
    short = flowmap(tmp_path / "short", 3, talus_executable)
    continued = flowmap(tmp_path / "long", 6, talus_executable, "--continue-from", str(tmp_path / "short"))
    assert continued["restarted_from"]["step"] == short["steps"]
    assert continued["steps"] == reference["steps"]
    assert continued["chute"]["averaging_window"] == reference["chute"]["averaging_window"]
    for key in ("h", "froude", "K", "alpha", "mean_velocity"):
        assert continued[key] == reference[key], key
    rows = (tmp_path / "long" / "sweep_runs.csv").read_text().splitlines()
    assert len(rows) == 2 and ",end_time," in rows[1]


def test_a_case_the_earlier_sweep_lacks_runs_from_the_start(tmp_path, talus_executable):
    (tmp_path / "empty").mkdir()
    continued = flowmap(tmp_path / "long", 2, talus_executable, "--continue-from", str(tmp_path / "empty"))
    assert "restarted_from" not in continued


def test_a_missing_earlier_sweep_is_an_error(tmp_path, talus_executable):
    with pytest.raises(AssertionError, match="nowhere: no such folder"):
        flowmap(tmp_path / "long", 2, talus_executable, "--continue-from", str(tmp_path / "nowhere"))
