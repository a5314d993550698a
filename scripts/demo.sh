#!/usr/bin/env bash
# Quick start 1: set up, build, and run the probing demo on the built-in mill3.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh release >/dev/null
exec build/skipnc demo "$@"
