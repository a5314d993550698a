#!/usr/bin/env bash
# The regression guard: builds BASE (a commit) and the work tree, both plain
# Release (tests and benchmarks off), and times them side by side on the
# interpreter, a full simulation and a probing sweep, in interleaved runs
# (A B, B A, ... after a warm-up). Prints, per benchmark, the median of the
# pair-by-pair ratios work / base (wall and CPU) with their spread (min - max).
# A ratio above 1 is a slow-down. Run it at every change that touches src/ and
# quote its lines in the commit message (bench/README.md, "Regression guard").
#
# Usage: bench/regress.sh BASE [--quick] [--pairs N] [--same] [--keep]
#   BASE      a commit (517ebdb, main, HEAD~3, ...)
#   --quick   smaller programs and 5 pairs (about a minute once built)
#   --pairs N interleaved pairs (default 7, at least 5)
#   --same    also check that both give the same outputs to the byte (canon
#             text, run report, sweep table): for a change that must not alter them
#   --keep    keep the generated programs and outputs (their folder is printed)
# Builds go to build-regress/ (the base binary is kept per commit; the work
# tree's build is incremental); ccache makes them mostly cache hits.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
usage() { sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
base="" quick=0 pairs="" same=0 keep=0
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=1 ;;
    --pairs) pairs=$2; shift ;;
    --same) same=1 ;;
    --keep) keep=1 ;;
    -h|--help) usage ;;
    -*) echo "regress.sh: unknown option $1" >&2; usage ;;
    *) [ -z "$base" ] || usage; base=$1 ;;
  esac
  shift
done
[ -n "$base" ] || usage
sha=$(git rev-parse --verify --quiet "$base^{commit}") || {
  echo "regress.sh: '$base' is not a commit" >&2; exit 2; }
[ -n "$pairs" ] || pairs=$([ $quick = 1 ] && echo 5 || echo 7)
[ "$pairs" -ge 5 ] || { echo "regress.sh: at least 5 pairs" >&2; exit 2; }
kit=${PEER_KIT:-$root/../shared/peers/linuxcnc}
cache=${REGRESS_CACHE:-$root/build-regress}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

configure_and_build() { # source folder, build folder
  local launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  local generator=()
  command -v ninja >/dev/null && [ ! -f "$2/CMakeCache.txt" ] && generator=(-G Ninja)
  # Configured once: a work build configured with tests or benchmarks (to run
  # them on the same objects) stays so.
  [ -f "$2/CMakeCache.txt" ] ||
    cmake -S "$1" -B "$2" "${generator[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
      -DSKIPNC_TESTS=OFF -DSKIPNC_BENCH=OFF -DSKIPNC_PYTHON=OFF -DSKIPNC_WERROR=OFF \
      --no-warn-unused-cli >/dev/null
  cmake --build "$2" --target skipnc -j"$(nproc)" >/dev/null
}

base_bin=$cache/skipnc-$sha
if [ ! -x "$base_bin" ]; then
  echo "building base $(git rev-parse --short "$sha") ..."
  src=$cache/src-$sha
  rm -rf "$src" "$cache/build-$sha"
  git worktree add --detach --quiet "$src" "$sha"
  configure_and_build "$src" "$cache/build-$sha"
  cp "$cache/build-$sha/skipnc" "$base_bin"
  git worktree remove --force "$src"
  rm -rf "$cache/build-$sha"
fi
echo "building work tree ..."
configure_and_build "$root" "$cache/work"
work_bin=$cache/work/skipnc

tmp=$(mktemp -d "${TMPDIR:-/tmp}/skipnc-regress.XXXXXX")
[ $keep = 1 ] && echo "kept in: $tmp" || trap 'rm -rf "$tmp"' EXIT

blocks=300000 sim_seconds=9000 hour_seconds=3600 scenarios=300 probe_runs=20
[ $quick = 1 ] && { blocks=100000; sim_seconds=3000; hour_seconds=1200; scenarios=100; probe_runs=8; }
python3 "$kit/gen_motion.py" "$blocks" 1 > "$tmp/motion.ngc"
python3 "$kit/gen_expr.py" "$blocks" 1 > "$tmp/expr.ngc"
python3 "$root/bench/gen_short_moves.py" "$sim_seconds" > "$tmp/short.nc"
python3 "$root/bench/gen_hour.py" "$tmp/hour.nc" "$hour_seconds"

# The probing benchmark is the sweep when both binaries have it, otherwise the
# single-surface cycle run alone, probe_runs times per timed run.
ex=$root/examples/probing
sweep_spec=$root/bench/sweep/surface.sweep.toml
probe_kind=sweep
"$base_bin" --help 2>/dev/null | grep -q "^ *sweep " || probe_kind=run
base_ex=$ex # an older base may not read today's machine file: then it runs its own
if [ $probe_kind = run ] && ! "$base_bin" run "$ex/surface.nc" -s "$ex/fixture_real.scene.toml" \
    -m "$ex/mill3_probe.machine.toml" -q >/dev/null 2>&1; then
  base_ex=$tmp/base-examples
  mkdir -p "$base_ex"
  for f in surface.nc fixture_real.scene.toml mill3_probe.machine.toml; do
    git show "$sha:examples/probing/$f" > "$base_ex/$f"
  done
  probe_kind="run (base: its own example files)"
fi

