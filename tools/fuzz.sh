#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan) in build-fuzz and runs
# each for SECONDS (default 600), seeded from tests/fuzz/corpus/NAME. New interesting inputs
# collect in build-fuzz/corpus/NAME; crashes are written as build-fuzz/crash-NAME-*.
#   bash tools/fuzz.sh [SECONDS] [TARGET...]      targets: gltf mesh scene strokes slam image
# A crash found becomes a regression test: copy the input into tests/fuzz/corpus/NAME (the
# suite replays that folder, FuzzCorpus.NAME) and fix the reader.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(gltf mesh scene strokes slam image)

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DLINEWORK_FUZZ=ON -DLINEWORK_TESTS=OFF > /tmp/linework-fuzz-build.log
cmake --build build-fuzz -j2 --target $(printf 'fuzz_%s ' "${targets[@]}") >> /tmp/linework-fuzz-build.log

# Leak checks off: lavapipe and OpenImageIO (for formats other than PNG) keep caches alive past
# exit.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t"
  echo "fuzz_$t: ${seconds} s"
  ./build-fuzz/fuzz_$t -max_total_time="$seconds" -max_len=65536 -timeout=20 -rss_limit_mb=4096 \
      -artifact_prefix="build-fuzz/crash-$t-" -print_final_stats=1 \
      "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" 2>&1 | tee "build-fuzz/fuzz_$t.log" | grep -E "^#[0-9]+ *DONE|stat::number_of_executed_units|ERROR|SUMMARY" || true
done
