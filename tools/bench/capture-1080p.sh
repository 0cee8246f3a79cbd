#!/usr/bin/env bash
# The capture acceptance benchmark (issue 19): bench-trivial at 1920x1080, whole processes
# (start-up included), raw RGBA to stdout vs a PNG of every frame, run alternately PAIRS times;
# prints the medians (wall and CPU seconds), the PNG/raw ratio, the PNG files' total size and
# whether every PNG decodes (ffmpeg) to exactly the raw stream's pixels. With --base OTHER_TOYHOST
# the same pairs run for a second binary (e.g. a build of an older commit) interleaved with the
# first.
#
# usage: tools/bench/capture-1080p.sh BUILD_DIR [--base TOYHOST] [--pairs N] [--frames N] [--png-level L]
set -euo pipefail

usage() { sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
build=$1; shift
base=""; pairs=5; frames=240; level=1
while [ $# -gt 0 ]; do
  case $1 in
    --base) base=$2; shift 2 ;;
    --pairs) pairs=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --png-level) level=$2; shift 2 ;;
    *) usage ;;
  esac
done
repo=$(cd "$(dirname "$0")/../.." && pwd)
shader=$repo/shadertoys/bench-trivial
work=$(mktemp -d "${TMPDIR:-/tmp}/toyhost-capture-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
declare -A binaries=([new]=$build/tools/toyhost)
[ -n "$base" ] && binaries[base]=$base
for name in "${!binaries[@]}"; do
  [ -x "${binaries[$name]}" ] || { echo "capture-1080p: ${binaries[$name]} is missing" >&2; exit 1; }
done

args=(run "$shader" --headless --quiet --size 1920x1080 --frames "$frames")
# "WALL CPU": seconds of a whole process, wall clock and CPU (user + sys, from /usr/bin/time; "-"
# where it is not installed). On a shared machine the CPU seconds move far less with the load.
wall() {
  local start end cpu=-
  start=$(date +%s.%N)
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -f '%U %S' -o "$work/cpu" "$@" >/dev/null 2>&1 </dev/null || { echo "capture-1080p: $* failed" >&2; exit 1; }
    cpu=$(awk '{printf "%.2f", $1 + $2}' "$work/cpu")
  else
    "$@" >/dev/null 2>&1 </dev/null || { echo "capture-1080p: $* failed" >&2; exit 1; }
  fi
  end=$(date +%s.%N)
  awk "BEGIN {printf \"%.3f %s\", $end - $start, \"$cpu\"}"
}
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

declare -A raw png rawcpu pngcpu sizes ratios same
echo "load before: $(uptime | sed 's/.*load average/load average/')" >&2
for ((i = 1; i <= pairs; i++)); do
  for name in $(printf '%s\n' "${!binaries[@]}" | sort); do
    toyhost=${binaries[$name]}
    read -r r rc <<<"$(wall "$toyhost" "${args[@]}" --out -)"
    rm -rf "$work/$name"; mkdir -p "$work/$name"
    read -r p pc <<<"$(wall "$toyhost" "${args[@]}" --png-level "$level" --out "$work/$name/f_%04d.png")"
    raw[$name]+="$r "; png[$name]+="$p "; rawcpu[$name]+="$rc "; pngcpu[$name]+="$pc "
    ratios[$name]+="$(awk "BEGIN {printf \"%.3f\", $p / $r}") "
    sizes[$name]=$(du -cb "$work/$name"/*.png | tail -1 | cut -f1)
    echo "  pair $i $name: raw $r s (CPU $rc s), png $p s (CPU $pc s)" >&2
  done
done
echo "load after: $(uptime | sed 's/.*load average/load average/')" >&2

# Every PNG of the last run decodes to the raw stream's bytes.
for name in "${!binaries[@]}"; do
  toyhost=${binaries[$name]}
  "$toyhost" "${args[@]}" --out - 2>/dev/null >"$work/$name.raw"
  ffmpeg -v error -i "$work/$name/f_%04d.png" -f rawvideo -pix_fmt rgba - >"$work/$name.decoded"
  if cmp -s "$work/$name.raw" "$work/$name.decoded"; then same[$name]="yes"; else same[$name]="NO"; fi
done

cpu_median() { case " $* " in *" - "*) echo "-" ;; *) median "$@" ;; esac; }
printf '| binary | raw s (median) | PNG s (median) | PNG/raw (median of pairs) | raw CPU s | PNG CPU s | PNG frames/s | PNG bytes | frames decode to raw |\n|---|---|---|---|---|---|---|---|---|\n'
for name in $(printf '%s\n' "${!binaries[@]}" | sort); do
  # shellcheck disable=SC2086
  r=$(median ${raw[$name]}); p=$(median ${png[$name]}); q=$(median ${ratios[$name]})
  # shellcheck disable=SC2086
  rc=$(cpu_median ${rawcpu[$name]}); pc=$(cpu_median ${pngcpu[$name]})
  printf '| %s | %s | %s | %s | %s | %s | %.1f | %s | %s |\n' "$name" "$r" "$p" "$q" "$rc" "$pc" \
    "$(awk "BEGIN {print $frames / $p}")" "${sizes[$name]}" "${same[$name]}"
done
