#!/usr/bin/env bash
# one_node_cluster.sh: a throw-away Slurm cluster of one node on 127.0.0.1, started and stopped from a
# script (no systemd), for the Slurm tests of ochre (tests/cli/slurm) and for trying tools/scripts/ochre-slurm.
# Debian 12 packages: slurmctld slurmd slurm-client munge (tools/setup.sh installs them).
#
#   one_node_cluster.sh -d DIR start      write DIR/etc/slurm.conf, start munged, slurmctld, slurmd
#   one_node_cluster.sh -d DIR env        print "export SLURM_CONF=DIR/etc/slurm.conf" for clients
#   one_node_cluster.sh -d DIR wait JOBID wait until JOBID (or a whole array) has ended; exit 0 only if
#                                         every record is COMPLETED
#   one_node_cluster.sh -d DIR stop       cancel the jobs, stop our daemons by PID, remove DIR
#   one_node_cluster.sh check             exit 0 when this machine can run the cluster (root, binaries)
#
# Everything (config, state, spool, logs, sockets, PID files) lives in DIR; nothing outside it is
# written. Settings (environment):
#   SLURM_ONE_NODE_PORTS    "CTLD SLURMD" ports, default: a free pair chosen at random in 20000-59999
#   SLURM_ONE_NODE_AUTH     munge (default) | none (no munged; any local process may claim any uid)
#   SLURM_ONE_NODE_TIMEOUT  seconds for each daemon to come up and for `wait` (default 120)
#   SLURM_ONE_NODE_KEEP=1   `stop` keeps DIR (its log/ folder) instead of removing it
#
# What it takes care of (each found by trying on Debian 12, Slurm 22.05, munge 0.5.15):
# - munged refuses a socket directory that is not searchable by all (mktemp -d makes 0700 folders) and
#   a socket path longer than a Unix socket allows: keep DIR short (e.g. /tmp/ochre-slurm.XXXXXX).
# - Our own munge key and socket, so the machine's munge (if any) is not touched.
# - No systemd, no cgroups: proctrack/linuxproc, task/none, no accounting (so no sacct: job states come
#   from `squeue -t all`, kept for MinJobAge = 600 s).
# - With NoCtldInAddrAny/NoInAddrAny Slurm binds to the address the host name resolves to, not to
#   SlurmctldHost's: loopback-only binding is used only when `hostname` resolves to 127.0.0.1; otherwise
#   the daemons listen on all interfaces (a warning says so).
# - slurmd -N fixes the node name whatever the host name; RealMemory and the CPU layout are copied from
#   `slurmd -C` (more than detected drains the node).
# - batch_sched_delay=0: jobs start at the next scheduler tick (~1 s), not 3 s later.
# - Job steps outlive slurmd (slurmstepd double-forks): `stop` cancels the jobs first, then stops the
#   daemons by the PIDs it recorded (checking their command lines name DIR), then kills leftover
#   slurmstepd whose environment holds our SLURM_CONF. Never pkill or killall.
set -euo pipefail

PROG=${0##*/}
DIR=
AUTH=${SLURM_ONE_NODE_AUTH:-munge}
TIMEOUT=${SLURM_ONE_NODE_TIMEOUT:-120}
NODE=localhost
PARTITION=debug
MARKER=.one_node_cluster
export PATH="$PATH:/usr/sbin:/sbin:/usr/bin:/bin"

log() { printf '[%s] %s\n' "$PROG" "$*" >&2; }
die() { log "error: $*"; exit 1; }

while getopts "d:" opt; do
  case $opt in
    d) DIR=$OPTARG ;;
    *) exit 2 ;;
  esac
