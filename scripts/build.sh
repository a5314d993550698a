#!/usr/bin/env bash
# Configures and builds one flavour, warnings as errors (SKIPNC_WERROR=ON; a
# plain `cmake` build leaves them warnings):
#   release  (default) build/, RelWithDebInfo, with the tests and the benchmarks (built, not run)
#   asan     build-asan/, Debug with AddressSanitizer + UndefinedBehaviorSanitizer
#   demo     build/, only the skipnc binary (no tests)
#   tsan     build-tsan/, ThreadSanitizer, only the thread tests (tests/threads/)
# Usage: scripts/build.sh [release|asan|demo|tsan]
set -euo pipefail
cd "$(dirname "$0")/.."
flavour=${1:-release}
targets=()
case $flavour in
  release) dir=build; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSKIPNC_TESTS=ON -DSKIPNC_BENCH=ON) ;;
  asan) dir=build-asan; flags=(-DCMAKE_BUILD_TYPE=Debug -DSKIPNC_SANITIZE=ON -DSKIPNC_TESTS=ON) ;;
  demo) dir=build; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSKIPNC_TESTS=OFF); targets=(--target skipnc) ;;
  tsan) dir=build-tsan; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSKIPNC_TSAN=ON -DSKIPNC_TESTS=ON -DSKIPNC_PYTHON=OFF); targets=(--target skipnc_thread_tests) ;;
  *) echo "build.sh: unknown flavour '$flavour' (release, asan, demo, tsan)" >&2; exit 2 ;;
esac
generator=()
command -v ninja >/dev/null && [ ! -f "$dir/CMakeCache.txt" ] && generator=(-G Ninja)
cmake -S . -B "$dir" "${generator[@]}" -DSKIPNC_WERROR=ON "${flags[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)" "${targets[@]}"
