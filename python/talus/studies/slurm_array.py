"""Slurm job arrays for the studies (`--slurm FILE`), for clusters that schedule jobs, not
ranks. Task i of the array runs the study's part i (`--case-index i`: one case of a sweep,
ensemble or flow map, one base roughness of an h_stop search) on one core; each task, once its
part is done, writes the study's tables if every part is finished, so the last task to end
leaves the complete results. Finished cases are reused, as in any run of the tools, so a task
that is cut off and submitted again goes on where it stopped.
"""
import os
import shlex
import sys


def without_option(argv, name):
    """argv without `name VALUE` and `name=VALUE`."""
    out, skip = [], False
    for arg in argv:
        if skip:
            skip = False
        elif arg == name:
            skip = True
        elif not arg.startswith(name + "="):
            out.append(arg)
    return out


def add_options(parser):
    """The --slurm, --slurm-time and --case-index options every study tool takes."""
    parser.add_argument("--slurm", metavar="FILE", help="write a Slurm job-array script instead of running")
    parser.add_argument("--slurm-time", metavar="LIMIT", help="#SBATCH --time of each array task, e.g. 12:00:00")
    parser.add_argument("--case-index", type=int, help="run part i of the study only (a Slurm array task)")


def check_index(index, parts, name):
    if index is not None and not 0 <= index < parts:
        sys.exit("%s: --case-index %d: the study has %d parts (0 to %d)" % (name, index, parts, parts - 1))


def task_argv(argv, talus):
    """A study's `python3 -m talus` arguments for its array tasks: without --slurm, and with the
    talus executable this study found, so that every task runs the same one."""
    return without_option(without_option(argv, "--slurm"), "--talus") + ["--talus", talus]


def write_script(path, parts, job_name, log_dir, argv, time_limit=None):
    """Writes an sbatch script of `parts` array tasks, each running `python3 -m talus` with
    `argv` (task_argv) plus `--case-index $SLURM_ARRAY_TASK_ID`, from the directory it was
    written in, with this package on PYTHONPATH. Paths in argv stay as given, relative to
    that directory."""
    package_parent = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    command = " ".join(shlex.quote(a) for a in [sys.executable, "-m", "talus"] + list(argv))
    lines = [
        "#!/bin/bash",
        "# %s as a Slurm job array: sbatch %s" % (job_name, os.path.basename(path)),
        "#SBATCH --job-name=%s" % job_name,
        "#SBATCH --array=0-%d" % (parts - 1),
        "#SBATCH --ntasks=1",
        "#SBATCH --cpus-per-task=1",
        "#SBATCH --output=%s" % os.path.join(os.path.abspath(log_dir), "slurm-%A_%a.log"),
    ]
    if time_limit:
        lines.append("#SBATCH --time=%s" % time_limit)
    lines += [
        "set -euo pipefail",
        "cd %s" % shlex.quote(os.getcwd()),
        "export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE",
        "export PYTHONPATH=%s${PYTHONPATH:+:$PYTHONPATH}" % shlex.quote(package_parent),
        "exec %s --case-index \"$SLURM_ARRAY_TASK_ID\"" % command,
        "",
    ]
    os.makedirs(os.path.abspath(log_dir), exist_ok=True)
    tmp = "%s.%d.tmp" % (path, os.getpid())
    with open(tmp, "w") as f:
        f.write("\n".join(lines))
    os.chmod(tmp, 0o755)
    os.replace(tmp, path)
    print("%s: %d array tasks in %s (submit with: sbatch %s)" % (job_name, parts, path, path))
