#!/usr/bin/env bash
# Capture and render benchmarks against the floor (tools/bench/floor_render.cpp), measured side by
# side in one run. Builds nothing: give it a build folder that has tools/toyhost and
# tools/bench/floor_render. Every case runs REPS times (toyhost and the floor interleaved) and the
# median is kept. Prints a table; with --write FILE it also replaces the results block of FILE
# (between "<!-- bench:begin -->" and "<!-- bench:end -->", e.g. docs/performance.md).
#
# usage: tools/bench/bench.sh BUILD_DIR [--write docs/performance.md] [--reps N] [--quick]
#
# Comparisons are like with like: on llvmpipe a draw that fully covers a tile discards the tile's
# queued work when nothing read it in between, so an unsynchronised render-only loop measures far
# less than the shading cost. Render-only runs therefore wait for the GPU after every frame on
# both sides (--finish-each-frame); capture runs read every frame back, which forces the same work.
set -euo pipefail

usage() { sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
build=$1; shift
write=""; reps=3; quick=0
while [ $# -gt 0 ]; do
  case $1 in
    --write) write=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    *) usage ;;
  esac
done

repo=$(cd "$(dirname "$0")/../.." && pwd)
toyhost=$build/tools/toyhost
floor=$build/tools/bench/floor_render
for program in "$toyhost" "$floor"; do
  [ -x "$program" ] || { echo "bench: $program is missing; build first (cmake --build $build)" >&2; exit 1; }
done
ocean_glsl=$repo/../shared/shadertoys/MdXyzX/image.glsl
[ -f "$ocean_glsl" ] || { echo "bench: needs ../shared/shadertoys (the ocean and Mountains & Lakes)" >&2; exit 1; }
ocean=$repo/shadertoys/ocean
lakes=$repo/shadertoys/mountains-lakes
trivial=$repo/shadertoys/bench-trivial
work=$(mktemp -d "${TMPDIR:-/tmp}/toyhost-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT

ocean_frames=30; trivial_frames=3000; lakes_frames=60; first_reps=$((reps + 2))
if [ "$quick" = 1 ]; then ocean_frames=8; trivial_frames=500; lakes_frames=20; fi

# --- measuring -------------------------------------------------------------------------------
# Seconds of toyhost's frame loop (GPU work and encoders included), from its report line.
# The summary says "first frame 16 ms, then 29 frames in 4.81 s (...)": the loop is both.
toyhost_seconds() {
  local line
  line=$("$toyhost" run "$@" --headless --quiet 2>&1 >/dev/null | grep ' frames at ') || { echo "bench: toyhost run $* failed" >&2; exit 1; }
  echo "$line" >"$work/report_line"
  awk '{
    for (i = 1; i < NF; i++) {
      if ($i == "frame" && $(i - 1) == "first") first = seconds($(i + 1), $(i + 2));
      if ($i == "in" && $(i - 1) == "frames" && $(i - 3) == "then") rest = seconds($(i + 1), $(i + 2));
    }
    printf "%.6f\n", first + rest
  }
  function seconds(value, unit) { sub(/[,(]/, "", unit); return unit ~ /^ms/ ? value / 1000 : value }' <<<"$line"
}
floor_seconds() {
  "$floor" "$@" | sed -E 's/.*seconds_total=([0-9.]+).*/\1/'
}
# Wall-clock seconds of a whole process, start to exit.
wall_seconds() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || { echo "bench: $* failed" >&2; exit 1; }
  end=$(date +%s.%N)
  awk "BEGIN {print $end - $start}"
}
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
calc() { awk "BEGIN {printf \"$1\", $2}"; }

declare -a rows
row() { rows+=("$(printf '| %s | %s | %s | %s | %s |' "$1" "$2" "$3" "$4" "$5")"); echo "  $1: $2 vs $3 -> $4 ($5)" >&2; }
verdict() { awk "BEGIN {print ($1) ? \"met\" : \"NOT met\"}"; }

# CPU time the whole machine spent busy, in clock ticks, and what this script's children used:
# the difference is load from elsewhere, which the table reports as the measurement's noise.
busy_ticks() { awk '/^cpu / {print $2 + $3 + $4 + $7 + $8 + $9}' /proc/stat; }
# `times` must run in this shell (a subshell starts with zeroed child times), hence the file.
children_seconds() {
  times >"$work/times"
  children=$(tail -1 "$work/times" | awk '{split($1, u, /[ms]/); split($2, s, /[ms]/); print u[1] * 60 + u[2] + s[1] * 60 + s[2]}')
}
busy_before=$(busy_ticks)
children_seconds; children_before=$children
started=$(date +%s)

