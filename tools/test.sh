#!/usr/bin/env bash
# tools/test.sh — the README's test command and CI's (.ci/run): install what is missing,
# build, run the whole suite on lavapipe with the Khronos validation layer on; then the same
# suite built with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan).
#   bash tools/test.sh            both
#   bash tools/test.sh --quick    the plain build only
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/bootstrap.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
[ "${1:-}" = "--quick" ] && exit 0

echo "test: the suite again under ASan + UBSan (build-asan)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLINEWORK_SANITIZE=ON
cmake --build build-asan -j"$(nproc)"
UBSAN_OPTIONS=print_stacktrace=1 ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
