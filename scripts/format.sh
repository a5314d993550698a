#!/usr/bin/env bash
# Formats the C++ sources that git tracks with clang-format (the style is in
# .clang-format; Debian's clang-format package).
# Usage: scripts/format.sh          format in place
#        scripts/format.sh --check  change nothing; list what is not formatted, exit 1 if any
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
if [ "${1:-}" = --check ]; then
  if ! out=$(clang-format --dry-run --Werror "${files[@]}" 2>&1); then
    echo "$out" | grep -E '^[^ ].*(warning|error):' | cut -d: -f1 | sort -u | sed 's/^/not formatted: /' >&2
    echo "format.sh: run scripts/format.sh to format them" >&2
    exit 1
  fi
  echo "format: ${#files[@]} files formatted"
else
  clang-format -i "${files[@]}"
fi
