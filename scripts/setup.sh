#!/usr/bin/env bash
# Installs what skipnc needs, from Debian packages.
# Usage: scripts/setup.sh [demo|all]
#   demo  only what building the skipnc binary needs (scripts/demo.sh)
#   all   (default) also the tests, the Python module, the benchmarks, the
#         plot page test (Chromium), the check build and fuzz stage (clang 16)
#         and the formatting check (clang-format), the function-length
#         check (universal-ctags)
# Idempotent: packages already present are left alone.
set -euo pipefail
what=${1:-all}
# ccache: a second build (another clone, a clean tree) takes its objects from the cache.
build=(cmake ninja-build g++ ccache libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev)
case $what in
  demo) pkgs=("${build[@]}") ;;
  all)
    pkgs=("${build[@]}" pkg-config libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
          python3
          # the Python module (python/) and its tests, the example, Dask sweeps
          python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib
          python3-distributed
          # pip install . (the Python package, offline, setuptools driving CMake)
          python3-venv python3-pip python3-setuptools
          # the plot page test (tests/browser/plot_page_test.py): headless Chromium
          chromium
          # the check build (scripts/build.sh check): clang 16 with its ASan, UBSan,
          # TSan and libFuzzer runtimes; the formatting check
          clang-16 libclang-rt-16-dev clang-format
          # the function-length check (scripts/function_length.sh)
          universal-ctags) ;;
  *) echo "setup.sh: unknown set '$what' (demo, all)" >&2; exit 2 ;;
esac
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
