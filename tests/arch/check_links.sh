#!/usr/bin/env bash
# Fails when the executable links a shared library whose name matches the pattern (e.g. GL or EGL
# for the pure unit tests). Usage: check_links.sh EXECUTABLE PATTERN
set -euo pipefail
exe="$1" pattern="$2"
# A missing or unreadable executable is a failure, not "links nothing".
libraries="$(ldd "$exe")" || { echo "check_links.sh: cannot list the libraries of $exe" >&2; exit 1; }
found="$(grep -E "$pattern" <<<"$libraries" || true)"
if [[ -n "$found" ]]; then
  echo "$(basename "$exe") links what it must not:"
  echo "$found"
  exit 1
fi
echo "$(basename "$exe") links none of: $pattern"