done
shift $((OPTIND - 1))
CMD=${1:-}
[ -n "$CMD" ] || { sed -n '2,14p' "$0"; exit 2; }
if [ "$CMD" != check ]; then
  [ -n "$DIR" ] || die "give the cluster folder with -d DIR"
  case $DIR in /*) ;; *) DIR="$PWD/$DIR" ;; esac
fi
CONF=$DIR/etc/slurm.conf
PIDS=$DIR/pids
SOCK=$DIR/run/munge.socket

# PID is alive and not a zombie.
alive() {
  local st
  [ -r "/proc/$1/stat" ] || return 1
  st=$(sed 's/^.*) //' "/proc/$1/stat" | cut -d' ' -f1) || return 1
  [ "$st" != Z ] && [ "$st" != X ]
}

# PID is the daemon NAME we started for DIR (guards against a recycled PID).
ours() {
  local cmd
  alive "$1" || return 1
  cmd=$(tr '\0' ' ' <"/proc/$1/cmdline" 2>/dev/null) || return 1
  case $cmd in *"$2"*"$DIR/"*) return 0 ;; esac
  return 1
}

missing_binaries() {
  local b missing=
  for b in slurmctld slurmd scontrol sinfo sbatch squeue scancel; do
    command -v "$b" >/dev/null || missing="$missing $b"
  done
  if [ "$AUTH" = munge ]; then
    for b in munged munge unmunge; do command -v "$b" >/dev/null || missing="$missing $b"; done
  fi
  echo "$missing"
}

cmd_check() {
  [ "$(id -u)" = 0 ] || { echo "not root: slurmd must run as root to start jobs"; return 1; }
  local missing; missing=$(missing_binaries)
  [ -z "$missing" ] || { echo "missing:$missing (Debian: apt-get install slurmctld slurmd slurm-client munge)"; return 1; }
}

port_free() { ! ss -Hltn "sport = :$1" 2>/dev/null | grep -q .; }

choose_ports() {
  if [ -n "${SLURM_ONE_NODE_PORTS:-}" ]; then read -r CTLD_PORT SLURMD_PORT <<<"$SLURM_ONE_NODE_PORTS"; return; fi
  local p
  for _ in $(seq 1 50); do
    p=$((20000 + (RANDOM * 32768 + RANDOM) % 40000))
    if port_free "$p" && port_free $((p + 1)); then CTLD_PORT=$p; SLURMD_PORT=$((p + 1)); return; fi
  done
  die "no free pair of ports found"
}

launch() {  # NAME COMMAND...: start in the foreground mode, in the background; $! is the daemon itself
  local name=$1; shift
  "$@" </dev/null >>"$DIR/log/$name.stdout" 2>&1 &
  echo $! >"$PIDS/$name.pid"
}

wait_for() {  # NAME WHAT COMMAND...: poll every 0.1 s until COMMAND succeeds or NAME dies
  local name=$1 what=$2 pid; shift 2
  pid=$(cat "$PIDS/$name.pid")
  for _ in $(seq 1 $((TIMEOUT * 10))); do
    "$@" >/dev/null 2>&1 && return 0
    alive "$pid" || { log "$name died; its log:"; tail -n 20 "$DIR/log/$name".* >&2 || true; return 1; }
    sleep 0.1
  done
  log "timeout waiting for $what"; tail -n 20 "$DIR/log/$name".* >&2 || true
  return 1
}

write_conf() {
  local hw cpus boards sockets cores threads mem host addr comm auth
  hw=$(slurmd -C | head -n1)
  val() { printf '%s\n' "$hw" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
  cpus=$(val CPUs); boards=$(val Boards); sockets=$(val SocketsPerBoard)
  cores=$(val CoresPerSocket); threads=$(val ThreadsPerCore); mem=$(val RealMemory)
  if [ -z "$cpus" ] || [ -z "$mem" ]; then die "cannot read 'slurmd -C': $hw"; fi
  host=$(hostname)
  addr=$(getent ahostsv4 "$host" 2>/dev/null | awk 'NR==1{print $1}') || true
  if [ "$addr" = 127.0.0.1 ]; then
    comm="CommunicationParameters=NoCtldInAddrAny,NoInAddrAny"
  else
    log "warning: host name '$host' resolves to '${addr:-nothing}', not 127.0.0.1: the daemons listen on all interfaces"
    addr=127.0.0.1; comm="# listening on all interfaces"
  fi
  if [ "$AUTH" = munge ]; then
    auth="AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$SOCK"
  else
    auth="AuthType=auth/none
CredType=cred/none"
  fi
  cat >"$CONF" <<CONF
# Written by $PROG: a one-node test cluster. Not for production.
ClusterName=ochretest
SlurmctldHost=$NODE($addr)
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
$comm
SlurmUser=root
SlurmdUser=root
$auth
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/run/slurmctld.pid
SlurmdPidFile=$DIR/run/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
JobContainerType=job_container/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0
MailProg=/bin/true
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=600
InactiveLimit=0
KillWait=10
SlurmctldTimeout=60
SlurmdTimeout=60
NodeName=$NODE NodeAddr=$addr NodeHostname=$NODE CPUs=$cpus Boards=$boards SocketsPerBoard=$sockets CoresPerSocket=$cores ThreadsPerCore=$threads RealMemory=$mem State=UNKNOWN
PartitionName=$PARTITION Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
CONF
}

cmd_start() {
  local why; why=$(cmd_check) || die "$why"
  if [ -e "$DIR" ] && [ -n "$(ls -A "$DIR" 2>/dev/null)" ]; then
    [ -e "$DIR/$MARKER" ] || die "$DIR exists, is not empty and is not a cluster folder"
    local f
    for f in "$PIDS"/*.pid; do [ -e "$f" ] && alive "$(cat "$f")" && die "$DIR has a running cluster"; done
    rm -rf "$DIR"
  fi
  mkdir -p "$DIR"/{etc,state,spool,log,run,pids}
  touch "$DIR/$MARKER"
  chmod 755 "$DIR" "$DIR/run"
  chmod 700 "$DIR/etc" "$DIR/state" "$DIR/spool"
  choose_ports
  write_conf
  export SLURM_CONF=$CONF
  if [ "$AUTH" = munge ]; then
    mkdir -m 700 "$DIR/munge"
    if command -v mungekey >/dev/null; then
      mungekey --create --keyfile="$DIR/munge/munge.key" --bits=1024
    else
      dd if=/dev/urandom of="$DIR/munge/munge.key" bs=1 count=1024 2>/dev/null
    fi
    chmod 400 "$DIR/munge/munge.key"
    launch munged munged --foreground --socket="$SOCK" --key-file="$DIR/munge/munge.key" \
      --pid-file="$DIR/run/munged.pid" --seed-file="$DIR/munge/munged.seed" --log-file="$DIR/log/munged.log"
    wait_for munged "munged" sh -c "munge -n -S '$SOCK' | unmunge -S '$SOCK'" || { stop_daemons; exit 1; }
  fi
  launch slurmctld slurmctld -D -c -f "$CONF"
  wait_for slurmctld "slurmctld" sh -c "scontrol ping | grep -q 'is UP'" || { stop_daemons; exit 1; }
  launch slurmd slurmd -D -N "$NODE" -f "$CONF"
  wait_for slurmd "node idle" sh -c "sinfo -h -n $NODE -o %T | grep -qx idle" || { stop_daemons; exit 1; }
  log "cluster up in $DIR (ports $CTLD_PORT, $SLURMD_PORT); clients: export SLURM_CONF=$CONF"
}

stop_daemons() {
  local name pid
  for name in slurmd slurmctld munged; do
    [ -f "$PIDS/$name.pid" ] || continue
    pid=$(cat "$PIDS/$name.pid")
    if ours "$pid" "$name"; then
      kill -TERM "$pid" 2>/dev/null || true
      for _ in $(seq 1 100); do alive "$pid" || break; sleep 0.1; done
      if alive "$pid"; then kill -KILL "$pid" 2>/dev/null || true; fi
    fi
    rm -f "$PIDS/$name.pid"
  done
}

cmd_stop() {
  [ -e "$DIR/$MARKER" ] || { log "no cluster in $DIR"; return 0; }
  export SLURM_CONF=$CONF
  local p
  if [ -f "$PIDS/slurmctld.pid" ] && ours "$(cat "$PIDS/slurmctld.pid")" slurmctld; then
    scancel --partition="$PARTITION" >/dev/null 2>&1 || true
    for _ in $(seq 1 100); do [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break; sleep 0.1; done
  fi
  stop_daemons
  for p in /proc/[0-9]*; do
    [ "$(cat "$p/comm" 2>/dev/null)" = slurmstepd ] || continue
    if tr '\0' '\n' 2>/dev/null <"$p/environ" | grep -qxF "SLURM_CONF=$CONF"; then
      kill -KILL "${p#/proc/}" 2>/dev/null || true
    fi
  done
  if [ "${SLURM_ONE_NODE_KEEP:-0}" = 1 ]; then log "kept $DIR"; else rm -rf "$DIR"; fi
}

cmd_wait() {
  local jobid=${1:?usage: $PROG -d DIR wait JOBID} n states
  export SLURM_CONF=$CONF
  for _ in $(seq 1 $((TIMEOUT * 10))); do
    n=$({ squeue -h -j "$jobid" -o %i 2>/dev/null || true; } | wc -l)
    [ "$n" = 0 ] && break
    sleep 0.1
  done
  [ "$n" = 0 ] || { log "job $jobid still running after ${TIMEOUT} s"; return 1; }
  states=$(squeue -h -t all -j "$jobid" -o '%i %T %r' 2>&1 | sort -V) || true
  printf '%s\n' "$states"
  [ -n "$states" ] && [ "$(printf '%s\n' "$states" | awk '$2 != "COMPLETED"' | wc -l)" = 0 ]
}

case $CMD in
  check) cmd_check ;;
  start) cmd_start ;;
  stop) cmd_stop ;;
  env) echo "export SLURM_CONF=$CONF" ;;
  wait) shift; cmd_wait "$@" ;;
  *) die "unknown command '$CMD' (check | start | env | wait JOBID | stop)" ;;
esac
