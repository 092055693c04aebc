#!/usr/bin/env bash
# A one-node SLURM cluster on this machine, from Debian's slurm-wlm, for tests:
#   scripts/slurm-cluster.sh start DIR    writes DIR/slurm.conf, starts slurmctld and slurmd
#                                         (state, spool, logs and pid files in DIR) and waits
#                                         until the node takes jobs; then
#                                         export SLURM_CONF=DIR/slurm.conf
#   scripts/slurm-cluster.sh stop DIR     stops both daemons and removes DIR
# No munge: AuthType=auth/none and CredType=cred/none, which Slurm 22.05 still has and
# which suit a cluster of one machine that only its own user reaches. The ports are
# derived from DIR's name, so two clusters on one machine (or a leftover) do not meet.
# A failed start is one line naming the daemon that failed and its log; what was started
# is stopped, and DIR keeps the logs alone (no slurm.conf to point SLURM_CONF at); exit 1.
set -euo pipefail
action=${1:?usage: slurm-cluster.sh start|stop DIR}
dir=${2:?usage: slurm-cluster.sh start|stop DIR}

stop() {
  for daemon in slurmd slurmctld; do
    if [[ -f "$dir/$daemon.pid" ]]; then
      pid=$(cat "$dir/$daemon.pid")
      kill "$pid" 2>/dev/null || true
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
      kill -9 "$pid" 2>/dev/null || true
    fi
  done
}

case "$action" in
  stop)
    [[ -d "$dir" ]] || exit 0
    stop
    rm -rf "$dir"
    ;;
  start)
    for program in slurmctld slurmd sinfo; do
      command -v "$program" >/dev/null || { echo "slurm-cluster: $program is not installed (Debian package slurm-wlm)" >&2; exit 1; }
    done
    mkdir -p "$dir/state" "$dir/spool"
    dir=$(cd "$dir" && pwd)
    host=$(hostname -s)
    port=$((20000 + $(printf '%s' "$dir" | cksum | cut -d' ' -f1) % 20000))
    user=$(id -un)
    cat > "$dir/slurm.conf" <<CONF
ClusterName=grainmesh-test
SlurmctldHost=$host
AuthType=auth/none
CredType=cred/none
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$(nproc) RealMemory=$(( $(free -m | awk '/^Mem:/ {print $2}') / 2 )) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$dir/slurm.conf"
    failed() {
      echo "slurm-cluster: $1; see $2" >&2
      stop
      rm -rf "$dir/slurm.conf" "$dir/state" "$dir/spool" "$dir"/*.pid
      exit 1
    }
    # Each daemon forks into the background once its configuration is read; one that dies
    # after that (a port in use) is caught by its pid file's process having gone.
    for daemon in slurmctld slurmd; do
      status=0
      "$daemon" -f "$SLURM_CONF" > "$dir/$daemon.out" 2>&1 || status=$?
      [[ -s "$dir/$daemon.out" ]] && cat "$dir/$daemon.out" >> "$dir/$daemon.log"
      rm -f "$dir/$daemon.out"
      [[ $status -eq 0 ]] || failed "$daemon did not start (exit code $status)" "$dir/$daemon.log"
      for _ in $(seq 50); do [[ -s "$dir/$daemon.pid" ]] && break; sleep 0.1; done
      sleep 0.3
      [[ -s "$dir/$daemon.pid" ]] && kill -0 "$(cat "$dir/$daemon.pid")" 2>/dev/null ||
        failed "$daemon stopped as it started" "$dir/$daemon.log"
    done
    for _ in $(seq 100); do
      if [[ "$(sinfo -h -o '%t' 2>/dev/null)" == "idle" ]]; then exit 0; fi
      sleep 0.2
    done
    failed "the node is not idle after 20 s ($(sinfo -h -o '%t' 2>&1))" "$dir/slurmctld.log and $dir/slurmd.log"
    ;;
  *)
    echo "usage: slurm-cluster.sh start|stop DIR" >&2
    exit 2
    ;;
esac
