#!/bin/sh
# Issue 31: a sweep's memory is bounded by its workers, not by its scenarios.
# A sweep of SCENARIOS cheap scenarios (default 20000) runs under a 2 GiB
# address-space limit (`ulimit -v 2097152`, as a user's batch job may set it)
# and writes its whole table: exit 0, a header and one row per scenario, every
# row passed. (The 1,000,000-scenario run, its time and peak memory are in
# bench/README.md.)
# Usage: sweep_address_space.sh SKIPNC [SCENARIOS]
set -eu
skipnc=$1
n=${2:-20000}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf 'G91 G1 X0.1 F600\nG04 X0.3\n#100 = #5021\nM30\n' > "$dir/p.nc"
cat > "$dir/s.sweep.toml" <<SPEC
program = "p.nc"
scenarios = $n
workers = 2
seed = 3
vars = ["100"]
expect = ["#100=0.1+-0.001", "status=completed"]

[[vary]]
what = "G54.Z"
uniform = [-0.1, 0.1]
SPEC
status=0
(ulimit -v 2097152 && exec "$skipnc" sweep "$dir/s.sweep.toml" -q --csv "$dir/t.csv" \
  --json "$dir/t.json") > "$dir/out.txt" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then
  echo "sweep under ulimit -v 2097152 exited $status"
  cat "$dir/out.txt"
  exit 1
fi
rows=$(wc -l < "$dir/t.csv")
if [ "$rows" -ne $((n + 1)) ]; then
  echo "t.csv has $rows lines, expected $((n + 1))"
  exit 1
fi
passed=$(tail -n +2 "$dir/t.csv" | grep -c ',pass,[^,]*$' || true)
header=$(head -1 "$dir/t.csv")
echo "header: $header"
if ! grep -q '"passed": *'"$n" "$dir/t.json"; then
  echo "t.json does not count $n passed scenarios:"
  grep -o '"summary".*' "$dir/t.json" | head -c 400
  exit 1
fi
echo "ok: $n scenarios under a 2 GiB address space ($passed rows say passed)"
