#!/usr/bin/env bash
# Quick start 2: set up, build, and run every test: once in the release build,
# once under AddressSanitizer + UndefinedBehaviorSanitizer.
# SKIPNC_SKIP_ASAN=1 leaves out the sanitizer pass (faster local runs).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
echo "== release build"
scripts/build.sh release
(cd build && ctest --output-on-failure -j"$(nproc)")
if [ "${SKIPNC_SKIP_ASAN:-0}" != 1 ]; then
  echo "== ASan + UBSan build"
  scripts/build.sh asan
  (cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j"$(nproc)")
fi
