#!/usr/bin/env bash
# Starts and stops a real one-node Slurm cluster on this machine (Debian's Slurm 22.05 packages), for a
# test to submit jobs and job arrays through:
#   scripts/slurm-cluster.sh install|start|stop|status|--help
# install  installs Debian's slurmctld, slurmd, slurm-client and munge if missing (as root, by apt-get),
#          quietly; elsewhere it says what is missing.
# start    writes /etc/slurm/slurm.conf and cgroup.conf (one node, localhost, with nproc CPUs as cores;
#          one partition, robosim, the default), starts munged, slurmctld and slurmd and waits (up to
#          ROBOSIM_SLURM_START_TIMEOUT seconds, default 60) until the node is idle. Each start is a fresh
#          cluster: the jobs of an earlier one are forgotten (slurmctld -c). When it is running and healthy
#          already it says so and changes nothing; a cluster that was killed (stale pid files, a node left
#          down) starts afresh. Needs root. On a failure: one line naming what failed, the tail of that
#          daemon's log, exit 1.
# stop     stops the daemons start started (by their pid files), after cancelling any job left; exit 0 even
#          when nothing was running.
# status   one line per daemon (running or not) and what sinfo says; exit 3 when a daemon is not running.
# Every state, spool, log and pid file, and munged's socket, is under one directory: ROBOSIM_SLURM_DIR
# (default /tmp/robosim-slurm). Ports: ROBOSIM_SLURMCTLD_PORT (default 6817), ROBOSIM_SLURMD_PORT (6818).
# One such cluster per machine (the clients read /etc/slurm/slurm.conf). Jobs may be submitted as root.
# No accounting (sacct is off): a finished job stays in `squeue -t all` and `scontrol show job` for
# MinJobAge (300 s). A job starts about 1 s after its submission (the first after a start: about 3 s
# after slurmctld's). `sbatch --wait` polls slowly: poll squeue instead; a dependency on an array with a
# failed task should be afterany (afterok would wait forever). Every line printed starts with
# `slurm-cluster: `.
set -euo pipefail
export PATH=$PATH:/usr/sbin:/sbin # (the daemons' directory, not on every user's path)
me=slurm-cluster
dir=${ROBOSIM_SLURM_DIR:-/tmp/robosim-slurm}
ctld_port=${ROBOSIM_SLURMCTLD_PORT:-6817}
slurmd_port=${ROBOSIM_SLURMD_PORT:-6818}
timeout=${ROBOSIM_SLURM_START_TIMEOUT:-60}
conf_dir=/etc/slurm
conf=$conf_dir/slurm.conf
marker="# written by RoboSim's scripts/slurm-cluster.sh for the cluster in"
munge_key=/etc/munge/munge.key
daemons=(munged slurmctld slurmd)
packages=(slurmctld slurmd slurm-client munge)

say() {
  local line
  for line in "$@"; do echo "$me: $line"; done
}
# Bad input or a missing prerequisite: one line, exit 2.
fail_usage() {
  echo "$me: $*" >&2
  exit 2
}
# Daemon $1 (or a step) failed: one line, the last lines of log $3 (when given), then (in a start) the
# daemons started are stopped again; exit 1.
starting=0
fail() {
  local log=${3:-}
  echo "$me: $2" >&2
  if [ -n "$log" ] && [ -s "$log" ]; then
    echo "$me: the last lines of $log:" >&2
    tail -n 15 "$log" | sed "s/^/$me:   /" >&2
  fi
  if [ "$starting" = 1 ]; then
    starting=0
    do_stop >&2
  fi
  exit 1
}
usage() {
  sed -nE "2,/^[^#]/s/^# ?/$me: /p" "$0"
}
# Output of a command, prefixed line by line.
prefixed() {
  sed "s/^/$me:   /"
}

for v in "$ctld_port" "$slurmd_port" "$timeout"; do
  [[ "$v" =~ ^[1-9][0-9]*$ ]] || fail_usage "ports and ROBOSIM_SLURM_START_TIMEOUT must be whole numbers >= 1, got '$v'"
