#!/usr/bin/env bash
# `toyhost-compat --results`: two runs over parts of a folder (written as --json) make one table,
# in id order, without running anything again.
# Usage: run_results_merge.sh COMPAT_BIN TESTS_COMPAT_DIR OUT_DIR
set -euo pipefail
compat="$1" shaders="$2" out="$3"
rm -rf "$out"
mkdir -p "$out"
"$compat" "$shaders/flash" --json "$out/a.json" --min-pass-rate 1
"$compat" "$shaders/frozen" --json "$out/b.json" || true  # fails: one colour, never changing
"$compat" parts --results "$out/b.json" "$out/a.json" --markdown "$out/table.md" --json "$out/all.json" || true
grep -q '^\*\*1 of 2 pass' "$out/table.md" || { echo "expected 1 of 2 passing"; cat "$out/table.md"; exit 1; }
rows="$(grep -E '^\| (flash|frozen) ' "$out/table.md" | cut -d'|' -f2 | tr -d ' ' | tr '\n' ' ')"
[ "$rows" = "flash frozen " ] || { echo "rows out of order or missing: '$rows'"; exit 1; }
grep -q '"total": 2' "$out/all.json" || { echo "merged JSON lacks both results"; exit 1; }
echo "merged table ok"
