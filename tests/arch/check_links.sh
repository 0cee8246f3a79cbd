#!/usr/bin/env bash
# Fails when the executable links a shared library whose name matches the pattern (e.g. GL or EGL
# for the pure unit tests). Usage: check_links.sh EXECUTABLE PATTERN
set -euo pipefail
exe="$1" pattern="$2"
found="$(ldd "$exe" | grep -E "$pattern" || true)"
if [[ -n "$found" ]]; then
  echo "$(basename "$exe") links what it must not:"
  echo "$found"
  exit 1
fi
echo "$(basename "$exe") links none of: $pattern"