done
case $dir in /*) ;; *) fail_usage "ROBOSIM_SLURM_DIR must be an absolute path, got '$dir'" ;; esac

# The commands each package brings.
package_of() {
  case $1 in
    slurmctld) echo slurmctld ;; slurmd) echo slurmd ;; sbatch|squeue|sinfo|scontrol|scancel) echo slurm-client ;;
    munged|mungekey) echo munge ;;
  esac
}
# The packages of which a command is missing, one a line.
missing_packages() {
  local c
  for c in slurmctld slurmd sbatch squeue sinfo scontrol scancel munged; do
    command -v "$c" >/dev/null || package_of "$c"
  done | sort -u
}

do_install() {
  local missing out
  missing=$(missing_packages | tr '\n' ' ')
  missing=${missing% }
  if [ -z "$missing" ]; then
    say "installed already (${packages[*]}): $(slurmctld -V 2>/dev/null || echo 'slurm')"
    return 0
  fi
  if [ "$(id -u)" != 0 ] || ! command -v apt-get >/dev/null; then
    fail_usage "missing packages: $missing (install them as root: apt-get install --no-install-recommends ${packages[*]})"
  fi
  say "installing Debian's ${packages[*]} (missing: $missing) ..."
  if ! out=$(apt-get update -qq 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
      --no-install-recommends "${packages[@]}" 2>&1); then
    echo "$me: apt-get could not install ${packages[*]}; its last lines:" >&2
    tail -n 15 <<<"$out" | prefixed >&2
    exit 1
  fi
  missing=$(missing_packages | tr '\n' ' ')
  [ -z "$missing" ] || fail apt-get "installed, yet still missing: $missing"
  say "installed: $(slurmctld -V)"
}

# Daemon $1's pid file and log (munged's are in the munge user's directory).
pid_file() {
  case $1 in munged) echo "$dir/munge/munged.pid" ;; *) echo "$dir/run/$1.pid" ;; esac
}
log_of() {
  case $1 in munged) echo "$dir/munge/munged.log" ;; *) echo "$dir/log/$1.log" ;; esac
}

# Whether process $1 is there and no zombie (one killed waits as a zombie until its parent, often pid 1,
# reaps it).
alive() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  stat=${stat##*) }
  [ "${stat%% *}" != Z ] && [ "${stat%% *}" != X ]
}
# The pid in daemon $1's pid file, when that process is alive and is that daemon; else nothing.
live_pid() {
  local f pid comm
  f=$(pid_file "$1")
  [ -f "$f" ] || return 0
  pid=$(tr -dc 0-9 <"$f" 2>/dev/null || true)
  [ -n "$pid" ] || return 0
  comm=$(cat "/proc/$pid/comm" 2>/dev/null || true)
  [ "$comm" = "$1" ] && alive "$pid" && echo "$pid"
  return 0
}

# The node's state as sinfo says it (idle, mixed, down*, drained, ...), or nothing when slurmctld
# does not answer.
node_state() {
  timeout 10 sinfo -h -n localhost -o %T 2>/dev/null | head -n 1 || true
}
ctld_up() {
  timeout 10 scontrol ping 2>/dev/null | grep -q 'is UP'
}
# Healthy: the three daemons alive, slurmctld answering and the node usable.
healthy() {
  local d
  for d in "${daemons[@]}"; do
    [ -n "$(live_pid "$d")" ] || return 1
  done
  [ "$(conf_dir_of_running)" = "$dir" ] || return 1
  ctld_up || return 1
  case $(node_state) in idle|mixed|allocated|completing) return 0 ;; *) return 1 ;; esac
}
# The state directory the slurm.conf in /etc/slurm was written for (by this script), or nothing.
conf_dir_of_running() {
  [ -f "$conf" ] && sed -n "s|^$marker ||p" "$conf" | head -n 1
  return 0
}

# Stops daemon $1 by its pid file: SIGTERM, up to 15 s, then SIGKILL.
stop_daemon() {
  local d=$1 pid i
  pid=$(live_pid "$d")
  if [ -z "$pid" ]; then
    rm -f "$(pid_file "$d")"
    return 0
  fi
  kill "$pid" 2>/dev/null || true
  for ((i = 0; i < 150; i++)); do
    alive "$pid" || break
    sleep 0.1
  done
  if alive "$pid"; then
    say "$d (pid $pid) did not stop in 15 s: killing it"
    kill -9 "$pid" 2>/dev/null || true
    for ((i = 0; i < 50; i++)); do
      alive "$pid" || break
      sleep 0.1
    done
  fi
  rm -f "$(pid_file "$d")"
  say "stopped $d (pid $pid)"
}

do_stop() {
  local jobs any=0 d i
  for d in "${daemons[@]}"; do
    [ -n "$(live_pid "$d")" ] && any=1
  done
  if [ "$any" = 0 ]; then
    rm -f "$dir"/run/*.pid "$dir/munge/munged.pid" 2>/dev/null || true
    say "not running (nothing to stop in $dir)"
    return 0
  fi
  [ "$(id -u)" = 0 ] || fail_usage "stop needs root (the daemons run as root and munge)"
  # jobs left would go on running under their slurmstepd once slurmd is gone
  if [ -n "$(live_pid slurmctld)" ] && [ "$(conf_dir_of_running)" = "$dir" ] && ctld_up; then
    jobs=$(timeout 10 squeue -h -t pending,running,suspended,completing -o %A 2>/dev/null | sort -u | tr '\n' ' ' || true)
    if [ -n "${jobs// /}" ]; then
      say "cancelling the jobs left: $jobs"
      # shellcheck disable=SC2086
      timeout 10 scancel $jobs 2>/dev/null || true
      for ((i = 0; i < 50; i++)); do
        [ -z "$(timeout 10 squeue -h -t running,completing -o %A 2>/dev/null || true)" ] && break
        sleep 0.2
      done
    fi
  fi
  stop_daemon slurmd
  stop_daemon slurmctld
  stop_daemon munged
}

do_status() {
  local d pid rc=0
  for d in "${daemons[@]}"; do
    pid=$(live_pid "$d")
    if [ -n "$pid" ]; then say "$d running (pid $pid)"; else say "$d not running"; rc=3; fi
  done
  if [ -n "$(live_pid slurmctld)" ] && [ "$(conf_dir_of_running)" = "$dir" ]; then
    timeout 10 sinfo 2>&1 | prefixed || say "sinfo failed"
  else
    say "sinfo: (slurmctld of $dir not running)"
  fi
  return "$rc"
}

write_conf() {
  local cpus mem_kb mem
  cpus=$(nproc)
  mem_kb=$(sed -n 's/^MemTotal: *\([0-9]*\) kB/\1/p' /proc/meminfo)
  mem=$((mem_kb / 1024 / 2))
  [ "$mem" -le 2048 ] || mem=2048
  [ "$mem" -ge 100 ] || mem=100
  if [ -f "$conf" ] && ! grep -q "^$marker " "$conf"; then
    [ -e "$conf.before-robosim" ] || cp -p "$conf" "$conf.before-robosim"
    say "$conf was not ours: kept as $conf.before-robosim"
  fi
  if [ -f "$conf_dir/cgroup.conf" ] && ! grep -q "^$marker " "$conf_dir/cgroup.conf"; then
    [ -e "$conf_dir/cgroup.conf.before-robosim" ] || cp -p "$conf_dir/cgroup.conf" "$conf_dir/cgroup.conf.before-robosim"
    say "$conf_dir/cgroup.conf was not ours: kept as $conf_dir/cgroup.conf.before-robosim"
  fi
  mkdir -p "$conf_dir"
  cat >"$conf.tmp" <<EOF
$marker $dir
# A one-node test cluster: root runs every daemon; every file of state is under $dir.
ClusterName=robosim
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
# slurmd listens on localhost only (slurmctld 22.05 still on every address; munge signs every message)
CommunicationParameters=NoInAddrAny
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/slurmctld
SlurmdSpoolDir=$dir/slurmd
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
# a job submitted starts within about a second (the default lets slurmctld wait up to 3 s more)
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
# the node's CPUs as configured here (each a core), not as slurmd finds the hardware
SlurmdParameters=config_overrides
ReturnToService=2
MinJobAge=300
NodeName=localhost CPUs=$cpus Sockets=1 CoresPerSocket=$cpus ThreadsPerCore=1 RealMemory=$mem State=UNKNOWN
PartitionName=robosim Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
  mv -f "$conf.tmp" "$conf"
  cat >"$conf_dir/cgroup.conf.tmp" <<EOF
$marker $dir
# slurmd 22.05 starts no further on a hybrid cgroup hierarchy without it; nothing is constrained
CgroupPlugin=cgroup/v1
EOF
  mv -f "$conf_dir/cgroup.conf.tmp" "$conf_dir/cgroup.conf"
  say "wrote $conf ($cpus CPUs, ${mem} MB, partition robosim, ports $ctld_port and $slurmd_port) and cgroup.conf"
}

# Runs daemon $1 (the command after it) and waits for its pid file; a daemon that exits or writes no pid
# file in time fails the start.
start_daemon() {
  local d=$1 i pid out="$dir/log/$1.start"
  shift
  rm -f "$(pid_file "$d")"
  if ! "$@" </dev/null >"$out" 2>&1; then
    [ -s "$out" ] || out=$(log_of "$d")
    fail "$d" "$d did not start (exit status of '$*' not 0)" "$out"
  fi
  for ((i = 0; i < 100; i++)); do
    pid=$(live_pid "$d")
    [ -n "$pid" ] && break
    sleep 0.1
  done
  [ -n "$pid" ] || fail "$d" "$d wrote no pid file ($(pid_file "$d")) within 10 s of its start, or exited" "$(log_of "$d")"
  say "started $d (pid $pid)"
}

# Which daemon to blame for a start that got stuck, and its log.
blame() {
  local d
  for d in "${daemons[@]}"; do
    [ -n "$(live_pid "$d")" ] || { echo "$d"; return; }
  done
  echo slurmd
}

do_start() {
  local missing other d state t0 resumed=0 polls=0 deadline munge_user
  missing=$(missing_packages | tr '\n' ' ')
  [ -z "${missing// /}" ] || fail_usage "missing packages: $missing (run: $0 install, as root)"
  [ "$(id -u)" = 0 ] || fail_usage "start needs root (slurmd runs jobs as their users; the daemons run as root)"
  other=$(conf_dir_of_running)
  if [ -n "$other" ] && [ "$other" != "$dir" ] \
      && [ -n "$(live_pid_in "$other" slurmctld)$(live_pid_in "$other" slurmd)" ]; then
    fail_usage "a cluster of $other is running on this machine: stop it first (ROBOSIM_SLURM_DIR=$other $0 stop)"
  fi
  if healthy; then
    say "running already and healthy ($dir; node $(node_state)): nothing to do"
    return 0
  fi
  t0=$(date +%s)
  local up=() down=()
  for d in "${daemons[@]}"; do
    if [ -n "$(live_pid "$d")" ]; then up+=("$d"); else down+=("$d"); fi
  done
  if [ ${#up[@]} -gt 0 ]; then
    if [ ${#down[@]} -gt 0 ]; then
      say "running but not healthy (${down[*]} not running): stopping it to start afresh"
    else
      state=$(node_state)
      say "running but not healthy (node: ${state:-no answer from slurmctld}): stopping it to start afresh"
    fi
    do_stop
  fi
  starting=1
  # root writes, chowns and kills by pid files there: a directory someone else made first (or a link) is refused
  if [ -L "$dir" ] || { [ -e "$dir" ] && [ "$(stat -c %u "$dir")" != 0 ]; }; then
    fail_usage "$dir is a link or not root's: remove it or set ROBOSIM_SLURM_DIR to a directory of root's"
  fi
  mkdir -p "$dir"
  chmod 755 "$dir"
  for d in run log slurmctld slurmd munge; do
    [ ! -L "$dir/$d" ] || fail_usage "$dir/$d is a link: remove it"
  done
  mkdir -p "$dir"/{run,log,slurmctld,slurmd,munge}
  chmod 755 "$dir" "$dir/run" "$dir/log"
  chmod 700 "$dir/slurmctld" "$dir/slurmd"
  rm -f "$dir"/run/*.pid "$dir/munge/munged.pid"

  # munged: as the munge user when there is one (its key is theirs), its socket, pid, log and seed under $dir
  munge_user=root
  id munge >/dev/null 2>&1 && munge_user=munge
  if [ ! -s "$munge_key" ]; then
    mkdir -p "${munge_key%/*}"
    if command -v mungekey >/dev/null; then
      mungekey --create --keyfile="$munge_key" >/dev/null 2>&1 || fail munged "mungekey could not create $munge_key"
    else
      (umask 077 && dd if=/dev/urandom of="$munge_key" bs=1024 count=1 2>/dev/null) || fail munged "could not create $munge_key"
    fi
    chown "$munge_user:" "$munge_key" && chmod 400 "$munge_key"
    say "created the munge key $munge_key"
  fi
  chown "$munge_user:" "$dir/munge" && chmod 755 "$dir/munge"
  rm -f "$dir/munge/munge.socket" "$dir/munge/munge.socket.lock"
  start_daemon munged setpriv --reuid="$munge_user" --regid="$munge_user" --init-groups \
    munged --key-file="$munge_key" --socket="$dir/munge/munge.socket" --pid-file="$dir/munge/munged.pid" \
    --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed"

  write_conf
  start_daemon slurmctld slurmctld -c
  deadline=$((t0 + timeout))
  until ctld_up; do
    [ -n "$(live_pid slurmctld)" ] || fail slurmctld "slurmctld exited during its start" "$dir/log/slurmctld.log"
    [ "$(date +%s)" -lt "$deadline" ] || fail slurmctld "slurmctld did not answer scontrol ping within $timeout s" "$dir/log/slurmctld.log"
    sleep 0.2
  done
  start_daemon slurmd slurmd -c
  while :; do
    for d in "${daemons[@]}"; do
      [ -n "$(live_pid "$d")" ] || fail "$d" "$d exited during the start" "$(log_of "$d")"
    done
    state=$(node_state)
    polls=$((polls + 1))
    case $state in
      idle) break ;;
      down*|drain*|fail*)
        # (a node left down or drained, once slurmd had 2 s to register: ReturnToService=2 and slurmctld -c
        # usually spare us this)
        if [ "$resumed" = 0 ] && [ "$polls" -ge 10 ]; then
          say "node localhost is $state: resuming it"
          scontrol update nodename=localhost state=resume >/dev/null 2>&1 || true
          resumed=1
        fi ;;
    esac
    if [ "$(date +%s)" -ge "$deadline" ]; then
      d=$(blame)
      fail "$d" "the node did not become idle within $timeout s (sinfo says '${state:-nothing}'; $(scontrol show node localhost 2>/dev/null | sed -n 's/^ *Reason=/reason: /p' | head -n 1))" "$(log_of "$d")"
    fi
    sleep 0.2
  done
  starting=0
  say "running: node localhost idle in partition robosim after $(($(date +%s) - t0)) s (state and logs in $dir)"
}

# live_pid for state directory $1.
live_pid_in() {
  local saved=$dir
  dir=$1
  live_pid "$2"
  dir=$saved
}

[ $# -le 1 ] || [ "$1" = -h ] || [ "$1" = --help ] || fail_usage "takes one command, got: $* (see --help)"
case ${1:-} in
  -h|--help|help) usage ;;
  install) do_install ;;
  start) do_start ;;
  stop) do_stop ;;
  status) do_status ;;
  '') fail_usage "needs a command: install, start, stop or status (see --help)" ;;
  *) fail_usage "unknown command '$1': install, start, stop or status (see --help)" ;;
esac
