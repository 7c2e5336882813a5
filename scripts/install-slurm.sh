#!/usr/bin/env bash
# Installs the Debian packages that tests/slurm/local_cluster.sh needs to run a one-node Slurm
# cluster on localhost (slurmctld, slurmd, the client commands, munge); quiet and quick when all
# are present. Daemons are not started here: the harness starts its own, with private state.
set -euo pipefail
cd "$(dirname "$0")/.."
exec ./scripts/install-deps.sh slurmctld slurmd slurm-client munge