# --- 1. render-only vs the floor: the ocean at 800x450 ----------------------------------------
echo "bench: ocean 800x450 render-only, $ocean_frames frames x $reps" >&2
t=(); f=()
for _ in $(seq "$reps"); do
  t+=("$(toyhost_seconds "$ocean" --size 800x450 --frames "$ocean_frames" --finish-each-frame)")
  f+=("$(floor_seconds "$ocean_glsl" --size 800x450 --time 0 --frames "$ocean_frames" --finish-each-frame)")
done
ocean_toyhost=$(median "${t[@]}"); ocean_floor=$(median "${f[@]}")
ratio=$(calc %.3f "$ocean_toyhost / $ocean_floor")
row "Render-only, ocean 800x450, toyhost / floor (both synced per frame)" \
    "$(calc %.1f "$ocean_toyhost * 1000 / $ocean_frames") ms/frame" "$(calc %.1f "$ocean_floor * 1000 / $ocean_frames") ms/frame" \
    "**$ratio**" "<= 1.02: $(verdict "$ratio <= 1.02")"

# --- 2. per-frame overhead: a trivial shader at 320x180 ---------------------------------------
echo "bench: trivial 320x180 render-only, $trivial_frames frames x $reps" >&2
t=(); f=()
for _ in $(seq "$reps"); do
  t+=("$(toyhost_seconds "$trivial" --size 320x180 --frames "$trivial_frames" --finish-each-frame)")
  f+=("$(floor_seconds "$trivial/image.glsl" --size 320x180 --time 0 --frames "$trivial_frames" --finish-each-frame)")
done
tt=$(median "${t[@]}"); tf=$(median "${f[@]}")
overhead=$(calc %.3f "($tt - $tf) * 1000 / $trivial_frames")
row "Per-frame overhead, trivial shader 320x180 (both synced per frame)" \
    "$(calc %.3f "$tt * 1000 / $trivial_frames") ms/frame" "$(calc %.3f "$tf * 1000 / $trivial_frames") ms/frame" \
    "**$overhead ms**" "<= 0.2 ms: $(verdict "$overhead <= 0.2")"

# --- 3. PNG capture of every frame vs render-only: the ocean at 800x450 -----------------------
echo "bench: ocean 800x450 PNG capture, $ocean_frames frames x $reps" >&2
r=(); a=(); s=(); two=(); raw=()
for _ in $(seq "$reps"); do
  # Render-only again, interleaved with the capture runs so that both see the same conditions.
  r+=("$(toyhost_seconds "$ocean" --size 800x450 --frames "$ocean_frames" --finish-each-frame)")
  rm -rf "$work/png"
  a+=("$(toyhost_seconds "$ocean" --size 800x450 --frames "$ocean_frames" --out "$work/png/a_%04d.png")")
  rm -rf "$work/png"
  s+=("$(toyhost_seconds "$ocean" --size 800x450 --frames "$ocean_frames" --out "$work/png/s_%04d.png" --sync-capture)")
  rm -rf "$work/png"
  two+=("$(toyhost_seconds "$ocean" --size 800x450 --frames "$ocean_frames" --out "$work/png/t_%04d.png" --encoder-threads 2)")
  raw+=("$(toyhost_seconds "$ocean" --size 800x450 --frames "$ocean_frames" --out -)")  # stdout: /dev/null
done
ocean_toyhost=$(median "${r[@]}")
png=$(median "${a[@]}"); png_sync=$(median "${s[@]}"); png_two=$(median "${two[@]}"); raw_out=$(median "${raw[@]}")
ratio=$(calc %.3f "$png / $ocean_toyhost")
row "PNG capture of every frame / render-only, ocean 800x450 (async, $(nproc) cores: 1 encoder thread)" \
    "$(calc %.1f "$png * 1000 / $ocean_frames") ms/frame" "$(calc %.1f "$ocean_toyhost * 1000 / $ocean_frames") ms/frame" \
    "**$ratio**" "<= 1.10: $(verdict "$ratio <= 1.10")"
row "same, 2 encoder threads (for choosing the default)" \
    "$(calc %.1f "$png_two * 1000 / $ocean_frames") ms/frame" "$(calc %.1f "$ocean_toyhost * 1000 / $ocean_frames") ms/frame" \
    "$(calc %.3f "$png_two / $ocean_toyhost")" "information"
row "same, --sync-capture (readback and encoding on the render thread)" \
    "$(calc %.1f "$png_sync * 1000 / $ocean_frames") ms/frame" "$(calc %.1f "$ocean_toyhost * 1000 / $ocean_frames") ms/frame" \
    "$(calc %.3f "$png_sync / $ocean_toyhost")" "information"
row "Raw RGBA to stdout (/dev/null) / render-only: readback without encoding" \
    "$(calc %.1f "$raw_out * 1000 / $ocean_frames") ms/frame" "$(calc %.1f "$ocean_toyhost * 1000 / $ocean_frames") ms/frame" \
    "$(calc %.3f "$raw_out / $ocean_toyhost")" "information"

