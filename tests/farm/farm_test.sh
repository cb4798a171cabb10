#!/usr/bin/env bash
# A shot through a real Slurm (the one-node cluster of slurm.sh, two CPUs, on loopback):
#  1. --exact, 24 frames of an orbit with SLAM strokes in 4 chunks: every frame identical to
#     one render of the range (linework diff, max error 0), although one chunk's linework is
#     SIGKILLed mid-chunk (its task runs again and resumes): every frame there, none
#     half-written;
#  2. --warmup 8: each chunk's first frame's phase error against the one render reported,
#     and what warm-up does give checked (below).
# Usage: farm_test.sh LINEWORK_BINARY SOURCE_DIR
set -euo pipefail
linework=$1 src=$2
here=$(cd "$(dirname "$0")" && pwd)
# Short: the munge socket's path must stay under 108 bytes.
work=$(mktemp -d /tmp/lw-farm.XXXXXX)
# LW_FARM_KEEP=1 keeps the folder (logs, frames) for a look after a failure.
cleanup() { bash "$here/slurm.sh" stop "$work/slurm" || true; [[ -n ${LW_FARM_KEEP:-} ]] || rm -rf "$work"; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# (eval "$(…)" would not stop on a failed start.)
env=$(bash "$here/slurm.sh" start "$work/slurm") || fail "the local Slurm did not start (tools/test.sh installs slurm-wlm and munge)"
eval "$env"
# 960×720: a frame takes ~30 ms here, so the five frames after a chunk's first take ~150 ms,
# and a CONT/STOP slice (below) that overruns by tens of ms on a loaded machine still stops
# the chunk mid-way. At 160×120 (~9 ms a frame) the whole chunk once got written inside one
# overrun slice while ctest ran other tests beside it ("the kill did not land mid-chunk").
shot=("$src/tests/data/models/spot/spot.glb" --device cpu --size 960x720 --orbit 90 --slam "$src/scenes/slams/dots.exr")

echo "== one render of the range (the reference)"
"$linework" render "${shot[@]}" --frames 0:23 -o "$work/one" --dump-paths "$work/one_dumps" > "$work/one.log"

# Waits until none of the jobs named is pending or running (at most $2 seconds).
wait_jobs() {
  local jobs=$1 limit=$2 t
  for ((t = 0; t < limit * 10; t++)); do
    [[ -z $(squeue -h -j "$jobs" -t PD,R,CG,CF,S -o %i 2>/dev/null) ]] && return 0
    sleep 0.1
  done
  squeue -t all >&2
  fail "jobs $jobs still queued after $limit s"
}

submit() {
  local out
  out=$(bash "$1/slurm/submit.sh")
  echo "$out" >&2
  echo "$out" | sed -n 's/.*job \([0-9]*\).*/\1/p' | paste -sd, -
}

echo "== --exact through Slurm, one chunk's process killed mid-chunk"
"$linework" farm "${shot[@]}" --frames 0:23 --chunk 6 --exact -o "$work/exact"
# Chunk 2 (frames 12-17) is made to stop itself (SIGSTOP) before its linework starts: the
# test edits that task's command in the generated job script to go through stop_first.sh,
# which on its first run writes its pid, stops, and when let go execs linework in the same
# process. The test then lets it run in ~2 ms slices (bash builtins, no fork between CONT
# and STOP: a loaded machine delays a forked `sleep` by tens of ms, and a frame here takes
# ~30 ms) until its first frame is on disk, so that the SIGKILL lands mid-chunk whatever the
# machine's speed; its job script then runs the task again (stop_first.sh then just execs).
cat > "$work/stop_first.sh" <<EOS
#!/usr/bin/env bash
if mkdir "$work/stopped" 2>/dev/null; then echo \$\$ > "$work/stopped/pid"; kill -STOP \$\$; fi
exec "\$@"
EOS
frames_script=$(ls "$work"/exact/slurm/phase_*_frames.sbatch)
grep -q '^  2) id=.*; cmd=(' "$frames_script" || fail "no task 2 line in $frames_script"
sed -i "s|^  2) \(id=[^;]*\); cmd=(|  2) \1; cmd=(bash $work/stop_first.sh |" "$frames_script"
jobs=$(submit "$work/exact")
chunk_frames() { ls "$work/exact/frames" 2>/dev/null | grep -c '^frame_001[2-7].png$' || true; }
for ((t = 0; t < 3000; t++)); do
  [[ -s $work/stopped/pid ]] && break
  sleep 0.1
done
pid=$(cat "$work/stopped/pid" 2>/dev/null) || fail "never saw chunk 12-17 start"
# Until the pid shows as stopped (T) it may not yet have reached its own SIGSTOP.
for ((t = 0; t < 3000; t++)); do
  [[ $(ps -o stat= -p "$pid") == T* ]] && break
  sleep 0.01
done
exec {never}<> <(:)  # an fd that never has data: `read -t` on it is a fork-free sleep
for ((t = 0; t < 100000 && $(chunk_frames) == 0; t++)); do
  kill -CONT "$pid"; read -r -t 0.002 -u "$never" || true; kill -STOP "$pid"
done
written=$(chunk_frames)
kill -KILL "$pid"
echo "killed chunk 12-17 (pid $pid) with $written of its 6 frames written"
((written >= 1 && written < 6)) || fail "the kill did not land mid-chunk ($written of 6 frames written)"
wait_jobs "$jobs" 300
"$linework" farm status "$work/exact" || fail "farm status: the shot is not complete"
grep -q "ended by signal 9; running it again" "$work/exact/logs/frames_0002.log" || fail "the killed task was not run again"
grep -q "resuming at frame" "$work/exact/logs/frames_0002.log" || fail "the re-run did not resume"
if find "$work/exact" -name '*.partial*' | grep -q .; then fail "half-written files left"; fi
for f in $(seq -f %04g 0 23); do
  "$linework" diff "$work/one/frame_$f.png" "$work/exact/frames/frame_$f.png" --max-error 0 > "$work/diff.log" ||
    { cat "$work/diff.log"; fail "frame $f differs from one render"; }
done
echo "exact: 24 frames identical to one render (max error 0)"

echo "== --warmup 8 through Slurm"
"$linework" farm "${shot[@]}" --frames 0:23 --chunk 6 --warmup 8 -o "$work/warm" --dump-paths "$work/warm_dumps"
jobs=$(submit "$work/warm")
wait_jobs "$jobs" 300
"$linework" farm status "$work/warm" || fail "farm status: the warm-up shot is not complete"
# Reported: each chunk's first frame against one render. Warm-up gives no bound on the phase
# (README "Render farm": a chunk's own history sets it, p90 ≈ 0.45 period for any K); what
# it gives is checked: a chunk no further than K from the shot's start starts where one
# render does (frames 6-11 identical), and a chunk's first frames slide no more than one
# render's (first → second frame, worst chunk, within 1.5×, or within 0.002 periods: one
# render's own frame-to-frame slide varies from 0.001 to 0.004 periods over this shot, so
# below that there is no settling to tell from the fit's noise).
"$linework" coherence-report "$work/warm_dumps" --against "$work/one_dumps" | grep -E "against|frame (0|6|12|18):"
for f in $(seq -f %04g 6 11); do
  "$linework" diff "$work/one/frame_$f.png" "$work/warm/frames/frame_$f.png" --max-error 0 > /dev/null ||
    fail "warm-up chunk 6-11 (warmed up from frame 0) differs from one render at frame $f"
done
# Median |dt| from frame $2 to $2+1 of dump folder $1.
slide() {
  local tmp
  tmp=$(mktemp -d "$work/slide.XXXX")
  local f
  for f in "$2" $(($2 + 1)); do
    ln -s "$1/frame_$(printf %04d "$f").json" "$tmp/frame_$(printf %04d "$f").json"
  done
  "$linework" coherence-report "$tmp" | sed -n 's/.*sliding: median |dt| \([0-9.]*\).*/\1/p' | head -n1
}
for c in 12 18; do
  warm=$(slide "$work/warm_dumps" $c) one=$(slide "$work/one_dumps" $c)
  echo "sliding from frame $c to $((c + 1)): warm-up chunk $warm, one render $one periods"
  awk -v w="$warm" -v o="$one" 'BEGIN { exit !(w <= 1.5 * o || w <= 0.002) }' ||
    fail "the warm-up chunk at $c still settles (slides $warm against one render's $one)"
done
echo "PASS"
