#!/usr/bin/env bash
# Starts and stops a private single-node Slurm cluster (munged + slurmctld + slurmd) for the tests
# that submit tile jobs through sbatch. Everything (slurm.conf, munge key and socket, state, spool,
# logs, pid files) lives under DIR and the daemons run as the calling user, so nothing touches
# /etc/slurm, /etc/munge or system services. Hand-written because no Debian package provides a
# per-user throw-away cluster: slurm-wlm and munge assume /etc, /run and systemd units.
#   bash tests/tiles/slurm_cluster.sh start DIR   # 0 once the node is idle; 77 (reason on stderr)
#                                                 # when Slurm cannot run here, so CTest can SKIP
#   eval "$(bash tests/tiles/slurm_cluster.sh env DIR)"   # then sbatch, squeue, scontrol, scancel
#   bash tests/tiles/slurm_cluster.sh stop DIR    # cancels jobs, stops the daemons; idempotent
# Accounting: there is no slurmdbd, so a plain `sacct` fails ("Slurm accounting storage is
# disabled"). Finished jobs are written by jobcomp/filetxt to DIR/jobcomp.txt, which
# `sacct -c` (--completion) reads, but it shows array tasks only by raw JobId (it complains
# "Unknown type ArrayJobId"); the file's lines carry ArrayJobId=/ArrayTaskId=. Tests should use
# squeue / scontrol show job (finished jobs stay MinJobAge=300 s). An array task cancelled
# while pending leaves no record at all, in either.
# Limitations: the munge socket path must stay under ~100 characters (unix socket limit); as a
# non-root user slurmd can only run jobs as that same user.
set -euo pipefail
export PATH="$PATH:/usr/sbin:/sbin"  # the daemons live in sbin, often not on a user's PATH

