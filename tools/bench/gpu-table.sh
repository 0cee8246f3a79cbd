#!/usr/bin/env bash
# The GPU capture table (issue 19; docs/performance.md): the ocean and Mountains & Lakes at 1920x1080
# and 3840x2160, render-only (toyhost and the floor, synced per frame and not), raw RGBA to stdout,
# PNG (--png-level 1), EXR (exact 32-bit and --exr-half), mp4 with libx264 (default medium and
# veryfast), and with --codec auto (h264_nvenc where the GPU has an encoder). Whole processes; each case REPS times, cases
# interleaved rep by rep. Prints a Markdown table: frames per second of the frame loop (start-up
# excluded; encoders flushed) and the whole process's wall time. Not a test.
#
# usage: tools/bench/gpu-table.sh --toyhost PATH --floor PATH [--reps N] [--work DIR]
#                                 [--sizes "1920x1080 3840x2160"] [--frames N_AT_1080P] [--log FILE]
#                                 [--shaders "ocean mountains-lakes"] (folders in shadertoys/)
# Needs ../shared/shadertoys beside the repository (the originals), ffmpeg on PATH for the videos,
# and TOYHOST_EGL_PLATFORM=device on an NVIDIA machine (the floor reads it too).
set -euo pipefail
usage() { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
shaders="ocean mountains-lakes" toyhost="" floor="" reps=2 work="" sizes="1920x1080 3840x2160" log=/dev/null frames1080=120
while [ $# -gt 0 ]; do
  case $1 in
    --toyhost) toyhost=$2; shift 2 ;;
    --floor) floor=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --frames) frames1080=$2; shift 2 ;;
    --log) log=$2; shift 2 ;;
    --shaders) shaders=$2; shift 2 ;;
    *) usage ;;
  esac
done
[ -x "$toyhost" ] && [ -x "$floor" ] || usage
repo=$(cd "$(dirname "$0")/../.." && pwd)
ocean_glsl=$repo/../shared/shadertoys/MdXyzX/image.glsl
[ -f "$ocean_glsl" ] || { echo "gpu-table: needs ../shared/shadertoys beside the repository" >&2; exit 1; }
[ -n "$work" ] || work=$(mktemp -d "${TMPDIR:-/tmp}/toyhost-gpu.XXXXXX")
mkdir -p "$work"
: >"$log"

# Frames per case: the 1080p count, a quarter of it at 4K (the pixels are 4x), EXR (133 MB a 4K
# frame in 32-bit float) half of that.
frames_for() { # SIZE CASE
  local n=$frames1080
  [ "$1" = 3840x2160 ] && n=$((n / 4))
  case $2 in exr*) n=$((n / 2)) ;; esac
  [ "$n" -ge 8 ] || n=8
  echo "$n"
}

# Runs one case; prints "LOOP_SECONDS WALL_SECONDS" (loop: first frame + the rest, from toyhost's
# report; the floor prints seconds_total). Failure prints "fail fail" and logs why.
run_case() { # SHADER SIZE CASE FRAMES
  local shader=$1 size=$2 case=$3 frames=$4 dir=$repo/shadertoys/$1 out=$work/out
  rm -rf "$out"; mkdir -p "$out"
  local args=(run "$dir" --headless --size "$size" --frames "$frames")
  local cmd=()
  case $case in
    render-sync) cmd=("$toyhost" "${args[@]}" --finish-each-frame) ;;
    render) cmd=("$toyhost" "${args[@]}") ;;
    floor-sync) cmd=("$floor" "$ocean_glsl" --size "$size" --time 0 --frames "$frames" --finish-each-frame) ;;
    floor) cmd=("$floor" "$ocean_glsl" --size "$size" --time 0 --frames "$frames") ;;
    raw) cmd=("$toyhost" "${args[@]}" --out -) ;;
    png) cmd=("$toyhost" "${args[@]}" --png-level 1 --out "$out/f_%04d.png") ;;
    exr) cmd=("$toyhost" "${args[@]}" --out "$out/f_%04d.exr") ;;
    exr-half) cmd=("$toyhost" "${args[@]}" --exr-half --out "$out/f_%04d.exr") ;;
    x264) cmd=("$toyhost" "${args[@]}" --out "$out/v.mp4") ;;
    x264-veryfast) cmd=("$toyhost" "${args[@]}" --codec libx264 --video-preset veryfast --out "$out/v.mp4") ;;
    auto) cmd=("$toyhost" "${args[@]}" --codec auto --out "$out/v.mp4") ;;
  esac
  local start end status=0
  start=$(date +%s.%N)
  if [ "$case" = raw ]; then "${cmd[@]}" >/dev/null 2>"$work/err" || status=$?
  else "${cmd[@]}" >"$work/stdout" 2>"$work/err" || status=$?; fi
  end=$(date +%s.%N)
  { echo "== $shader $size $case ($frames frames): exit $status"; cat "$work/err"; } >>"$log"
  if [ "$status" != 0 ]; then echo "fail fail"; return; fi
  local loop
  if [[ $case == floor* ]]; then
    loop=$(sed -nE 's/.*seconds_total=([0-9.]+).*/\1/p' "$work/stdout")
  else
    loop=$(awk '/ frames at /{
      for (i = 1; i < NF; i++) {
        if ($i == "frame" && $(i - 1) == "first") first = s($(i + 1), $(i + 2));
        if ($i == "in" && $(i - 1) == "frames" && $(i - 3) == "then") rest = s($(i + 1), $(i + 2));
      }
      printf "%.6f\n", first + rest }
      function s(v, u) { sub(/[,(]/, "", u); return u ~ /^ms/ ? v / 1000 : v }' "$work/err")
    # The loop's time already holds the wait for the encoders after the last frame.
  fi
  echo "$loop $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }')"
  rm -rf "$out"
}

cases_for() { # SHADER
  if [ "$1" = ocean ]; then echo "render-sync floor-sync render floor raw png exr exr-half x264 x264-veryfast auto"
  else echo "render-sync render raw png exr exr-half x264 x264-veryfast auto"; fi
}

declare -A loops walls
for rep in $(seq "$reps"); do
  for size in $sizes; do
    for shader in $shaders; do
      for case in $(cases_for "$shader"); do
        frames=$(frames_for "$size" "$case")
        read -r loop wall < <(run_case "$shader" "$size" "$case" "$frames")
        key="$shader $size $case"
        loops[$key]+="$loop "; walls[$key]+="$wall "
        echo "rep $rep: $key: loop $loop s, wall $wall s" >&2
      done
    done
  done
done

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END { if (NR == 0) print "fail"; else if (a[1] == "fail") print "fail"; else print (NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2) }'; }
echo "| shader | size | case | frames | frames/s (loop, median of $reps) | loop s (each run) | wall s (each run) |"
echo "|---|---|---|---|---|---|---|"
for size in $sizes; do
  for shader in $shaders; do
    for case in $(cases_for "$shader"); do
      key="$shader $size $case"; frames=$(frames_for "$size" "$case")
      m=$(echo "${loops[$key]}" | grep -q fail && echo fail || echo "${loops[$key]}" | median)
      fps=$([ "$m" = fail ] && echo "failed (see log)" || awk -v f="$frames" -v s="$m" 'BEGIN { printf "%.1f", f / s }')
      echo "| $shader | $size | $case | $frames | $fps | ${loops[$key]}| ${walls[$key]}|"
    done
  done
done
