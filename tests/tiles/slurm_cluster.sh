#!/usr/bin/env bash
# Starts and stops a private single-node Slurm cluster (munged + slurmctld + slurmd) for the tests
# that submit tile jobs through sbatch. Everything (slurm.conf, munge key and socket, state, spool,
# logs, pid files) lives under DIR and the daemons run as the calling user, so nothing touches
# /etc/slurm, /etc/munge or system services. Hand-written because no Debian package provides a
# per-user throw-away cluster: slurm-wlm and munge assume /etc, /run and systemd units.
#   bash tests/tiles/slurm_cluster.sh start DIR [--accounting]   # 0 once the node is idle; 77
#                         # (reason on stderr) when Slurm cannot run here, so CTest can SKIP
#   eval "$(bash tests/tiles/slurm_cluster.sh env DIR)"   # then sbatch, squeue, scontrol, scancel
#   bash tests/tiles/slurm_cluster.sh stop DIR    # cancels jobs, stops the daemons; idempotent
# A start into a DIR used before starts clean: no old jobs, no old accounting, job ids from 1.
# Accounting: without --accounting there is no slurmdbd, so a plain `sacct` fails ("Slurm
# accounting storage is disabled"). Finished jobs are written by jobcomp/filetxt to DIR/jobcomp.txt,
# which `sacct -c` (--completion) reads, but it shows array tasks only by raw JobId (it complains
# "Unknown type ArrayJobId"); the file's lines carry ArrayJobId=/ArrayTaskId=. Tests should use
# squeue / scontrol show job (finished jobs stay MinJobAge=300 s). An array task cancelled
# while pending leaves no record at all, in either (nor in sacct with --accounting).
# --accounting also starts a private MariaDB server (data in DIR/mysql, unix socket DIR/mysql.sock,
# no TCP) and slurmdbd (DIR/slurmdbd.conf, one more free TCP port on 127.0.0.1), registers the
# cluster "tiles" and an account "tiles" (the caller's default) with sacctmgr, and gathers job
# accounting with jobacct_gather/linux, so plain `sacct -j JOB` lists jobs, array tasks (JOB_N) and
# steps as on a real cluster; jobcomp.txt is still written. It needs mariadbd (or mysqld),
# mariadb-install-db (or mysql_install_db), slurmdbd and sacctmgr: Debian's slurmdbd and
# mariadb-server (scripts/setup.sh --slurm-accounting); without them start exits 77. It adds a
# few seconds to the start (the database schema is created then) and ~30 MB under DIR.
# Limitations: the munge socket path must stay under ~100 characters (unix socket limit); as a
# non-root user slurmd can only run jobs as that same user.
set -euo pipefail
export PATH="$PATH:/usr/sbin:/sbin"  # the daemons live in sbin, often not on a user's PATH

usage() { echo "usage: $0 start DIR [--accounting] | stop DIR | env DIR" >&2; exit 2; }
acct=0
args=()
for a in "$@"; do
  case $a in
    --accounting) acct=1 ;;
    *) args+=("$a") ;;
  esac
