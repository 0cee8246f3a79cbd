#!/usr/bin/env bash
# Shows that check_sizes.sh fails on each defect it exists for: on a copy of runtime/ and of the
# allow-list it passes as the tree is (and with a new file exactly at its limit), and fails, naming
# the defect, with a new file one line over its limit, SessionCore.cpp one line past what it is
# allowed, an allow-list line for a file within its limit, for a file that does not exist, without a
# reason, with a limit no higher than the file's own, and twice for one file.
# Usage: check_sizes_selftest.sh SOURCE_DIR
set -euo pipefail
src="$(cd "$1" && pwd)"
check="$src/tests/arch/check_sizes.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0

# A copy of runtime/ and the allow-list, made once; copy() undoes what a case changed.
planted=runtime/core/PlantedLong.cpp
core=runtime/session/SessionCore.cpp
allowlist="$work/tree/tests/arch/size-allowlist.txt"
mkdir -p "$work/tree/tests/arch"
cp -r "$src/runtime" "$work/tree/"
copy() {
  rm -f "$work/tree/$planted"
  cp "$src/$core" "$work/tree/$core"
  cp "$src/tests/arch/size-allowlist.txt" "$allowlist"
}
# lines_file PATH N: PATH (relative to the copy) with N lines.
lines_file() { mkdir -p "$(dirname "$work/tree/$1")"; for ((i = 0; i < $2; i++)); do echo "// line"; done > "$work/tree/$1"; }

expect_pass() {
  local output
  if output="$("$check" "$work/tree" 2>&1)"; then
    echo "selftest: $1: passes as it should"
  else
    echo "selftest: $1: check_sizes.sh fails:"; echo "$output"; status=1
  fi
}
expect_failure() {
  local output
  if output="$("$check" "$work/tree" 2>&1)"; then
    echo "selftest: $1: check_sizes.sh passed a tree with the defect"; status=1
  elif ! grep -qF -- "$2" <<<"$output"; then
    echo "selftest: $1: check_sizes.sh failed without saying \"$2\":"; echo "$output"; status=1
  else
    echo "selftest: $1: fails as it should ($2)"
  fi
}

limit=$("$check" --limit-of "$planted")

copy; expect_pass unchanged
copy; lines_file "$planted" "$limit"; expect_pass at_the_limit
copy; lines_file "$planted" $((limit + 1)); expect_failure one_line_over "$planted has $((limit + 1)) lines, over its limit of $limit"

# SessionCore.cpp one line past what it may have: its allow-list line's limit, or its own.
allowed="$(awk -v path="$core" '$1 == path {print $2}' "$src/tests/arch/size-allowlist.txt")"
allowed="${allowed:-$("$check" --limit-of "$core")}"
copy; lines_file "$core" $((allowed + 1)); expect_failure session_core_grew "$core has $((allowed + 1)) lines"

# The smallest runtime file, to list while within its limit.
small="$(cd "$src" && find runtime -type f -name '*.h' -exec wc -l {} + | grep -v ' total$' | sort -n | head -1 | awk '{print $2}')"
copy; echo "$small $((limit + 100)) it was long once" >> "$allowlist"
expect_failure stale_line "$small has $(wc -l < "$src/$small") lines, within its limit"
copy; echo "runtime/core/Gone.cpp $((limit + 100)) it was split" >> "$allowlist"
expect_failure gone_file "runtime/core/Gone.cpp is not a runtime source file"
copy; lines_file "$planted" $((limit + 1)); echo "$planted $((limit + 1))" >> "$allowlist"
expect_failure no_reason "$planted has no reason"
copy; lines_file "$planted" $((limit + 1)); echo "$planted $limit generated" >> "$allowlist"
expect_failure limit_not_higher "$planted is allowed $limit lines, no more than its limit"
copy; lines_file "$planted" $((limit + 1)); printf '%s\n' "$planted $((limit + 1)) generated" "$planted $((limit + 2)) generated" >> "$allowlist"
expect_failure listed_twice "$planted is listed twice"
exit $status
