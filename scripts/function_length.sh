#!/usr/bin/env bash
# Lists the functions of src/ and python/ longer than 80 lines (from the line
# of their name to their closing brace, as universal-ctags sees them) and
# fails when one is not in the allow-list, or when a function of the list is
# no longer that long (the list only shrinks).
# The allow-list (scripts/function_length.allow): one function a line, as
# "<file> <function>", '#' comments; the long functions that are still being
# split.
# Usage: scripts/function_length.sh [--list]
#   --list  print every function over 80 lines ("<lines> <file> <function>"), exit 0
# Exit status: 0 none outside the list, 1 a function to split or a stale
# line of the list, 77 universal-ctags missing (Debian package universal-ctags).
set -euo pipefail
cd "$(dirname "$0")/.."
limit=80
allow=scripts/function_length.allow
if ! ctags --version 2>/dev/null | grep -q 'Universal Ctags'; then
  echo "function_length.sh: needs universal-ctags (scripts/setup.sh installs it)" >&2
  exit 77
fi
# "<lines> <file> <function>" for every function over the limit.
long=$(ctags -R --languages=C++ --kinds-C++=f --fields=+ne --output-format=u-ctags -f - src python |
  awk -F'\t' -v limit="$limit" '{
    l = ""; e = ""
    for (i = 4; i <= NF; i++) {
      if ($i ~ /^line:/) l = substr($i, 6)
      if ($i ~ /^end:/) e = substr($i, 5)
    }
    if (e != "" && e - l + 1 > limit) print e - l + 1, $2, $1
  }' | sort -k2,2 -k3,3)
if [ "${1:-}" = --list ]; then
  [ -n "$long" ] && echo "$long"
  exit 0
fi
# (grep finds no line once the list is empty: not an error.)
listed=$({ grep -v '^[[:space:]]*\(#\|$\)' "$allow" || true; } | awk '{print $1, $2}' | sort -u)
found=$(echo "$long" | awk 'NF {print $2, $3}' | sort -u)
status=0
while read -r n file name; do
  [ -n "$n" ] || continue
  if ! grep -qxF "$file $name" <<<"$listed"; then
    echo "function_length: $file: $name is $n lines (at most $limit): split it" >&2
    status=1
  fi
done <<<"$long"
while read -r file name; do
  [ -n "$file" ] || continue
  if ! grep -qxF "$file $name" <<<"$found"; then
    echo "function_length: $allow lists '$file $name', which is not over $limit lines now: take the line out" >&2
    status=1
  fi
done <<<"$listed"
if [ "$status" -eq 0 ]; then
  echo "function_length: no function over $limit lines outside $allow ($(grep -c . <<<"$listed" || true) listed)"
fi
exit "$status"
