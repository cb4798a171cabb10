#!/usr/bin/env bash
# A throw-away one-node Slurm cluster for tests: own munged, own ports, all
# state under DIR.  Nothing is written to /etc, /var or /run.
#
#   slurm.sh start DIR   start munged, slurmctld, slurmd; wait for the node;
#                        print the exports a caller needs (eval "$(...)")
#   slurm.sh env DIR     print those exports again
#   slurm.sh stop DIR    cancel jobs, stop the three daemons (idempotent)
set -euo pipefail

usage() { echo "usage: $0 start|stop|env DIR" >&2; exit 2; }
[[ $# -eq 2 ]] || usage
action=$1 DIR=$2
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
NODE=lwnode
# Daemons live in sbin, which a non-login PATH may lack.
export PATH="$PATH:/usr/sbin:/sbin"

die() { echo "slurm.sh: $*" >&2; exit 1; }

print_env() { echo "export SLURM_CONF=$DIR/slurm.conf"; }

# Live pid from a pid file, only if that process belongs to this DIR (its
# command line names our socket/config), so we never signal anything else.
our_pid() {
  local pid
  pid=$(cat "$1" 2>/dev/null) || return 1
  [[ $pid =~ ^[0-9]+$ ]] || return 1
  tr '\0' ' ' 2>/dev/null <"/proc/$pid/cmdline" | grep -qF "$DIR/" || return 1
  echo "$pid"
}

# SIGTERM all at once (in turn, each takes ~2 s to exit), wait up to 10 s,
# then SIGKILL whatever is left.
stop_pids() {
  local i p alive
  [[ $# -gt 0 ]] || return 0
  kill -TERM "$@" 2>/dev/null || true
  for ((i = 0; i < 100; i++)); do
    alive=()
    for p; do kill -0 "$p" 2>/dev/null && alive+=("$p"); done
    [[ ${#alive[@]} -eq 0 ]] && return 0
    sleep 0.1
  done
  kill -KILL "${alive[@]}" 2>/dev/null || true
}

# slurmstepd processes of this cluster: they inherit slurmd's SLURM_CONF.
our_steps() {
  local p
  for p in $(pgrep -x slurmstepd || true); do
    tr '\0' '\n' 2>/dev/null <"/proc/$p/environ" | grep -qxF "SLURM_CONF=$DIR/slurm.conf" && echo "$p"
  done
  return 0
}

do_stop() {
  local pid p i
  # Cancel jobs first so slurmstepd/job processes do not outlive slurmd, and
  # wait until they are done (up to 5 s): stopping slurmctld while a job is
  # still completing makes it wait for its hung RPCs to slurmd.
  if pid=$(our_pid "$DIR/run/slurmctld.pid"); then
    export SLURM_CONF=$DIR/slurm.conf
    timeout 5 scancel --quiet --user="$(id -un)" 2>/dev/null || true
    for ((i = 0; i < 50; i++)); do
      [[ -z $(our_steps) && -z $(timeout 2 squeue -h -t R,CG,S,CF -o %i 2>/dev/null) ]] && break
      sleep 0.1
    done
  fi
  for p in $(our_steps); do kill -KILL "$p" 2>/dev/null || true; done
  local pids=()
  for p in slurmctld slurmd munged; do
    if pid=$(our_pid "$DIR/run/$p.pid"); then pids+=("$pid"); fi
  done
  stop_pids "${pids[@]}"
  rm -f "$DIR"/run/{slurmctld,slurmd,munged}.pid
}

fail() {
  echo "slurm.sh: $*" >&2
  local f
  for f in "$DIR"/log/*.log; do
    [[ -f $f ]] && { echo "---- tail $f" >&2; tail -n 20 "$f" >&2; }
  done
  do_stop
  exit 1
}

# A port nothing listens on (bash /dev/tcp connect fails).
free_port() {
  local p
  while :; do
    p=$((20000 + RANDOM % 40000))
    (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return; }
  done
}

do_start() {
  local b missing="" pid ctld_port slurmd_port i state
  for b in munged slurmctld slurmd sbatch sinfo scancel; do
    command -v "$b" >/dev/null || missing+=" $b"
  done
  [[ -z $missing ]] || die "missing:$missing (apt-get install slurm-wlm munge)"
  for b in munged slurmctld slurmd; do
    if pid=$(our_pid "$DIR/run/$b.pid"); then die "$b already running for $DIR (pid $pid); stop it first"; fi
  done

  # Unix socket paths are limited to 108 bytes; slurm.conf takes no quoting.
  ((${#DIR} < 90)) || die "DIR path too long for a socket: $DIR"
  [[ $DIR != *[[:space:]\|\&\#,=]* ]] || die "DIR must not contain blanks or |&#,=: $DIR"
  mkdir -p "$DIR"/{munge,run,log,state/ctld,state/slurmd}
  # munged insists that every user can traverse to its socket.
  chmod 755 "$DIR" "$DIR/munge"

  # munge key and daemon, private to DIR.  --force: without it munged refuses
  # a DIR whose parent is group-writable ("PRNG seed dir is insecure"),
  # common in CI checkouts.  No --force is needed for running as root.
  [[ -f $DIR/munge/munge.key ]] ||
    (umask 077 && dd if=/dev/urandom of="$DIR/munge/munge.key" bs=1024 count=1 status=none)
  munged --force --key-file="$DIR/munge/munge.key" --socket="$DIR/munge/munge.socket" \
    --pid-file="$DIR/run/munged.pid" --log-file="$DIR/log/munged.log" \
    --seed-file="$DIR/munge/munged.seed" || fail "munged failed to start"

  ctld_port=$(free_port)
  slurmd_port=$(free_port)
  while [[ $slurmd_port == "$ctld_port" ]]; do slurmd_port=$(free_port); done
  sed -e "s|@DIR@|$DIR|g" -e "s|@CTLD_PORT@|$ctld_port|g" \
    -e "s|@SLURMD_PORT@|$slurmd_port|g" -e "s|@USER@|$(id -un)|g" \
    "$HERE/slurm.conf.in" >"$DIR/slurm.conf"
  : >"$DIR/plugstack.conf" # no SPANK plugins
  export SLURM_CONF=$DIR/slurm.conf

  # Both daemonize and write their pid files in DIR/run.  -c: start from a
  # clean state even in a reused DIR (a recovered node state would look
  # "idle" before slurmd has registered).
  slurmctld -c -f "$SLURM_CONF" || fail "slurmctld failed to start"
  slurmd -c -N "$NODE" -f "$SLURM_CONF" || fail "slurmd failed to start"

  for ((i = 0; i < 300; i++)); do
    state=$(sinfo -h -n "$NODE" -o %T 2>/dev/null || true)
    [[ $state == idle ]] && { print_env; return 0; }
    sleep 0.1
  done
  fail "node $NODE not idle after 30 s (state: '${state:-none}')"
}

case $action in
  start) mkdir -p "$DIR"; DIR=$(cd "$DIR" && pwd -P); do_start ;;
  stop) [[ -d $DIR ]] || exit 0; DIR=$(cd "$DIR" && pwd -P); do_stop ;;
  env) DIR=$(cd "$DIR" && pwd -P); print_env ;;
  *) usage ;;
esac
