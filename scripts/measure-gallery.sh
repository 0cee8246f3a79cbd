#!/usr/bin/env bash
# Measures the six water ports as issue 20 defines it: 640x360, --fps 30 --start-time 3, 4 frames,
# then tests/support/FrameMeasures.h's numbers (toyhost_frame_measures). Usage:
#   scripts/measure-gallery.sh [BUILD_DIR] [PORT...]     (frames are left in BUILD_DIR/gallery-measures)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}; shift || true
ports=("$@")
[ ${#ports[@]} -gt 0 ] || ports=(exp-sine-ocean raymarched-sea lake-optics caustics-pool ripple-pool coastal-foam exp-sine-ocean@down)
size=${SIZE:-640x360}   # SIZE=320x180 for the size the tests use; PORTS_DIR=another copy of shadertoys/
out=$build/gallery-measures
mkdir -p "$out"
for entry in "${ports[@]}"; do
  port=${entry%@*}
  extra=()
  case $entry in
    *@down) extra=(--mouse "$(( ${size%x*} / 2 )),10") ;;   # exp-sine-ocean looking down (banding)
    ripple-pool) extra=(--mouse-script "$root/shadertoys/ripple-pool/drag.json") ;;
  esac
  name=${entry//@/-}
  rm -f "$out/$name"_*.png
  "$build/tools/toyhost" run "${PORTS_DIR:-$root/shadertoys}/$port" --size "$size" --fps 30 --start-time 3 --frames 4 \
    --quiet "${extra[@]}" --out "$out/${name}_%04d.png"
  printf '%-22s ' "$name"
  "$build/tests/toyhost_frame_measures" "$out/$name"_000{0,1,2,3}.png
done
