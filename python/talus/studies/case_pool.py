"""Where the cases of a study run: `open_pool(jobs)` gives the pool every study tool (sweep,
ensemble, h_stop search, flow map) starts its `talus run` processes through.

- Alone, a LocalPool runs up to `jobs` processes at once on this machine.
- Under mpirun (or srun) with more than one rank, rank 0 drives the study and runs one case
  itself; every other rank serves: it runs the cases rank 0 sends it, one at a time, and
  reports their exit status. `open_pool` never returns on a serving rank. A study's logic
  (which case next, speculative cases cancelled) is the same either way.

Ranks wait by polling with sleeps, not in a blocking receive: Open MPI's blocking receive spins
a core, which the cases need. Cases run without the MPI variables of their parent, so a case
never mistakes itself for a rank of the study's job.
"""
import atexit
import os
import subprocess
import sys
import time

POLL_SECONDS = 0.2
_RUN, _CANCEL, _DONE, _STOP = 1, 2, 3, 4
# What a launcher sets in its ranks (Open MPI, PMIx, PMI, Slurm's step): a case must not see them.
_LAUNCHER_PREFIXES = ("OMPI_", "PMIX_", "PMI_", "OPAL_", "ORTE_", "HYDRA_", "MPI_LOCALNRANKS", "MPI_LOCALRANKID")


def case_environment(extra=None):
    """This process's environment without the launcher's variables, one OpenMP thread that sleeps
    when idle, plus `extra`."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(_LAUNCHER_PREFIXES)}
    env.update(OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE")
    env.update(extra or {})
    return env


def launched_rank():
    """This process's rank under a launcher (0 when started alone)."""
    for key in ("OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"):
        if os.environ.get(key, "").isdigit():
            return int(os.environ[key])
    return 0


def launched_ranks():
    """The rank count a launcher gave this process (1 when started alone)."""
    for key in ("OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"):
        if os.environ.get(key, "").isdigit():
            return int(os.environ[key])
    return 1


class _Pool:
    def wait_any(self):
        """Blocks until a case ends: (key, exit status)."""
        while True:
            done = self.poll()
            if done:
                return done
            time.sleep(POLL_SECONDS)


class LocalPool(_Pool):
    """Up to `slots` cases at once on this machine. A case is (key, command, log path)."""

    def __init__(self, slots):
        self.slots = slots
        self.running = {}  # key -> (Popen, log file)

    def free(self):
        return self.slots - len(self.running)

    def start(self, key, cmd, log_path):
        log = open(log_path, "w")
        self.running[key] = (subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=case_environment()), log)

    def cancel(self, key):
        proc, log = self.running.pop(key)
        proc.terminate()
        proc.wait()
        log.close()

    def poll(self):
        """A finished case as (key, exit status), or None."""
        for key, (proc, log) in list(self.running.items()):
            if proc.poll() is not None:
                del self.running[key]
                log.close()
                return key, proc.returncode
        return None


    def close(self):
        for key in list(self.running):
            self.cancel(key)


class MpiPool(_Pool):
    """Rank 0's view of the ranks: one case of its own (a LocalPool of one slot) and one case
    on each serving rank."""

    def __init__(self, comm):
        self.comm = comm
        self.local = LocalPool(1)
        self.idle = list(range(1, comm.Get_size()))
        self.remote = {}  # key -> rank
        self.finished = []  # (key, status) received while waiting for something else
        self.closed = False

    @property
    def running(self):
        return {**self.remote, **self.local.running}

    def free(self):
        return self.local.free() + len(self.idle)

    def start(self, key, cmd, log_path):
        if self.local.free() > 0:
            self.local.start(key, cmd, log_path)
            return
        rank = self.idle.pop(0)
        self.remote[key] = rank
        self.comm.send((key, cmd, log_path), dest=rank, tag=_RUN)

    def _receive(self):
        from mpi4py import MPI
        status = MPI.Status()
        if not self.comm.Iprobe(source=MPI.ANY_SOURCE, tag=_DONE, status=status):
            return None
        key, code = self.comm.recv(source=status.Get_source(), tag=_DONE)
        self.remote.pop(key, None)
        self.idle.append(status.Get_source())
        return key, code

    def cancel(self, key):
        if key in self.local.running:
            self.local.cancel(key)
            return
        self.comm.send(key, dest=self.remote[key], tag=_CANCEL)
        while key in self.remote:  # its report comes, cancelled or finished before the request
            done = self._receive()
            if done is None:
                time.sleep(POLL_SECONDS)
            elif done[0] != key:
                self.finished.append(done)

    def poll(self):
        if self.finished:
            return self.finished.pop(0)
        return self.local.poll() or self._receive()


    def close(self):
        if self.closed:
            return
        self.closed = True
        self.local.close()
        for key in list(self.remote):
            self.cancel(key)
        for rank in range(1, self.comm.Get_size()):
            self.comm.send(None, dest=rank, tag=_STOP)


def serve(comm):
    """A serving rank: runs what rank 0 sends until it says stop."""
    from mpi4py import MPI
    status = MPI.Status()
    while True:
        if not comm.Iprobe(source=0, tag=MPI.ANY_TAG, status=status):
            time.sleep(POLL_SECONDS)
            continue
        tag = status.Get_tag()
        message = comm.recv(source=0, tag=tag)
        if tag == _STOP:
            return
        if tag == _CANCEL:  # for a case that ended before the request came: already reported
            continue
        key, cmd, log_path = message
        with open(log_path, "w") as log:
            proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=case_environment())
            while proc.poll() is None:
                if comm.Iprobe(source=0, tag=_CANCEL):
                    if comm.recv(source=0, tag=_CANCEL) == key:
                        proc.terminate()
                        proc.wait()
                        break
                time.sleep(POLL_SECONDS)
        comm.send((key, proc.returncode), dest=0, tag=_DONE)


def open_pool(jobs, name="study"):
    """The pool for this process: a LocalPool of `jobs` slots, or under a launcher with several
    ranks an MpiPool on rank 0 (`jobs` is then one case per rank). Serving ranks never return."""
    if launched_ranks() <= 1:
        return LocalPool(jobs)
    from mpi4py import MPI  # Debian's python3-mpi4py
    comm = MPI.COMM_WORLD
    if comm.Get_size() <= 1:
        return LocalPool(jobs)
    if comm.Get_rank() != 0:
        serve(comm)
        MPI.Finalize()
        sys.exit(0)
    print("%s: %d ranks, one case each" % (name, comm.Get_size()), flush=True)
    pool = MpiPool(comm)
    atexit.register(pool.close)  # also after an exception: the serving ranks stop with rank 0
    return pool
