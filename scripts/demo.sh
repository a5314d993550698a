#!/usr/bin/env bash
# Quick start 1: install what the build needs, build the skipnc binary (no
# tests: a few minutes on two cores, progress shown), run the probing demo on
# the built-in mill3.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh demo
echo "demo: building skipnc in build/ (the tests are built by scripts/test.sh)"
scripts/build.sh demo
echo
exec build/skipnc demo "$@"
