#!/usr/bin/env bash
# Side-by-side measurements of skipnc and LinuxCNC (the peer kit in
# ../shared/peers/linuxcnc), in one run, on this machine. Prints tables; see
# bench/README.md for the last results.
#
# Usage: bench/compare.sh [--quick]
#   needs: build/ with -DSKIPNC_BENCH=ON (scripts/build.sh then
#   cmake -S . -B build -DSKIPNC_BENCH=ON && cmake --build build), and as root
#   the peer kit installs linuxcnc-uspace itself.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
kit=${PEER_KIT:-$root/../shared/peers/linuxcnc}
bin=$root/build/skipnc
quick=0
[ "${1:-}" = "--quick" ] && quick=1
sizes="1000000"; reps=3; big=10000000
[ $quick = 1 ] && { sizes="100000"; reps=1; big=1000000; }
work=$(mktemp -d "${TMPDIR:-/tmp}/skipnc-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "host: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cpus"
echo "skipnc: $(git -C "$root" rev-parse --short HEAD)"

echo
echo "== 1. interpreter throughput: rs274 -g (A) vs skipnc canon (B), output to /dev/null"
"$kit/peer.sh" --skip-probe --sizes "$sizes" --reps "$reps" --vs "$bin canon {file}" "$work/peer" \
  | sed -n '/^== 1/,/^B\/A_wall/p'

echo
echo "== 2. memory: skipnc canon of a $big-block program (peak RSS)"
python3 "$kit/gen_motion.py" "$big" 1 > "$work/big.ngc"
/usr/bin/time -f "%M" -o "$work/rss" "$bin" canon "$work/big.ngc" > /dev/null
echo "blocks $big  file $(( $(stat -c %s "$work/big.ngc") / 1048576 )) MiB  peak RSS $(( $(cat "$work/rss") / 1024 )) MiB"
rm -f "$work/big.ngc"

echo
echo "== 3. simulation speed: simulated seconds per wall second"
python3 "$root/bench/gen_hour.py" "$work/hour.nc"
# Each case runs several times (the median is the figure; the fastest shows
# what an undisturbed run takes on a shared virtual machine).
for trace in off on; do
  args=(run "$work/hour.nc" --report "$work/hour.json" -q)
  [ $trace = on ] && args+=(--trace "$work/hour.csv")
  runs=5
  [ $trace = on ] && runs=3
  [ $quick = 1 ] && runs=1
  walls=()
  for _ in $(seq "$runs"); do
    start=$(date +%s.%N)
    "$bin" "${args[@]}"
    end=$(date +%s.%N)
    walls+=("$(python3 -c "print($end - $start)")")
    rm -f "$work/hour.csv"
  done
  sim=$(python3 -c "import json;print(json.load(open('$work/hour.json'))['final']['time'])")
  python3 - "$trace" "$sim" "${walls[@]}" <<'PY'
import statistics, sys
trace, sim, walls = sys.argv[1], float(sys.argv[2]), sorted(float(w) for w in sys.argv[3:])
med = statistics.median(walls)
print(f"trace {trace:3}  simulated {sim:.0f} s  wall median {med:.2f} s (runs: "
      + "/".join(f"{w:.2f}" for w in walls)
      + f")  ratio {sim / med:,.0f}x real time (fastest run {sim / walls[0]:,.0f}x)")
PY
done

echo
echo "== 4. kernel tick cost (planner sampling + skip monitor, no I/O)"
"$root/build/bench/skipnc_tick_latency" $([ $quick = 1 ] && echo 200000 || echo 2000000)

echo
echo "== 5. latch accuracy (skipnc modes beside LinuxCNC's G38.2 figures)"
python3 "$root/bench/latch_table.py" "$bin"
