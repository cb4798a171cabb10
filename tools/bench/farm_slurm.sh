#!/usr/bin/env bash
# Wall time of one shot through the local Slurm of tests/farm (one node, two CPUs) with at
# most 1 and then 2 tasks at once (linework farm --throttle), --exact, pair by pair, and
# the state phase's own time. Prints one line per run and the medians (docs/BENCHMARKS.md).
#   tools/bench/farm_slurm.sh build/linework MODEL [runs] [render options...]
#   e.g. tools/bench/farm_slurm.sh build/linework LeePerrySmith.glb 3 --size 640x480 \
#        --orbit 90 --slam scenes/slams/dots.exr --device cpu
set -euo pipefail
linework=$(realpath "$1") model=$(realpath "$2") runs=${3:-3}
shift 3 || shift $#
frames=${LW_FARM_FRAMES:-0:47} chunk=${LW_FARM_CHUNK:-12}
here=$(cd "$(dirname "$0")/../../tests/farm" && pwd)
work=$(mktemp -d /tmp/lw-fb.XXXXXX)
trap 'bash "$here/slurm.sh" stop "$work/slurm" || true; rm -rf "$work"' EXIT
eval "$(bash "$here/slurm.sh" start "$work/slurm")"

# Seconds from submission until every job of the shot has left the queue.
shot() {
  local dir=$1 throttle=$2 jobs t0 t1
  rm -rf "$dir"
  "$linework" farm "$model" --frames "$frames" --chunk "$chunk" --exact --throttle "$throttle" \
    -o "$dir" "${render_args[@]}" > /dev/null
  t0=$(date +%s.%N)
  jobs=$(bash "$dir/slurm/submit.sh" | sed -n 's/.*job \([0-9]*\).*/\1/p' | paste -sd, -)
  while [[ -n $(squeue -h -j "$jobs" -t PD,R,CG,CF,S -o %i 2>/dev/null) ]]; do sleep 0.05; done
  t1=$(date +%s.%N)
  "$linework" farm status "$dir" > /dev/null || { echo "shot incomplete: $dir" >&2; exit 1; }
  echo "$t1 - $t0" | bc
}
render_args=("$@")
one=() two=()
for ((i = 0; i < runs; i++)); do
  a=$(shot "$work/one" 1)
  b=$(shot "$work/two" 2)
  one+=("$a") two+=("$b")
  state=$(grep -h "time per frame" "$work/two/logs/state_0000.log" | tail -n1)
  echo "run $i: 1 task at a time $a s, 2 at a time $b s (state phase: $state)"
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'; }
m1=$(median "${one[@]}") m2=$(median "${two[@]}")
echo "median: 1 task $m1 s, 2 tasks $m2 s, speed-up $(echo "scale=2; $m1 / $m2" | bc)"
