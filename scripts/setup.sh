#!/usr/bin/env bash
# Installs what skipnc needs to build and test, from Debian packages.
# Idempotent: packages already present are left alone.
set -euo pipefail
pkgs=(cmake ninja-build g++ pkg-config libfmt-dev libcli11-dev libtomlplusplus-dev
      nlohmann-json3-dev libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
      python3
      # the plot page test (tests/browser/plot_page_test.py): headless Chromium
      chromium
      # the fuzz stage (scripts/fuzz.sh): libFuzzer, ASan and UBSan of clang 16
      clang-16 libclang-rt-16-dev)
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
