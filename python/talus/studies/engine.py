"""The talus executable that runs a study's cases. Studies live in this package and start the
engine as a separate program; the engine never calls back into them.

The executable is, in this order: the one named by --talus, $TALUS_BINARY, the one this
package was built or installed with (build/talus beside build/python/talus, or P/bin/talus
beside P/lib/python3/dist-packages/talus), the first `talus` on PATH."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

from . import case_pool

PACKAGE = Path(__file__).resolve().parent.parent  # the talus package's folder


def _beside_package():
    candidates = [PACKAGE.parent.parent / "talus"]  # build tree
    if len(PACKAGE.parents) > 3:
        candidates.append(PACKAGE.parents[3] / "bin" / "talus")  # installed prefix
    return [c for c in candidates if c.is_file() and os.access(c, os.X_OK)]


def find_talus(explicit=None) -> str:
    """The absolute path of the talus executable; exits with a message when there is none.
    Absolute, because a Slurm array task runs it from the script it was written into."""
    for name, source in ((explicit, "--talus"), (os.environ.get("TALUS_BINARY"), "TALUS_BINARY")):
        if name:
            found = shutil.which(name)
            if not found:
                sys.exit(f"talus: {source} {name}: no such executable")
            return os.path.abspath(found)
    beside = _beside_package()
    if beside:
        return str(beside[0])
    found = shutil.which("talus")
    if found:
        return os.path.abspath(found)
    sys.exit("talus: no talus executable found beside the package or on PATH; pass --talus PATH "
             "or set TALUS_BINARY")


def check_scenario(talus: str, scenario: str, overrides) -> None:
    """`talus check` on the scenario with the first case's overrides, once before any case
    starts: bad input stops here with its file and line, rather than in every case's log.
    Exits with the check's status (2 for bad input) when it fails."""
    if case_pool.launched_rank() != 0:  # under mpirun, rank 0 checks for everyone
        return
    cmd = [talus, "check", scenario]
    for o in overrides:
        cmd += ["--set", o]
    # The case environment: a check started by an MPI rank must not join the rank's job.
    proc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          env=case_pool.case_environment())
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr)
        sys.exit(proc.returncode if proc.returncode > 0 else 1)
