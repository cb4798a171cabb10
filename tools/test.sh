#!/usr/bin/env bash
# tools/test.sh — the README's test command and CI's (.ci/run): install what is missing,
# build, run the whole suite on lavapipe with the Khronos validation layer on; then the same
# suite built with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan).
#   bash tools/test.sh            both
#   bash tools/test.sh --quick    the plain build only
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/bootstrap.sh
# The farm test's scheduler: a one-node Slurm started and stopped by the test (tests/farm).
test_packages=(slurm-wlm munge librsvg2-bin)  # a local Slurm; rsvg-convert draws the SVG export (tests/test_svg_export.cpp)
for p in "${test_packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    echo "test: installing ${test_packages[*]}"
    apt-get update -q
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${test_packages[@]}"
    break
  fi
done
ctest --test-dir build --output-on-failure -j"$(nproc)"
[ "${1:-}" = "--quick" ] && exit 0

echo "test: the suite again under ASan + UBSan (build-asan)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLINEWORK_SANITIZE=ON
cmake --build build-asan -j"$(nproc)"
UBSAN_OPTIONS=print_stacktrace=1 ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
