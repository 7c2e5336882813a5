#!/usr/bin/env bash
# Runs a Slurm batch (or job-array) script on a private one-node Slurm cluster on localhost, to test
# the scripts that `talus ... --slurm FILE` writes without a real cluster.
#   usage: tests/slurm/local_cluster.sh SCRIPT [TIMEOUT_SECONDS]   (timeout default 300)
# Starts munged, slurmctld and slurmd with all their state (config, key, socket, spool, logs) in a
# fresh temporary dir, on free ports, and never reads or writes /etc/slurm or the system's munge;
# so two runs can go side by side. Submits SCRIPT from the current directory, waits, prints each
# task's state and exit code, and exits 0 only if every task COMPLETED (else the highest task exit
# code, or 1; 124 on timeout). Daemons are always stopped on exit. Needs scripts/install-slurm.sh
# and root (slurmd runs jobs as the submitting user). TALUS_SLURM_KEEP=1 keeps the state dir.
set -euo pipefail
script=${1:?usage: $0 SCRIPT [TIMEOUT_SECONDS]}
timeout_s=${2:-300}
[ -r "$script" ] || { echo "local_cluster: cannot read $script" >&2; exit 2; }
for c in munged slurmctld slurmd sbatch; do
  command -v "$c" >/dev/null || { echo "local_cluster: $c not found (scripts/install-slurm.sh)" >&2; exit 2; }
done
t0=$SECONDS
state=$(mktemp -d /tmp/talus-slurm.XXXXXX)
chmod 711 "$state"  # munged wants its socket's directory and the ones above it searchable by all
mkdir -p "$state"/{munge,spool/ctld,spool/d,log}
chmod 755 "$state/munge"
pids=()
# shellcheck disable=SC2317  # run by the EXIT trap
cleanup() {
  local rc=$? p i f
  trap - INT TERM
  if [ -n "${jobid:-}" ]; then  # cancel a job still going, and give its tasks 10 s to end
    scancel "$jobid" 2>/dev/null || true
    for _ in $(seq 100); do squeue -h -j "$jobid" 2>/dev/null | grep -q . || break; sleep 0.1; done
  fi
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do  # slurmd, slurmctld, then munged: 5 s each
    p=${pids[i]}
    kill "$p" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$p" 2>/dev/null || true
  done
  # Backstop: a slurmstepd left over (it holds our slurmd log open and ignores SIGTERM), with
  # every process in its session (the job's tasks).
  for f in /proc/[0-9]*/fd/*; do
    [[ $(readlink "$f" 2>/dev/null) == "$state"/* ]] || continue
    p=${f#/proc/}; p=${p%%/*}
    [ "$p" = $$ ] && continue
    ps -eo pid=,sid= | awk -v s="$(ps -o sid= -p "$p")" '$2 == s { print $1 }' | xargs -r kill -9 2>/dev/null || true
  done
  if [ "$rc" -ne 0 ] && [ -z "${job_done:-}" ]; then  # the harness failed, not a task
    for l in "$state"/log/*; do
      [ -s "$l" ] && { echo "--- tail $l" >&2; tail -n 15 "$l" >&2; }
    done
  fi
  if [ "${TALUS_SLURM_KEEP:-0}" = 1 ]; then echo "local_cluster: state kept in $state" >&2
  else rm -rf "$state"; fi
  exit "$rc"
}
trap cleanup EXIT
trap "exit 130" INT; trap "exit 143" TERM

# Two free TCP ports on localhost, one for slurmctld, one for slurmd.
free_port() {
  local p
  while :; do
    p=$((20000 + RANDOM % 20000))
    ss -Hltn "sport = :$p" | grep -q . || ss -Hltn "sport = :$((p + 1))" | grep -q . || { echo "$p"; return; }
  done
}
port=$(free_port)

dd if=/dev/urandom of="$state/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$state/munge/munge.key"
sock=$state/munge/munge.socket
munged -F --socket="$sock" --key-file="$state/munge/munge.key" --pid-file="$state/munge/munged.pid" \
  --seed-file="$state/munge/munged.seed" >"$state/log/munged.log" 2>&1 &
pids+=($!)

# The node as slurmd sees this machine (real CPUs, sockets, memory), under a fixed name.
node=talusnode
hw=$(slurmd -C | head -n 1 | sed 's/^NodeName=[^ ]* //')
export SLURM_CONF=$state/slurm.conf
cat > "$SLURM_CONF" <<EOF
ClusterName=talustest
SlurmctldHost=localhost
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
StateSaveLocation=$state/spool/ctld
SlurmdSpoolDir=$state/spool/d
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
ReturnToService=2
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 NodeHostname=localhost $hw State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
for _ in $(seq 100); do [ -S "$sock" ] && break; sleep 0.1; done
slurmctld -D -f "$SLURM_CONF" >"$state/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$node" >"$state/log/slurmd.out" 2>&1 &
pids+=($!)
up=""
for _ in $(seq 300); do
  [ "$(sinfo -h -n "$node" -o %t 2>/dev/null)" = idle ] && { up=1; break; }
  for p in "${pids[@]}"; do
    kill -0 "$p" 2>/dev/null || { echo "local_cluster: a daemon died at start (pid $p)" >&2; exit 3; }
  done
  sleep 0.1
done
[ -n "$up" ] || { echo "local_cluster: node $node not idle after 30 s" >&2; exit 3; }
echo "local_cluster: cluster up in $((SECONDS - t0)) s (ports $port, $((port + 1)); state $state)" >&2

t1=$SECONDS
jobid=$(sbatch --parsable "$script")
jobid=${jobid%%;*}
echo "local_cluster: submitted job $jobid" >&2
# Poll every 0.5 s (sbatch --wait polls every 10 s) until every task is in a final state.
final='^(COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED|BOOT_FAIL|DEADLINE)$'
while :; do
  states=$(squeue -h -r -j "$jobid" -t all -o %T 2>/dev/null) || states=""
  [ -n "$states" ] && ! grep -qvE "$final" <<<"$states" && break
  if [ $((SECONDS - t1)) -ge "$timeout_s" ]; then
    echo "local_cluster: job $jobid timed out after $timeout_s s; states: ${states//$'\n'/ }" >&2
    exit 124
  fi
  sleep 0.5
done
job_done=1
echo "local_cluster: job $jobid done in $((SECONDS - t1)) s" >&2

# One line per task: TASK STATE EXITCODE (signal after the colon); then the overall status.
rc=0
report=()
while read -r line; do
  task=$(grep -o 'ArrayTaskId=[^ ]*' <<<"$line" || grep -o 'JobId=[^ ]*' <<<"$line")
  st=$(grep -o 'JobState=[^ ]*' <<<"$line"); st=${st#*=}
  ec=$(grep -o ' ExitCode=[^ ]*' <<<"$line"); ec=${ec#*=}
  report+=("${task#*=} $st $ec")
  if [ "$st" != COMPLETED ]; then
    code=${ec%%:*}
    if [ "$code" -gt "$rc" ]; then rc=$code; fi
    if [ "$rc" -eq 0 ]; then rc=1; fi
  fi
done < <(scontrol -o show job "$jobid")
printf '%s\n' "${report[@]}" | sort -n
jobid=""
exit "$rc"
