#!/usr/bin/env bash
# A single-node Slurm cluster on 127.0.0.1, for `girtd sweep --slurm` on one
# machine and its CTest: munged, then slurmctld and slurmd from one
# slurm.conf naming this host on 127.0.0.1.
#   tools/slurm_local.sh up DIR     start munged (if not running), slurmctld and slurmd;
#                                   configuration, state, spool, logs and pids in DIR;
#                                   prints `export SLURM_CONF=DIR/slurm.conf`
#   tools/slurm_local.sh down DIR   stop what `up DIR` started
# Needs root and Debian's slurmctld slurmd slurm-client munge (tools/girtd slurm-up installs them).
set -euo pipefail
cmd=${1:?up or down}
dir=$(mkdir -p "${2:?a folder}" && cd "$2" && pwd)
export SLURM_CONF=$dir/slurm.conf

stop() {
  local pids=()
  for d in slurmd slurmctld; do
    [[ -f $dir/$d.pid ]] && pids+=("$(cat "$dir/$d.pid")")
  done
  [[ -f $dir/munged.started && -f /run/munge/munged.pid ]] && pids+=("$(cat /run/munge/munged.pid)")
  ((${#pids[@]})) || { rm -f "$dir/munged.started"; return 0; }
  local live=()
  for p in "${pids[@]}"; do  # ours only: a stale pid file may name another process by now
    grep -qE '^(slurmd|slurmctld|munged)$' "/proc/$p/comm" 2>/dev/null && live+=("$p")
  done
  ((${#live[@]})) && { kill "${live[@]}" 2>/dev/null || true; }
  for _ in $(seq 50); do  # until they are gone
    ((${#live[@]})) && kill -0 "${live[@]}" 2>/dev/null || break
    sleep 0.1
  done
  rm -f "$dir/munged.started"
  return 0
}

if [[ $cmd == down ]]; then stop; exit 0; fi
[[ $cmd == up ]] || { echo "usage: $0 up|down DIR" >&2; exit 2; }
for p in slurmctld slurmd sbatch munged; do
  command -v "$p" >/dev/null || { echo "$0: $p is missing: tools/girtd slurm-up installs Slurm" >&2; exit 2; }
done
host=$(hostname -s)
mkdir -p "$dir/state" "$dir/spool"
cat > "$SLURM_CONF" <<CONF
ClusterName=girtd
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
if ! pgrep -x munged >/dev/null; then
  mkdir -p /run/munge && chown munge:munge /run/munge
  runuser -u munge -- /usr/sbin/munged
  touch "$dir/munged.started"
fi
slurmctld
slurmd
for _ in $(seq 100); do  # until the node takes jobs
  sinfo --noheader -o %T 2>/dev/null | grep -qE '^(idle|mixed|allocated)' && { echo "export SLURM_CONF=$SLURM_CONF"; exit 0; }
  sleep 0.2
done
echo "$0: the node did not come up; logs in $dir" >&2
stop
exit 1
