# slurm_cluster.sh: sourced by the farm tests. A throwaway Slurm cluster on this machine: a
# generated munge key, munged on its own socket, slurmctld and slurmd for one node (localhost, the
# machine's CPUs), all state under one folder, stopped by process id. Needs Debian's slurm-wlm
# and munge (scripts/install-deps.sh).

cluster_pids=()

# Two free TCP ports on localhost, distinct (the kernel picks them; a port taken again before the
# daemons bind it makes the start fail with the reason, not hang).
free_ports() {
  /usr/bin/python3 -c '
import socket
held = [socket.socket() for _ in range(2)]
for s in held: s.bind(("127.0.0.1", 0))
print(" ".join(str(s.getsockname()[1]) for s in held))'
}

# Starts a daemon in the background, recorded for stop_cluster. setpriv --pdeathsig: should this
# script itself be killed outright (SIGKILL, as by a test timeout), the kernel sends the daemon
# SIGTERM, so no daemon outlives the test.
start_daemon() {
  local log=$1; shift
  setpriv --pdeathsig TERM "$@" >"$log" 2>&1 &
  cluster_pids+=($!)
}

# Polls `condition` (a command) until it succeeds or `seconds` pass; returns its last status.
wait_until() {
  local seconds=$1; shift
  local deadline=$((SECONDS + seconds))
  until "$@"; do
    ((SECONDS < deadline)) || return 1
    sleep 0.2
  done
}

# start_cluster DIR: writes DIR/slurm.conf and starts the daemons; exports SLURM_CONF. Prints the
# reason and returns 1 when a daemon cannot start.
start_cluster() {
  local dir=$1
  local cpus host port_ctld port_d
  cpus=$(nproc)
  host=$(hostname -s)
  read -r port_ctld port_d < <(free_ports)
  mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/log"
  chmod 711 "$dir/munge"
  for tool in munged slurmctld slurmd sbatch squeue scontrol setpriv; do
    command -v "$tool" >/dev/null || { echo "cluster: $tool is not installed (scripts/install-deps.sh installs slurm-wlm and munge)"; return 1; }
  done
  head -c 1024 /dev/urandom > "$dir/munge/munge.key"
  chmod 400 "$dir/munge/munge.key"
  start_daemon "$dir/log/munged.out" munged --force --socket="$dir/munge/socket" --key-file="$dir/munge/munge.key" \
    --pid-file="$dir/munge/munged.pid" --seed-file="$dir/munge/seed" --log-file="$dir/log/munged.log" --foreground
  if ! wait_until 20 test -S "$dir/munge/socket"; then
    echo "cluster: munged did not start:"; cat "$dir/log/munged.log"; return 1
  fi
  cat > "$dir/slurm.conf" <<CONF
ClusterName=toyhosttest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port_ctld
SlurmdPort=$port_d
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/socket
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
JobRequeue=1
KillWait=10
MinJobAge=600
InactiveLimit=0
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=farm Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$dir/slurm.conf
  start_daemon "$dir/log/slurmctld.out" slurmctld -D -i -f "$dir/slurm.conf"
  start_daemon "$dir/log/slurmd.out" slurmd -D -f "$dir/slurm.conf" -N "$host"
  if ! wait_until 60 node_idle "$host"; then
    echo "cluster: the node did not come up (sinfo: $(sinfo -h -N -o '%N %T %E' 2>&1))"
    for log in slurmctld.out slurmctld.log slurmd.out slurmd.log; do
      echo "--- $log"; tail -n 30 "$dir/log/$log" 2>/dev/null
    done
    return 1
  fi
}

node_idle() {
  [ "$(sinfo -h -n "$1" -o '%T' 2>/dev/null)" = "idle" ]
}

# Cancels what still runs and stops the daemons by process id; waits until they are gone.
stop_cluster() {
  if [ -n "${SLURM_CONF:-}" ] && ((${#cluster_pids[@]} >= 3)); then
    scancel --quiet --user="$(id -un)" 2>/dev/null
    wait_until 30 no_jobs
  fi
  local pid
  for ((i = ${#cluster_pids[@]} - 1; i >= 0; i--)); do
    pid=${cluster_pids[i]}
    kill -TERM "$pid" 2>/dev/null
    if ! wait_until 30 gone "$pid"; then kill -KILL "$pid" 2>/dev/null; fi
    wait "$pid" 2>/dev/null
  done
  cluster_pids=()
}

no_jobs() { [ -z "$(squeue -h -o %i 2>/dev/null)" ]; }
gone() { ! kill -0 "$1" 2>/dev/null; }

# Waits until job `id` (and its array tasks) left the queue, up to `seconds`.
wait_job() {
  local id=$1 seconds=$2
  wait_until "$seconds" job_done "$id"
}
job_done() { [ -z "$(squeue -h -j "$1" -o %i 2>/dev/null)" ]; }
