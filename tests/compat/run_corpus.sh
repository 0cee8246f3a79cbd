#!/usr/bin/env bash
# Runs toyhost-compat over the corpus at CI size; exit 77 (skipped) when the corpus is absent.
# Usage: run_corpus.sh COMPAT_BIN CORPUS_DIR KNOWN_TSV OUT_DIR
set -euo pipefail
compat="$1" corpus="$2" known="$3" out="$4"
if [ ! -d "$corpus" ]; then
  echo "corpus $corpus not found: skipped"
  exit 77
fi
mkdir -p "$out"
"$compat" "$corpus" --size 160x90 --frames 10 --min-pass-rate 0.95 --known "$known" \
  --markdown "$out/compat.md" --json "$out/compat.json" || {
  echo "fewer than 95% of $corpus pass; see $out/compat.md"
  exit 1
}
