#!/usr/bin/env bash
# The main job: installs what is missing, builds toyhost, and renders afl_ext's ocean (read from
# ../shared/shadertoys/MdXyzX) headless at 1280x720 into PNG files. FRAMES (default 60) and
# OUT (default out/ocean) may be set in the environment.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"

cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j"$(nproc)" --target toyhost

frames="${FRAMES:-60}"
out="${OUT:-$root/out/ocean}"
mkdir -p "$out"
"$root/build/tools/toyhost" run "$root/shadertoys/ocean" --headless --size 1280x720 \
  --frames "$frames" --out "$out/ocean_%04d.png"
echo "toyhost: the ocean frames are in $out (ocean_0000.png .. ocean_$(printf '%04d' $((frames - 1))).png)"
