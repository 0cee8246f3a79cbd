#!/usr/bin/env bash
# The side-by-side crops of docs/sampling.md: the ocean (../shared/shadertoys/MdXyzX) at 320x180,
# one sample per pixel against --supersample 4 (the horizon's stair steps and sparkle), and a still
# frame against --motion-blur 8 with a 180-degree shutter (the waves moving), each crop enlarged 4x
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

# One frame (frame 30 at 30 fps: iTime 1.0) of the ocean with extra flags, as a PNG.
still() {
  local name=$1; shift
  "$toyhost" run "$repo/shadertoys/ocean" --headless --quiet --size 320x180 --fps 30 --frames 31 \
    --capture-every 30 --date 2024-01-01T12:00:00 "$@" --out "$work/${name}_%d.png"
  mv "$work/${name}_30.png" "$work/$name.png"
}
# Two crops (W x H at X,Y) side by side, each enlarged 4x with nearest-neighbour scaling.
pair() {
  local a=$1 b=$2 crop=$3 result=$4
  ffmpeg -loglevel error -y -i "$work/$a.png" -i "$work/$b.png" -filter_complex \
    "[0]crop=$crop,scale=iw*4:ih*4:flags=neighbor,pad=iw+8:ih:0:0:white[l];[1]crop=$crop,scale=iw*4:ih*4:flags=neighbor[r];[l][r]hstack" \
    "$result"
}

still one
still supersampled --supersample 4
still blurred --motion-blur 8 --shutter 180
pair one supersampled 96:54:112:40 "$out/ocean-supersample.png"
pair one blurred 96:54:112:100 "$out/ocean-motion-blur.png"
echo "sampling-crops: wrote $out/ocean-supersample.png and $out/ocean-motion-blur.png"