git -C "$root" log -1 --format='work tree: %h %s' | cut -c1-100
git log -1 --format='base:      %h %s' "$sha" | cut -c1-100
echo "host: $(nproc) cpus, load $(cut -d' ' -f1-3 /proc/loadavg); $pairs pairs; canon: $blocks blocks;" \
  "run: ${hour_seconds} s of long moves, ${sim_seconds} s of short moves; probing: $probe_kind"

python3 - "$tmp" "$base_bin" "$work_bin" "$pairs" "$same" "$probe_kind" "$scenarios" \
  "$probe_runs" "$sweep_spec" "$base_ex" "$ex" <<'PY'
import os, statistics, subprocess, sys, time, json, filecmp
tmp, base, work, pairs, same, probe_kind, scenarios, probe_runs, spec, base_ex, work_ex = sys.argv[1:]
pairs, same, probe_runs = int(pairs), same == "1", int(probe_runs)

def cases(binary, tag, ex):
    out = lambda name: os.path.join(tmp, f"{tag}.{name}")
    c = [("canon motion", [[binary, "canon", f"{tmp}/motion.ngc"]], out("motion.txt")),
         ("canon expr", [[binary, "canon", f"{tmp}/expr.ngc"]], out("expr.txt")),
         ("run hour", [[binary, "run", f"{tmp}/hour.nc", "-q",
                        "--report", out("hour.json")]], None),
         ("run short moves", [[binary, "run", f"{tmp}/short.nc", "-q",
                               "--report", out("short.json")]], None)]
    if probe_kind.startswith("sweep"):
        c.append(("sweep probing", [[binary, "sweep", spec, "-n", scenarios, "-j", "1", "-q",
                                     "--csv", out("sweep.csv"), "--json", out("sweep.json")]],
                  None))
    else:
        run = [binary, "run", f"{ex}/surface.nc", "-s", f"{ex}/fixture_real.scene.toml",
               "-m", f"{ex}/mill3_probe.machine.toml", "-q", "--report", out("probe.json")]
        c.append(("probing run x%d" % probe_runs, [run] * probe_runs, None))
    return c

def timed(commands, stdout):
    """Wall and CPU (user + system) seconds of the commands run one after the other.
    Exit status 1 is a run that ended as it may (an alarm, a sweep's failed check)."""
    cpu = 0.0
    start = time.perf_counter()
    for argv in commands:
        with open(stdout or os.devnull, "wb") as sink:
            p = subprocess.Popen(argv, stdout=sink, stderr=subprocess.PIPE)
            _, status, usage = os.wait4(p.pid, 0)
            err = p.stderr.read().decode(errors="replace")
            p.stderr.close()
            p.returncode = os.waitstatus_to_exitcode(status)
        if p.returncode not in (0, 1):
            sys.exit(f"regress.sh: {' '.join(argv)} failed ({p.returncode}): {err[-500:]}")
        cpu += usage.ru_utime + usage.ru_stime
    return time.perf_counter() - start, cpu

A, B = cases(base, "base", base_ex), cases(work, "work", work_ex)
for (_, ca, oa), (_, cb, ob) in zip(A, B):   # warm-up (and the outputs for --same)
    timed(ca, oa); timed(cb, ob)
res = {name: {"A": [], "B": []} for name, _, _ in A}
for i in range(pairs):
    for (name, ca, _), (_, cb, _) in zip(A, B):
        order = [("A", ca), ("B", cb)] if i % 2 == 0 else [("B", cb), ("A", ca)]
        for side, cmd in order:
            res[name][side].append(timed(cmd, None))

def sim_time(path):
    try:
        return json.load(open(path))["final"]["time"]
    except (OSError, KeyError, ValueError):
        return None

print()
print(f"{'benchmark':22} {'base wall':>10} {'work wall':>10}   {'work/base wall (min-max)':26} "
      f"{'work/base CPU (min-max)':26}")
for name in res:
    a, b = res[name]["A"], res[name]["B"]
    rw = [y[0] / x[0] for x, y in zip(a, b)]
    rc = [y[1] / x[1] for x, y in zip(a, b)]
    mw = lambda s: statistics.median(v[0] for v in s)
    fmt = lambda r: f"{statistics.median(r):.3f} ({min(r):.3f}-{max(r):.3f})"
    print(f"{name:22} {mw(a):9.3f}s {mw(b):9.3f}s   {fmt(rw):26} {fmt(rc):26}")
print()
for name, f in (("run hour", "hour"), ("run short moves", "short")):
    sim = sim_time(os.path.join(tmp, f"work.{f}.json"))
    if sim:
        wall = statistics.median(v[0] for v in res[name]["B"])
        print(f"{name}: {sim:.0f} s simulated, work {sim / wall:,.0f}x real time (wall median)")

if same:
    print()
    files = ["motion.txt", "expr.txt", "hour.json", "short.json"]
    files += ["sweep.csv", "sweep.json"] if probe_kind.startswith("sweep") else ["probe.json"]
    bad = 0
    for f in files:
        pa, pb = os.path.join(tmp, "base." + f), os.path.join(tmp, "work." + f)
        ok = filecmp.cmp(pa, pb, shallow=False)
        bad += not ok
        print(f"same output: {f:12} {'identical' if ok else 'DIFFERS'} ({os.path.getsize(pb)} bytes)")
    if bad:
        sys.exit(1)
PY