done
[ ${#args[@]} -eq 2 ] || usage
cmd=${args[0]}
dir=${args[1]}
cluster=tiles  # ClusterName, also the accounting cluster and account
mysqld=""      # with --accounting: mariadbd or mysqld
install_db=""  # with --accounting: mariadb-install-db or mysql_install_db

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

await_socket() {  # await_socket NAME SOCKET LOG: until daemon NAME has created SOCKET (5 s)
  local pid i
  pid=$(awk -v n="$1" '$1 == n {print $2}' "$dir/pids")
  for i in $(seq 50); do
    [ -S "$2" ] && return 0
    running "$1" "$pid" || skip "$1 died at start: $(tail -n1 "$3")"
    sleep 0.1
  done
  skip "$1 did not create $2"
}

start_accounting() {  # MariaDB and slurmdbd under DIR, then the cluster and an account in it
  local user=$1 dbdport=$2
  # --no-defaults: no /etc/mysql option files; small InnoDB files (the defaults take ~110 MB).
  local my=(--no-defaults --datadir="$dir/mysql" --innodb-log-file-size=8M
            --innodb-buffer-pool-size=32M)
  [ "$(id -u)" != 0 ] || my+=(--user="$user")  # mariadbd refuses root unless told so
  # Root account without password ('normal'): reachable only through DIR/mysql.sock (DIR is 0700).
  "$install_db" "${my[@]}" --auth-root-authentication-method=normal --skip-test-db \
    --skip-name-resolve >"$dir/logs/mariadb-install-db.out" 2>&1 ||
    skip "${install_db##*/} failed: $(tail -n1 "$dir/logs/mariadb-install-db.out")"
  daemon "${mysqld##*/}" "${my[@]}" --skip-networking --socket="$dir/mysql.sock" \
    --pid-file="$dir/run/mariadbd.pid" --log-error="$dir/logs/mariadbd.log" \
    --innodb-buffer-pool-dump-at-shutdown=0 --innodb-buffer-pool-load-at-startup=0
  await_socket "${mysqld##*/}" "$dir/mysql.sock" "$dir/logs/mariadbd.log"

  # slurmdbd reads slurmdbd.conf next to $SLURM_CONF and insists on mode 0600, owned by SlurmUser.
  cat >"$dir/slurmdbd.conf" <<CONF
# Private accounting daemon written by tests/tiles/slurm_cluster.sh; do not edit.
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
DbdHost=localhost
DbdAddr=127.0.0.1
DbdPort=$dbdport
SlurmUser=$user
PidFile=$dir/run/slurmdbd.pid
LogFile=$dir/logs/slurmdbd.log
# MariaDB through its unix socket: the mysql plugin has no socket setting, so slurmdbd gets
# MYSQL_UNIX_PORT=$dir/mysql.sock in its environment (the client library's default socket).
StorageType=accounting_storage/mysql
StorageHost=localhost
StorageUser=root
StorageLoc=slurm_acct_db
CONF
  chmod 600 "$dir/slurmdbd.conf"
  MYSQL_UNIX_PORT="$dir/mysql.sock" daemon slurmdbd -D

  # Up once sacctmgr gets an answer (slurmdbd creates the database schema first).
  local name pid log end=$((SECONDS + 60))
  until SLURM_CONF="$dir/slurm.conf" timeout 10 sacctmgr -i -n list cluster >/dev/null 2>&1; do
    while read -r name pid; do
      log=$dir/logs/$name.out
      [ -s "$log" ] || log=$dir/logs/$name.log  # mariadbd writes to its --log-error only
      running "$name" "$pid" || skip "$name died at start: $(tail -n1 "$log")"
    done <"$dir/pids"
    ((SECONDS < end)) || skip "slurmdbd not answering after 60 s; see $dir/logs/slurmdbd.log"
    sleep 0.5
  done
  # Cluster before slurmctld registers; the caller's jobs charged to account $cluster.
  local add
  for add in "cluster $cluster" \
      "account $cluster Cluster=$cluster Description=tests Organization=tests" \
      "user $user Cluster=$cluster Account=$cluster DefaultAccount=$cluster"; do
    # shellcheck disable=SC2086  # $add is split into sacctmgr's words on purpose
    SLURM_CONF="$dir/slurm.conf" timeout 20 sacctmgr -i add $add >>"$dir/logs/sacctmgr.out" 2>&1 ||
      skip "sacctmgr add ${add%% *} failed: $(tail -n1 "$dir/logs/sacctmgr.out")"
  done
}

start_cluster() {
  local b
  for b in munged slurmctld slurmd sbatch sinfo squeue scancel setsid; do
    command -v "$b" >/dev/null ||
      skip "$b not found (install slurm-wlm and munge: scripts/setup.sh --slurm)"
  done
  if [ "$acct" = 1 ]; then  # MariaDB's programs under either name
    mysqld=$(command -v mariadbd || command -v mysqld || echo mariadbd)
    install_db=$(command -v mariadb-install-db || command -v mysql_install_db ||
                 echo mariadb-install-db)
    for b in "$mysqld" "$install_db" slurmdbd sacctmgr; do
      command -v "$b" >/dev/null || skip "${b##*/} not found (--accounting: install slurmdbd" \
        "mariadb-server: scripts/setup.sh --slurm-accounting)"
    done
  fi
  stop_cluster  # a restart into the same DIR starts clean: no old jobs, ids from 1
  rm -rf "$dir"/{state,spool,run,mysql}
  mkdir -p "$dir"/{state,spool,logs,run}
  chmod 700 "$dir"
  rm -f "$dir"/{munge.key,munge.seed,munge.socket,munge.socket.lock,jobcomp.txt,mysql.sock}

  # Private munge key: clients and daemons talk to our munged only, via AuthInfo=socket=.
  if command -v mungekey >/dev/null; then
    mungekey --create --keyfile="$dir/munge.key" || skip "mungekey failed"
  else
    dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
  fi
  chmod 400 "$dir/munge.key"

  local host user cpus port i gather storage
  host=$(hostname -s)
  user=$(id -un)
  cpus=$(nproc); ((cpus >= 2)) || cpus=2  # config_overrides lets slurmd advertise 2 on 1 core
  # Non-default ports so that a system Slurm or a parallel test cluster does not clash; with
  # --accounting port + 2 is slurmdbd's.
  for i in $(seq 50); do
    port=$((20000 + RANDOM % 20000))
    port_free "$port" && port_free $((port + 1)) &&
      { [ "$acct" = 0 ] || port_free $((port + 2)); } && break
    ((i < 50)) || skip "no free TCP port pair found"
  done
  if [ "$acct" = 0 ]; then
    gather="JobAcctGatherType=jobacct_gather/none"
    storage="# No slurmdbd: finished jobs go to a text file that 'sacct -c' reads.
AccountingStorageType=accounting_storage/none"
  else
    gather="JobAcctGatherType=jobacct_gather/linux"
    storage="# slurmdbd (--accounting) for sacct; finished jobs also go to a text file ('sacct -c').
AccountingStorageType=accounting_storage/slurmdbd
AccountingStorageHost=127.0.0.1
AccountingStoragePort=$((port + 2))
# Talking to slurmdbd, the munge socket is this one, not AuthInfo's.
AccountingStoragePass=$dir/munge.socket"
  fi

  echo "# empty: keeps SPANK plugins from /etc/slurm/plugstack.conf out" >"$dir/plugstack.conf"
  cat >"$dir/slurm.conf" <<CONF
# Private test cluster written by tests/tiles/slurm_cluster.sh; do not edit.
ClusterName=$cluster
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
$gather
$storage
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
  await_socket munged "$dir/munge.socket" "$dir/logs/munged.out"
  [ "$acct" = 0 ] || start_accounting "$user" $((port + 2))

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
