#!/usr/bin/env bash
# Smoke test of slurm.sh: start a cluster in DIR (default: a new temp folder),
# check concurrency, arrays, dependencies, requeue, scancel and a SIGKILLed
# job, stop it, and check that no system path was touched.  ~45 s.
# shellcheck disable=SC2016  # job script bodies are single-quoted on purpose
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
DIR=${1:-$(mktemp -d /tmp/lwfarm.XXXXXX)}
SYS_PATHS=(/etc/slurm /etc/munge /var/lib/slurm /var/lib/munge /var/spool/slurm
  /var/spool/slurmd /var/spool/slurmctld /var/log/slurm /var/log/munge
  /run/munge /run/slurm /var/run/munge /var/run/slurm)
fails=0
ok() { echo "PASS: $*"; }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }
check() { local msg=$1; shift; if "$@"; then ok "$msg"; else bad "$msg"; fi; }
field() { scontrol -o show job "$1" | tr ' ' '\n' | sed -n "s/^$2=//p" | head -1; }
# Wait (up to $3 s) until every job matching $1 is in a state matching $2.
wait_state() {
  local i s
  for ((i = 0; i < $3 * 10; i++)); do
    s=$(squeue -h -t all -j "$1" -o %T | sort -u | tr '\n' ' ')
    [[ -n $s && $s =~ ^(($2)\ )+$ ]] && return 0
    sleep 0.1
  done
  echo "  job $1 states: $s" >&2
  return 1
}
sys_changed() {
  local p
  for p in "${SYS_PATHS[@]}"; do [[ -e $p ]] && find "$p" -newer "$DIR.marker"; done
  return 0
}

touch "$DIR.marker"; sleep 1
t0=$EPOCHREALTIME
eval "$("$HERE/slurm.sh" start "$DIR")"
echo "start took $(awk "BEGIN{print $EPOCHREALTIME - $t0}") s; SLURM_CONF=$SLURM_CONF"
trap '"$HERE/slurm.sh" stop "$DIR"' EXIT
sinfo
mkdir -p "$DIR/logs"
hdr="#!/bin/bash
#SBATCH --chdir=$DIR
#SBATCH -n1 --cpus-per-task=1"

# 1. Two 1-CPU jobs run at once on the 2-CPU node.
printf '%s\n%s\n' "$hdr" 'date +%s.%N > start_$SLURM_JOB_ID; sleep 5; date +%s.%N > x_$SLURM_JOB_ID' >"$DIR/conc.sh"
j1=$(sbatch --parsable -o /dev/null "$DIR/conc.sh")
j2=$(sbatch --parsable -o /dev/null "$DIR/conc.sh")
wait_state "$j1,$j2" COMPLETED 20 || true
s1=$(cat "$DIR/x_$j1") s2=$(cat "$DIR/x_$j2")
echo "  x_$j1=$s1 x_$j2=$s2"
check "two 1-CPU jobs concurrent" awk "BEGIN{d=$s1-$s2; exit !(d<1 && d>-1)}"

# 2. Array %2 with per-task logs; afterok runs after all tasks succeeded,
#    and never when one fails (DependencyNeverSatisfied).
printf '%s\n%s\n' "$hdr" 'echo "task $SLURM_ARRAY_TASK_ID $(date +%s.%N)"; sleep 1
[[ $SLURM_ARRAY_TASK_ID != "${FAIL_TASK:-}" ]] || exit 3' >"$DIR/arr.sh"
printf '%s\n%s\n' "$hdr" 'echo "after $(date +%s.%N)"' >"$DIR/after.sh"
a=$(sbatch --parsable --array=0-3%2 -o "$DIR/logs/t_%a.log" "$DIR/arr.sh")
d=$(sbatch --parsable --dependency=afterok:"$a" -o "$DIR/logs/after.log" "$DIR/after.sh")
check "dependent job waits (Dependency)" test "$(field "$d" Reason)" = Dependency
wait_state "$d" COMPLETED 30 || true
check "array tasks wrote 4 logs" test "$(cat "$DIR"/logs/t_{0,1,2,3}.log | wc -l)" = 4
last=$(cat "$DIR"/logs/t_*.log | awk '{print $3}' | sort -n | tail -1)
check "afterok ran after last task" awk "BEGIN{exit !($(awk '{print $2}' "$DIR/logs/after.log") > $last)}"
a=$(FAIL_TASK=2 sbatch --parsable --array=0-3%2 -o /dev/null "$DIR/arr.sh")
d=$(sbatch --parsable --dependency=afterok:"$a" -o /dev/null "$DIR/after.sh")
wait_state "$a" 'COMPLETED|FAILED' 30 || true
sleep 1
echo "  $(squeue -h -t all -j "$a,$d" -o '%i=%T/%r' | tr '\n' ' ')"
check "afterok on failed array: DependencyNeverSatisfied" test "$(field "$d" Reason)" = DependencyNeverSatisfied
scancel "$d"

