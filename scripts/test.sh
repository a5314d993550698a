#!/usr/bin/env bash
# Quick start 2: set up, build, and run every test. The sources are compiled
# twice, once for each kind of check (docs/testing.md):
#   release  build/ (GCC, Release): every test, Python's included; then the
#            user's install is made from this tree and run
#   check    build-check/ (clang 16, -O1): every test again under
#            AddressSanitizer + UndefinedBehaviorSanitizer; the libFuzzer
#            harnesses come from the same compile (fuzz stage)
# and the thread tests a third time under ThreadSanitizer (only what they
# link). Then the formatting check. The time of each stage is printed at the end.
#
# SKIPNC_SKIP_CHECK=1 leaves out the sanitizer tests and the fuzz stage,
# SKIPNC_SKIP_TSAN=1 the ThreadSanitizer run (faster local runs).
# The fuzz stage (scripts/fuzz.sh: each harness for a bounded time) runs in
# CI (CI=true) or when SKIPNC_FUZZ=1; SKIPNC_FUZZ_SECONDS sets the time of
# each harness (default 20).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
stages=()
stage_start=0
begin() { echo "== $1"; stage_name=$1; stage_start=$(date +%s); }
end() { stages+=("$(printf '%-44s %4d s' "$stage_name" $(( $(date +%s) - stage_start )))"); }
report_times() {
  echo
  echo "== stage times"
  printf '%s\n' "${stages[@]}"
}
trap report_times EXIT

begin "setup (Debian packages)"
scripts/setup.sh
end

begin "release build (build/)"
scripts/build.sh release
end
begin "release tests"
(cd build && ctest --output-on-failure -j"$jobs")
end

begin "install from the release tree, run it"
rm -rf build/installed
cmake --install build --prefix build/installed >/dev/null
build/installed/bin/skipnc dialects >/dev/null
end

if [ "${SKIPNC_SKIP_CHECK:-0}" != 1 ]; then
  begin "check build (build-check/: ASan + UBSan, fuzz)"
  scripts/build.sh check
  end
  begin "check tests (ASan + UBSan)"
  (cd build-check && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j"$jobs")
  end
  if [ "${SKIPNC_FUZZ:-}" = 1 ] || { [ "${CI:-}" = true ] && [ "${SKIPNC_FUZZ:-}" != 0 ]; }; then
    begin "fuzz"
    SKIPNC_FUZZ_DIR=build-check scripts/fuzz.sh "${SKIPNC_FUZZ_SECONDS:-20}"
    end
  fi
fi

if [ "${SKIPNC_SKIP_TSAN:-0}" != 1 ]; then
  begin "ThreadSanitizer (two simulators in two threads)"
  scripts/build.sh tsan
  TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/skipnc_thread_tests
  end
fi

begin "format (clang-format --dry-run)"
scripts/format.sh --check
end
