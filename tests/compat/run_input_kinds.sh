#!/usr/bin/env bash
# Runs toyhost-compat over real shaders from ../shared/corpus/wild that use each input kind and
# pass type beyond textures and buffers (one or two per kind: video, webcam, music, musicstream,
# mic, cubemap, a Sound pass); every one must pass. Exit 77 (skipped) when the corpus is absent.
# Usage: run_input_kinds.sh COMPAT_BIN WILD_DIR OUT_DIR
set -euo pipefail
compat="$1" wild="$2" out="$3"
if [ ! -d "$wild" ]; then
  echo "corpus $wild not found: skipped"
  exit 77
fi
# video: 7dyfzW; webcam: Dty3Rh; music: ds3BW7; musicstream: 7tBcDy; mic: fd3yW8;
# cubemap: 7tKfz1 (Uffizi), Dd2SWh (St Peter's); Sound pass: 7sScWy, DsySRm.
ids=(7dyfzW Dty3Rh ds3BW7 7tBcDy fd3yW8 7tKfz1 Dd2SWh 7sScWy DsySRm)
rm -rf "$out/exports"
mkdir -p "$out/exports"
for id in "${ids[@]}"; do
  [ -f "$wild/$id.json" ] || { echo "missing $wild/$id.json"; exit 1; }
  ln -s "$wild/$id.json" "$out/exports/$id.json"
done
"$compat" "$out/exports" --size 160x90 --frames 10 --min-pass-rate 1 \
  --markdown "$out/input-kinds.md" --json "$out/input-kinds.json" 2> "$out/stderr.txt" || {
  cat "$out/stderr.txt" >&2
  echo "a shader of a new input kind did not pass; see $out/input-kinds.md"
  exit 1
}
cat "$out/stderr.txt" >&2
# The lines on stderr say what their "other" column is (issue 27).
grep -q '"other" (the share of the last judged frame' "$out/stderr.txt" || {
  echo "toyhost-compat's per-shader lines do not explain their \"other\" column"
  exit 1
}