# 3. Requeue of a running array task runs it again; scancel of another.
printf '%s\n%s\n' "$hdr" 'echo "start $SLURM_ARRAY_TASK_ID restarts=${SLURM_RESTART_COUNT:-0}" >> logs/rq_$SLURM_ARRAY_TASK_ID; sleep 4' >"$DIR/rq.sh"
a=$(sbatch --parsable --requeue --array=0-1 -o /dev/null "$DIR/rq.sh")
wait_state "${a}_0,${a}_1" RUNNING 10
# RUNNING comes before the script has started: wait for its first line.
for ((i = 0; i < 50; i++)); do [[ -s $DIR/logs/rq_0 && -s $DIR/logs/rq_1 ]] && break; sleep 0.1; done
scontrol requeue "${a}_0"
scancel "${a}_1"
wait_state "${a}_0" COMPLETED 40 || true   # restarts after cred_expire+1 s
cat "$DIR/logs/rq_0"
check "requeued task ran twice" test "$(wc -l <"$DIR/logs/rq_0")" = 2
check "scancelled task CANCELLED" test "$(field "${a}_1" JobState)" = CANCELLED

# 4. SIGKILL of the job's script: job FAILED, ExitCode 0:9, no leftovers.
printf '%s\n%s\n' "$hdr" 'echo $$ > kpid; sleep 300' >"$DIR/k.sh"
k=$(sbatch --parsable -o /dev/null "$DIR/k.sh")
wait_state "$k" RUNNING 10
for ((i = 0; i < 50; i++)); do [[ -s $DIR/kpid ]] && break; sleep 0.1; done
kill -KILL "$(cat "$DIR/kpid")"
wait_state "$k" FAILED 10 || true
echo "  $(scontrol show job "$k" | grep -E -o '(JobState|Reason|ExitCode)=[^ ]*' | tr '\n' ' ')"
check "SIGKILLed job FAILED 0:9" test "$(field "$k" ExitCode)" = 0:9
sleep 1
check "no orphaned 'sleep 300'" bash -c '! pgrep -f -x "sleep 300" >/dev/null'

# 5. Stop: no daemons of ours left, nothing changed in system paths.
trap - EXIT
mapfile -t pids < <(cat "$DIR"/run/*.pid)
t0=$EPOCHREALTIME
"$HERE/slurm.sh" stop "$DIR"
echo "stop took $(awk "BEGIN{print $EPOCHREALTIME - $t0}") s"
# shellcheck disable=SC2317  # called through check
all_gone() { local p; for p; do ! kill -0 "$p" 2>/dev/null || return 1; done; ! pgrep -x slurmstepd >/dev/null; }
check "no daemons left (pids ${pids[*]})" all_gone "${pids[@]}"
pgrep -a 'munged|slurm' || true
"$HERE/slurm.sh" stop "$DIR" # idempotent
changed=$(sys_changed)
[[ -z $changed ]] || echo "$changed"
check "no system path created/modified" test -z "$changed"
echo "$fails failure(s); logs in $DIR/log"
exit $((fails > 0))
