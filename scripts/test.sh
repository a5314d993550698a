#!/usr/bin/env bash
# Quick start 2: set up, build, and run every test: once in the release build,
# once under AddressSanitizer + UndefinedBehaviorSanitizer; and build skipnc as a
# user would (plain Release, warnings not errors) and install it.
# SKIPNC_SKIP_ASAN=1 leaves out the sanitizer pass (faster local runs);
# SKIPNC_SKIP_TSAN=1 the ThreadSanitizer run of the thread tests.
# The fuzz stage (scripts/fuzz.sh: every libFuzzer harness for a bounded
# time under ASan + UBSan) runs in CI (CI=true) or when SKIPNC_FUZZ=1;
# SKIPNC_FUZZ_SECONDS sets the time of each harness (default 40: with two
# harnesses at a time on two cores the stage, build included, stays within
# about four minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
echo "== release build"
scripts/build.sh release
(cd build && ctest --output-on-failure -j"$(nproc)")
echo "== a user's plain Release build (no -DSKIPNC_WERROR: warnings stay warnings), then install"
cmake -S . -B build-user -DCMAKE_BUILD_TYPE=Release -DSKIPNC_TESTS=OFF -DSKIPNC_PYTHON=OFF >/dev/null
cmake --build build-user -j"$(nproc)" --target skipnc
cmake --install build-user --prefix build-user/installed >/dev/null
build-user/installed/bin/skipnc dialects >/dev/null
if [ "${SKIPNC_SKIP_ASAN:-0}" != 1 ]; then
  echo "== ASan + UBSan build"
  scripts/build.sh asan
  (cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j"$(nproc)")
fi
if [ "${SKIPNC_SKIP_TSAN:-0}" != 1 ]; then
  echo "== ThreadSanitizer (two simulators in two threads)"
  scripts/build.sh tsan
  TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/skipnc_thread_tests
fi
if [ "${SKIPNC_FUZZ:-}" = 1 ] || { [ "${CI:-}" = true ] && [ "${SKIPNC_FUZZ:-}" != 0 ]; }; then
  echo "== fuzz"
  scripts/fuzz.sh "${SKIPNC_FUZZ_SECONDS:-40}"
fi