usage() { echo "usage: $0 start|stop|env DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
cmd=$1
dir=$2

stop_cluster() {
  [ -f "$dir/pids" ] || return 0
  # Cancel jobs first: slurmstepd and the job processes outlive a stopped slurmd.
  if [ -f "$dir/slurm.conf" ] && command -v scancel >/dev/null; then
    SLURM_CONF="$dir/slurm.conf" timeout 10 scancel -u "$(id -un)" 2>/dev/null || true
    local left
    for _ in $(seq 20); do  # up to 10 s for pending/running/completing jobs to go
      left=$(SLURM_CONF="$dir/slurm.conf" timeout 5 squeue -h -o %i 2>/dev/null) || break
      [ -n "$left" ] || break
      sleep 0.5
    done
  fi
  # Reverse start order; only signal a pid that still runs the program it was recorded for.
  local name pid alive
  while read -r name pid; do
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$name" ] || continue
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 100); do
      [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$name" ] || break
      sleep 0.1
    done
    alive=$(cat "/proc/$pid/comm" 2>/dev/null || true)
    [ "$alive" != "$name" ] || kill -KILL "$pid" 2>/dev/null || true
  done < <(tac "$dir/pids")
  # Leftovers when slurmd could not clean up: step daemons and job processes carry our SLURM_CONF,
  # jobs also SLURM_JOB_ID (which tells them from the caller's shell that eval'ed `env`).
  local e
  for e in /proc/[0-9]*/environ; do
    pid=${e#/proc/}; pid=${pid%/environ}
    [ "$pid" != $$ ] || continue
    grep -qzxF "SLURM_CONF=$dir/slurm.conf" "$e" 2>/dev/null || continue
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = slurmstepd ] || grep -qz '^SLURM_JOB_ID=' "$e" ||
      continue
    kill -KILL "$pid" 2>/dev/null || true
  done
  rm -f "$dir/pids" "$dir"/run/*.pid
}

skip() {  # Slurm cannot run here: undo the partial start, tell CTest to skip
  echo "slurm_cluster: $*" >&2
  stop_cluster
  exit 77
}

port_free() {  # nothing listening on TCP port $1 (IPv4 or IPv6)
  ! { cat /proc/net/tcp /proc/net/tcp6 2>/dev/null || true; } |
    awk -v p="$(printf '%04X' "$1")" '$4 == "0A" && substr($2, length($2) - 3) == p {f = 1}
                                      END {exit !f}'
}

daemon() {  # daemon NAME ARGS...: runs NAME in the foreground of its own session, records its pid
  local name=$1; shift
  SLURM_CONF="$dir/slurm.conf" setsid "$name" "$@" </dev/null >>"$dir/logs/$name.out" 2>&1 &
  local pid=$!
  for _ in $(seq 40); do  # until the fork has exec'ed NAME, which running() and stop look for
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$name" ] && break
    sleep 0.05
  done
  echo "$name $pid" >>"$dir/pids"
}

running() { [ "$(cat "/proc/$2/comm" 2>/dev/null)" = "$1" ]; }

start_cluster() {
  local b
  for b in munged slurmctld slurmd sbatch sinfo squeue scancel setsid; do
    command -v "$b" >/dev/null ||
      skip "$b not found (install slurm-wlm and munge: scripts/setup.sh --slurm)"
  done
  stop_cluster  # a restart into the same DIR starts clean: no old jobs, ids from 1
  rm -rf "$dir"/{state,spool,run}
  mkdir -p "$dir"/{state,spool,logs,run}
  chmod 700 "$dir"
  rm -f "$dir"/{munge.key,munge.seed,munge.socket,munge.socket.lock,jobcomp.txt}

  # Private munge key: clients and daemons talk to our munged only, via AuthInfo=socket=.
  if command -v mungekey >/dev/null; then
    mungekey --create --keyfile="$dir/munge.key" || skip "mungekey failed"
  else
    dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
  fi
  chmod 400 "$dir/munge.key"

  local host user cpus port i
  host=$(hostname -s)
  user=$(id -un)
  cpus=$(nproc); ((cpus >= 2)) || cpus=2  # config_overrides lets slurmd advertise 2 on 1 core
  # Non-default ports so that a system Slurm or a parallel test cluster does not clash.
  for i in $(seq 50); do
    port=$((20000 + RANDOM % 20000))
    port_free "$port" && port_free $((port + 1)) && break
    ((i < 50)) || skip "no free TCP port pair found"
  done

  echo "# empty: keeps SPANK plugins from /etc/slurm/plugstack.conf out" >"$dir/plugstack.conf"
  cat >"$dir/slurm.conf" <<CONF
# Private test cluster written by tests/tiles/slurm_cluster.sh; do not edit.
ClusterName=tiles
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/logs/slurmctld.log
SlurmdLogFile=$dir/logs/slurmd.log
PlugStackConfig=$dir/plugstack.conf
MailProg=/bin/true
# No cgroups: CI containers have no systemd / cgroup delegation.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
# No slurmdbd: finished jobs go to a text file that 'sacct -c' reads.
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.txt
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
SlurmdParameters=config_overrides
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF

  # --force: munged otherwise refuses a socket in a directory others cannot enter (DIR is 0700).
  daemon munged --foreground --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
    --pid-file="$dir/run/munged.pid" --log-file="$dir/logs/munged.log" --seed-file="$dir/munge.seed"
  local mpid; mpid=$(awk '$1 == "munged" {print $2}' "$dir/pids")
  for i in $(seq 50); do
    [ -S "$dir/munge.socket" ] && break
    running munged "$mpid" || skip "munged died at start: $(tail -n1 "$dir/logs/munged.out")"
    sleep 0.1
  done
  [ -S "$dir/munge.socket" ] || skip "munged did not create $dir/munge.socket"

  daemon slurmctld -D -f "$dir/slurm.conf"
  daemon slurmd -D -f "$dir/slurm.conf" -N "$host"

  # Usable once the node reports idle; a daemon that exits on the way means Slurm cannot run here.
  local name pid state=""
  for i in $(seq 120); do
    state=$(SLURM_CONF="$dir/slurm.conf" timeout 5 sinfo -h -N -n "$host" -o %T 2>/dev/null || true)
    [ "$state" = idle ] && return 0
    while read -r name pid; do
      running "$name" "$pid" ||
        skip "$name died at start: $(tail -n1 "$dir/logs/$name.out")"
    done <"$dir/pids"
    sleep 0.5
  done
  skip "node $host not idle after 60 s (state '${state:-unknown}'); see $dir/logs"
}

case $cmd in
  start) mkdir -p "$dir"; dir=$(cd "$dir" && pwd); start_cluster ;;
  stop) [ -d "$dir" ] || exit 0; dir=$(cd "$dir" && pwd); stop_cluster ;;
  env) dir=$(cd "$dir" && pwd); printf 'export SLURM_CONF=%q\n' "$dir/slurm.conf" ;;
  *) usage ;;
esac
