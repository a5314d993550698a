#!/usr/bin/env bash
# Configures and builds one flavour, warnings as errors (SKIPNC_WERROR=ON; a
# plain `cmake` build leaves them warnings):
#   release  (default) build/: Release, the tests, the Python module and the
#            benchmarks (built, not run). Also the tree the user's install is
#            made from (scripts/test.sh).
#   demo     build/: the same configuration, only the skipnc binary; the
#            release flavour later reuses every object it compiled
#   check    build-check/: clang 16 at -O1 with AddressSanitizer +
#            UndefinedBehaviorSanitizer and libFuzzer's coverage: the tests
#            and the fuzz harnesses (scripts/fuzz.sh) from one compile
#   tsan     build-tsan/: ThreadSanitizer (clang 16, -O1), only the thread
#            tests (tests/threads/)
# The tests are compiled a few files to a translation unit (SKIPNC_UNITY_TESTS,
# tests/CMakeLists.txt) in the release and check flavours.
# Usage: scripts/build.sh [release|demo|check|tsan]
set -euo pipefail
cd "$(dirname "$0")/.."
flavour=${1:-release}
targets=()
# Python: the module is part of the release tree whenever pybind11 is there
# (scripts/setup.sh installs it). Said explicitly, so that a tree first
# configured by demo.sh, before pybind11 was installed, does not keep OFF.
python=OFF
[ -f /usr/lib/cmake/pybind11/pybind11Config.cmake ] && python=ON
release=(-DCMAKE_BUILD_TYPE=Release -DSKIPNC_PYTHON="$python")
# clang 16: the sanitizer and fuzz flavours; -O1 keeps both quick to build and run.
clang=(-DCMAKE_CXX_COMPILER=clang++-16 -DCMAKE_BUILD_TYPE=Debug
       -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only")
case $flavour in
  release) dir=build; flags=("${release[@]}" -DSKIPNC_TESTS=ON -DSKIPNC_BENCH=ON -DSKIPNC_UNITY_TESTS=ON) ;;
  demo) dir=build; flags=("${release[@]}"); targets=(--target skipnc) ;;
  check) dir=build-check
    flags=("${clang[@]}" -DSKIPNC_SANITIZE=ON -DSKIPNC_FUZZ=ON -DSKIPNC_TESTS=ON -DSKIPNC_PYTHON="$python"
           -DSKIPNC_UNITY_TESTS=ON) ;;
  tsan) dir=build-tsan
    flags=("${clang[@]}" -DSKIPNC_TSAN=ON -DSKIPNC_TESTS=ON -DSKIPNC_PYTHON=OFF)
    targets=(--target skipnc_thread_tests) ;;
  *) echo "build.sh: unknown flavour '$flavour' (release, demo, check, tsan)" >&2; exit 2 ;;
esac
generator=()
command -v ninja >/dev/null && [ ! -f "$dir/CMakeCache.txt" ] && generator=(-G Ninja)
cmake -S . -B "$dir" "${generator[@]}" -DSKIPNC_WERROR=ON "${flags[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)" "${targets[@]}"
