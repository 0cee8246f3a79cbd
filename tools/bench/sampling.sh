#!/usr/bin/env bash
# The cost of a sample (--supersample, --motion-blur): N x N samples of a frame against N x N
# render-only frames of the same shader, on the ocean at 320x180 (the issue's goal: at most 1.05x)
# and on a trivial shader (where the accumulation itself would show). Every case runs REPS times,
# the sampled and the plain run interleaved, and the medians are compared; the CPU time of each
# run is printed beside its wall time. Builds nothing: give it a build folder with tools/toyhost.
#
# usage: tools/bench/sampling.sh BUILD_DIR [--reps N] [--frames F]
set -euo pipefail

usage() { sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
build=$1; shift
reps=5; frames=6
while [ $# -gt 0 ]; do
  case $1 in
    --reps) reps=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    *) usage ;;
  esac
done
repo=$(cd "$(dirname "$0")/../.." && pwd)
toyhost=$build/tools/toyhost
[ -x "$toyhost" ] || { echo "sampling.sh: $toyhost is missing; build first" >&2; exit 1; }
[ -f "$repo/../shared/shadertoys/MdXyzX/image.glsl" ] || { echo "sampling.sh: needs ../shared/shadertoys" >&2; exit 1; }

# The one-sample run renders samples x frames frames, the sampled one `frames` frames: both draw
# the Image pass as often, so the ratio of their times is the cost of a sample against a frame.
# Seconds of the frame loop (first frame and the rest, GPU work included: --finish-each-frame),
# and the CPU seconds of the whole process (user + system), as "wall cpu".
# The first argument is the frame count.
measure() {
  local out count=$1; shift
  out=$( { /usr/bin/time -f 'cpu %U %S' "$toyhost" run "$@" --headless --finish-each-frame --size 320x180 \
            --frames "$count" --date 2024-01-01T00:00:00 2>&1 >/dev/null; } ) || { echo "sampling.sh: run $* failed" >&2; exit 1; }
  awk '
    / frames at / {
      for (i = 1; i < NF; i++) {
        if ($i == "frame" && $(i - 1) == "first") first = seconds($(i + 1), $(i + 2));
        if ($i == "in" && $(i - 1) == "frames" && $(i - 3) == "then") rest = seconds($(i + 1), $(i + 2));
      }
    }
    /^cpu / { cpu = $2 + $3 }
    END { printf "%.6f %.3f\n", first + rest, cpu }
    function seconds(value, unit) { sub(/[,(]/, "", unit); return unit ~ /^ms/ ? value / 1000 : value }' <<<"$out"
}
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

echo "| shader (320x180) | samples a frame | one sample: samples x $frames frames, loop s (process CPU s) | sampled: $frames frames, loop s (process CPU s) | cost of a sample / a frame |"
echo "|---|---|---|---|---|"
for shader in ocean bench-trivial; do
  for n in 2 4; do
    samples=$((n * n))
    plain=(); plaincpu=(); sampled=(); sampledcpu=()
    for ((r = 0; r < reps; r++)); do
      read -r w c < <(measure $((frames * samples)) "$repo/shadertoys/$shader"); plain+=("$w"); plaincpu+=("$c")
      read -r w c < <(measure "$frames" "$repo/shadertoys/$shader" --supersample "$n"); sampled+=("$w"); sampledcpu+=("$c")
    done
    p=$(median "${plain[@]}"); pc=$(median "${plaincpu[@]}")
    s=$(median "${sampled[@]}"); sc=$(median "${sampledcpu[@]}")
    ratio=$(awk "BEGIN {printf \"%.3f\", $s / $p}")
    printf '| %s | %d | %.3f (%.2f) | %.3f (%.2f) | %s |\n' "$shader" "$samples" "$p" "$pc" "$s" "$sc" "$ratio"
  done
done
