"""What the talus module's tests share: where the repository's files are, and the talus
executable when the build has one (TALUS_EXECUTABLE, set by ctest)."""
import os
import pathlib

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
SCENARIOS = pathlib.Path(__file__).resolve().parent / "scenarios"
SETTLING_BOX = REPOSITORY / "examples" / "settling_box.toml"


@pytest.fixture
def talus_executable():
    path = os.environ.get("TALUS_EXECUTABLE", str(REPOSITORY / "build" / "talus"))
    if not os.access(path, os.X_OK):
        pytest.skip(f"no talus executable at {path}")
    return path
