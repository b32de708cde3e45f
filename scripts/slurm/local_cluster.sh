#!/usr/bin/env bash
# A Slurm cluster of one node on this machine, all of it in one folder: to
# try the array scripts beside it before a real cluster, and for the tests.
# Debian's slurmctld, slurmd, slurm-client and munge; no system file is
# changed and nothing listens beyond loopback.
#   scripts/slurm/local_cluster.sh start DIR   # then: export SLURM_CONF=DIR/slurm.conf
#   scripts/slurm/local_cluster.sh stop DIR
# start prints one line naming what failed (and exits 1) when a daemon does
# not come up; its log is in DIR/log.
set -euo pipefail
command=${1:-}
dir=${2:-}
if [[ -z $command || -z $dir ]]; then
  echo "usage: $0 start|stop DIR" >&2
  exit 2
fi
dir=$(mkdir -p "$dir" && cd "$dir" && pwd)

stop() {
  if [[ -f $dir/slurm.conf ]]; then
    SLURM_CONF=$dir/slurm.conf scancel --quiet --user="$(id -un)" 2>/dev/null || true
    SLURM_CONF=$dir/slurm.conf scontrol shutdown 2>/dev/null || true
  fi
  for pid_file in "$dir/slurmctld.pid" "$dir/slurmd.pid" "$dir/munge/munged.pid"; do
    [[ -f $pid_file ]] || continue
    pid=$(cat "$pid_file" 2>/dev/null || true)
    for _ in $(seq 50); do
      [[ -n $pid ]] && kill -0 "$pid" 2>/dev/null || break
      [[ $pid_file == */munged.pid ]] && kill "$pid" 2>/dev/null
      sleep 0.1
    done
    [[ -n $pid ]] && kill -9 "$pid" 2>/dev/null || true
    rm -f "$pid_file"
  done
}

fail() {
  echo "local_cluster: $1 (logs in $dir/log)" >&2
  stop
  exit 1
}

case $command in
  stop) stop; exit 0 ;;
  start) ;;
  *) echo "usage: $0 start|stop DIR" >&2; exit 2 ;;
esac

for tool in munged slurmctld slurmd sbatch squeue scontrol; do
  command -v "$tool" >/dev/null 2>&1 || PATH=$PATH:/usr/sbin
  command -v "$tool" >/dev/null 2>&1 ||
    fail "$tool not found (Debian's slurmctld, slurmd, slurm-client and munge)"
done
mkdir -p "$dir/state" "$dir/spool" "$dir/log" "$dir/munge"
chmod 700 "$dir/munge"

# munge: a fresh key of our own and a socket in the folder.
head -c 1024 /dev/urandom >"$dir/munge/munge.key"
chmod 600 "$dir/munge/munge.key"
munged --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
  --log-file="$dir/log/munged.log" --pid-file="$dir/munge/munged.pid" \
  --seed-file="$dir/munge/munged.seed" 2>>"$dir/log/munged.log" || fail "munged did not start"

# Slurm: this host as its only node, on loopback, at ports of its own.
node=$(hostname -s)
user=$(id -un)
cpus=$(nproc)
memory_mb=$(awk '/MemTotal/ { printf "%d", $2 / 1024 * 0.8 }' /proc/meminfo)
port=$((20000 + RANDOM % 20000))
cat >"$dir/slurm.conf" <<CONF
ClusterName=edgefit
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
KillWait=5
MpiDefault=none
SwitchType=switch/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -f "$SLURM_CONF" 2>>"$dir/log/slurmctld.log" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" 2>>"$dir/log/slurmd.log" || fail "slurmd did not start"
for _ in $(seq 100); do
  state=$(sinfo -h -n "$node" -o %t 2>/dev/null || true)
  if [[ $state == idle ]]; then
    echo "local_cluster: up, node $node ($cpus CPUs, $memory_mb MB); export SLURM_CONF=$SLURM_CONF"
    exit 0
  fi
  sleep 0.2
done
fail "the node did not come up (state '${state:-none}')"
