#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang-16, ASan + UBSan) in build-fuzz and
# runs each for a bounded time, seeded from tests/fuzz/corpus/<harness>/.
#
# Usage: scripts/fuzz.sh [SECONDS] [HARNESS...]
#   SECONDS   run time of each harness (default 60)
#   HARNESS   parser expr interp machine scene stl ngc_params sweep (default: all)
# Environment:
#   SKIPNC_FUZZ_JOBS  harnesses run at once (default: the number of cores)
#   SKIPNC_FUZZ_DIR   build folder (default build-fuzz; scripts/test.sh gives
#                     build-check, whose objects it shares with the sanitizer tests)
#
# New inputs that reach new code go to build-fuzz/corpus/<harness>/ (not kept
# in the source tree). A crash, hang (timeout-*), leak or broken check ends
# the script with status 1 and leaves the input in build-fuzz/artifacts/:
# copy it to tests/regression/<harness>/, fix the bug, and the normal test
# run replays it from then on (tests/regression/regression_test.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-60}
[ $# -gt 0 ] && shift
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(parser expr interp machine scene stl ngc_params sweep)
dir=${SKIPNC_FUZZ_DIR:-build-fuzz}
jobs=${SKIPNC_FUZZ_JOBS:-$(nproc)}
cxx=${SKIPNC_FUZZ_CXX:-clang++-16}

if ! command -v "$cxx" >/dev/null; then
  echo "fuzz.sh: $cxx not found (scripts/setup.sh installs clang-16 and libclang-rt-16-dev)" >&2
  exit 2
fi

# Debug keeps assertions on; -O1 keeps the sanitized harnesses quick to build and run.
start=$(date +%s)
# A tree already configured with the harnesses (the check build,
# scripts/build.sh check) is used as it is: its objects serve the tests and
# the harnesses alike. Otherwise a tree of the harnesses alone.
if ! grep -q '^SKIPNC_FUZZ:BOOL=ON' "$dir/CMakeCache.txt" 2>/dev/null; then
  cmake -S . -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DSKIPNC_FUZZ=ON -DSKIPNC_TESTS=OFF \
    -DSKIPNC_BENCH=OFF >/dev/null
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build "$dir" -j"$(nproc)" --target "${targets[@]}"
echo "fuzz.sh: built in $(( $(date +%s) - start )) s; running ${#harnesses[@]} harnesses for ${secs} s each, $jobs at a time"

run_one() {
  local h=$1
  local corpus="$dir/corpus/$h" art="$dir/artifacts/$h/" log="$dir/logs/$h.log"
  local max_len=4096
  case $h in machine|scene|sweep) max_len=8192 ;; stl) max_len=65536 ;; esac
  mkdir -p "$corpus" "$art" "$dir/logs"
  # -timeout: an input running longer is a hang; -rss_limit_mb: a leak or a
  # runaway allocation. Both are findings.
  if ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0 \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
     "$dir/tests/fuzz/fuzz_$h" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
       -max_len="$max_len" -artifact_prefix="$art" -print_final_stats=1 \
       "$corpus" "tests/fuzz/corpus/$h" >"$log" 2>&1; then
    echo "fuzz_$h: ok ($(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}') runs," \
         "$(grep -E '^stat::new_units_added' "$log" | awk '{print $2}') new inputs)"
    return 0
  fi
  echo "fuzz_$h: FAILED; log $log, input(s):" >&2
  ls "$art" >&2 || true
  tail -n 40 "$log" >&2
  return 1
}

status=0
pids=()
names=()
for h in "${harnesses[@]}"; do
  run_one "$h" &
  pids+=($!)
  names+=("$h")
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
    names=("${names[@]:1}")
  fi
done
for p in "${pids[@]}"; do wait "$p" || status=1; done
echo "fuzz.sh: done in $(( $(date +%s) - start )) s"
exit $status