# --- 4. Mountains & Lakes: capture every 10th frame vs every frame ----------------------------
echo "bench: Mountains & Lakes 800x450, $lakes_frames frames x $reps" >&2
e10=(); e1=()
for _ in $(seq "$reps"); do
  rm -rf "$work/ml"
  e10+=("$(toyhost_seconds "$lakes" --size 800x450 --frames "$lakes_frames" --capture-every 10 --out "$work/ml/a_%04d.png")")
  rm -rf "$work/ml"
  e1+=("$(toyhost_seconds "$lakes" --size 800x450 --frames "$lakes_frames" --capture-every 1 --out "$work/ml/b_%04d.png")")
done
m10=$(median "${e10[@]}"); m1=$(median "${e1[@]}")
row "Mountains & Lakes 800x450, PNG every 10th frame vs every frame" \
    "$(calc %.1f "$lakes_frames / $m10") frames/s" "$(calc %.1f "$lakes_frames / $m1") frames/s" \
    "$(calc %.2fx "$m1 / $m10") faster" "Image rendered only on captured frames"

# --- 5. time to the first frame ----------------------------------------------------------------
echo "bench: time to first frame, ocean 800x450 x $first_reps" >&2
t=(); f=()
for _ in $(seq "$first_reps"); do
  t+=("$(wall_seconds "$toyhost" run "$ocean" --size 800x450 --frames 1 --headless --quiet)")
  f+=("$(wall_seconds "$floor" "$ocean_glsl" --size 800x450 --time 0 --frames 1)")
done
ft=$(median "${t[@]}"); ff=$(median "${f[@]}")
delta=$(calc %.0f "($ft - $ff) * 1000")
row "Time to first frame, ocean 800x450 (whole process, start to exit, 1 frame)" \
    "$(calc %.0f "$ft * 1000") ms" "$(calc %.0f "$ff * 1000") ms" "**+$delta ms**" "<= +50 ms: $(verdict "$delta <= 50")"

# --- 6. for reference: unsynchronised render-only on both sides --------------------------------
echo "bench: ocean 800x450 render-only without per-frame sync x $reps" >&2
t=(); f=()
for _ in $(seq "$reps"); do
  t+=("$(toyhost_seconds "$ocean" --size 800x450 --frames "$ocean_frames")")
  f+=("$(floor_seconds "$ocean_glsl" --size 800x450 --time 0 --frames "$ocean_frames")")
done
ut=$(median "${t[@]}"); uf=$(median "${f[@]}")
row "Render-only without per-frame sync (llvmpipe skips overwritten frames; not a shading cost)" \
    "$(calc %.1f "$ut * 1000 / $ocean_frames") ms/frame" "$(calc %.1f "$uf * 1000 / $ocean_frames") ms/frame" \
    "$(calc %.3f "$ut / $uf")" "information"

# --- the table -----------------------------------------------------------------------------------
mesa=$(sed -E 's/.* on (.*): start-up .*$/\1/' "$work/report_line")
cpu=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
elapsed=$(( $(date +%s) - started ))
children_seconds
other_cpu=$(awk -v busy="$(( $(busy_ticks) - busy_before ))" -v hz="$(getconf CLK_TCK)" \
  -v own="$(awk "BEGIN {print $children - $children_before}")" -v wall="$elapsed" -v cores="$(nproc)" \
  'BEGIN {other = busy / hz - own; if (other < 0) other = 0; printf "%.0f%%", 100 * other / (wall * cores)}')
commit=$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$repo" diff --quiet HEAD 2>/dev/null || commit="$commit with uncommitted changes"
table=$(cat <<END
Measured $(date -u +%Y-%m-%d) on: $cpu, $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo) RAM; $mesa.
toyhost $commit; medians of $reps runs ($first_reps for the first frame); bench took ${elapsed} s; CPU used by other processes meanwhile: $other_cpu of the machine.

| Case | toyhost | compared with | ratio | target |
| --- | --- | --- | --- | --- |
$(printf '%s\n' "${rows[@]}")
END
)
echo
echo "$table"

if [ -n "$write" ]; then
  [ -f "$write" ] || { echo "bench: $write does not exist" >&2; exit 1; }
  grep -q '<!-- bench:begin -->' "$write" && grep -q '<!-- bench:end -->' "$write" ||
    { echo "bench: $write has no <!-- bench:begin --> / <!-- bench:end --> markers" >&2; exit 1; }
  tmp=$(mktemp "$write.XXXXXX")
  TABLE="$table" awk '
    /<!-- bench:begin -->/ { print; print ""; print ENVIRON["TABLE"]; print ""; skipping = 1; next }
    /<!-- bench:end -->/   { skipping = 0 }
    !skipping { print }' "$write" >"$tmp"
  mv "$tmp" "$write"
  echo "bench: results written to $write" >&2
fi
