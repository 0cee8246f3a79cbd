#!/usr/bin/env bash
# The side-by-side crops of docs/sampling.md: the ocean (../shared/shadertoys/MdXyzX) at 320x180,
# one sample per pixel against --supersample 4 (the horizon's stair steps and sparkle), and a still
# frame against --motion-blur 16 with a 180-degree shutter at 6 fps (the waves moving), each crop enlarged 4x
# without smoothing so that the pixels show. Needs a build with tools/toyhost and ffmpeg.
#
# usage: scripts/sampling-crops.sh BUILD_DIR [OUT_DIR (default docs/sampling)]
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
build=$1
repo=$(cd "$(dirname "$0")/.." && pwd)
out=${2:-$repo/docs/sampling}
toyhost=$build/tools/toyhost
[ -x "$toyhost" ] || { echo "sampling-crops: $toyhost is missing; build first" >&2; exit 1; }
command -v ffmpeg >/dev/null || { echo "sampling-crops: needs ffmpeg (apt-get install ffmpeg)" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/toyhost-crops.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# One frame (iTime 1.0: frame FPS at FPS frames a second) of the ocean with extra flags, as a PNG.
still() {
  local name=$1 fps=$2; shift 2
  "$toyhost" run "$repo/shadertoys/ocean" --headless --quiet --size 320x180 --fps "$fps" --frames $((fps + 1)) \
    --capture-every "$fps" --date 2024-01-01T12:00:00 "$@" --out "$work/${name}_%d.png"
  mv "$work/${name}_$fps.png" "$work/$name.png"
}
# Two crops (W x H at X,Y) side by side, each enlarged 4x with nearest-neighbour scaling.
pair() {
  local a=$1 b=$2 crop=$3 result=$4
  ffmpeg -loglevel error -y -i "$work/$a.png" -i "$work/$b.png" -filter_complex \
    "[0]crop=$crop,scale=iw*4:ih*4:flags=neighbor,pad=iw+8:ih:0:0:white[l];[1]crop=$crop,scale=iw*4:ih*4:flags=neighbor[r];[l][r]hstack" \
    "$result"
}

# Anti-aliasing at the horizon (30 fps); motion blur of the near waves at 6 fps, where a
# 180-degree shutter is open 1/12 s (the waves move visibly in that time).
still one 30
still supersampled 30 --supersample 4
still slow 6
still blurred 6 --motion-blur 16 --shutter 180
pair one supersampled 96:54:112:70 "$out/ocean-supersample.png"
pair slow blurred 96:54:112:120 "$out/ocean-motion-blur.png"
echo "sampling-crops: wrote $out/ocean-supersample.png and $out/ocean-motion-blur.png"
