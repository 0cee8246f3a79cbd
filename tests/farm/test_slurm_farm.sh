#!/usr/bin/env bash
# The Slurm job array that `toyhost farm plan --scheduler slurm` writes, submitted to a real
# (temporary, one-node) Slurm cluster on this machine:
#  1. an Image-only shadertoy (exp-sine-ocean) in 4 array tasks, its job folder named with a space,
#     quotes, # and $( ): frames byte-identical to one run, nothing the name holds run;
#  2. a shadertoy with buffers (ripple-pool, with its mouse script) in 3 tasks starting from the
#     checkpoint chain: byte-identical; `farm status` names a deleted and a truncated frame, `farm
#     join` refuses, the damaged shard is submitted again, `farm join` makes a lossless mp4 whose
#     decoded frames equal the PNGs;
#  2b. Mountains & Lakes (xjorma's original, Common + 4 buffers, from ../shared) in 3 tasks from the
#     checkpoint chain: byte-identical to one run;
#  3. a task killed at its time limit (Slurm sends SIGTERM): it leaves its checkpoint, is
#     requeued, resumes from it, and the frames are byte-identical to one uninterrupted run.
# The daemons are stopped by process id whatever happens; if they cannot start, the test fails.
# Usage: test_slurm_farm.sh TOYHOST SOURCE_DIR WORK_DIR [cases: image buffers mountains timeout]
set -uo pipefail
toyhost=$1 source=$2 work=$3
shift 3
cases=("$@")
((${#cases[@]})) || cases=(image buffers mountains timeout)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/slurm_cluster.sh"

rm -rf "$work"
mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
trap 'stop_cluster' EXIT
trap 'exit 143' TERM INT

if ! start_cluster "$work/cluster"; then
  echo "FAIL: the Slurm cluster did not start (reason above)"
  exit 1
fi
echo "cluster up: $(sinfo -h -o '%P %D %c %T')"

# Frames of two folders, compared byte for byte (names and contents).
same_frames() {
  local a=$1 b=$2 what=$3
  if ! diff -r -q "$a" "$b" >/dev/null; then
    fail "$what: frames differ from the single run:"; diff -r -q "$a" "$b" | head -n 10
    return 1
  fi
  echo "ok: $what: $(ls "$a" | wc -l) frames byte-identical to the single run"
}

submit() { # prints the array's job id
  local id
  id=$("$1/submit.sh" | tail -n 1) || return 1
  echo "$id"
}

show_logs() { tail -n 20 "$1"/logs/*.log 2>/dev/null; }

date_option=(--date 2024-05-01T12:00:00)

if [[ " ${cases[*]} " == *" image "* ]]; then
  ocean=$source/shadertoys/exp-sine-ocean
  # A job folder with a space, an apostrophe, a double quote, a # and a $( ): sbatch's directive
  # parser must read the quoted --output, and no script may run what the name holds.
  job="$work/ocean job's \"1\" #2 "'$(touch PWNED)'
  options=(--size 64x36 "${date_option[@]}")
  "$toyhost" run "$ocean" --headless --quiet --frames 24 "${options[@]}" --out "$work/ocean-single/f_%06d.png" 2>/dev/null ||
    fail "image: the single run failed"
  echo "+ toyhost farm plan $ocean --frames 24 --shards 4 --scheduler slurm --job \"$job\" ${options[*]}"
  "$toyhost" farm plan "$ocean" --frames 24 --shards 4 --scheduler slurm --job "$job" "${options[@]}" >/dev/null ||
    fail "image: farm plan failed"
  id=$(submit "$job") || fail "image: sbatch refused the job"
  wait_job "$id" 300 || fail "image: job $id still queued after 300 s"
  "$toyhost" farm status "$job" || { fail "image: farm status says incomplete"; show_logs "$job"; }
  same_frames "$job/frames" "$work/ocean-single" "image (4 array tasks, a job folder with quotes, # and \$( ))"
  [ -z "$(find "$work" -name PWNED 2>/dev/null)" ] && [ ! -e PWNED ] || fail "image: a command in the job folder's name ran"
fi

if [[ " ${cases[*]} " == *" buffers "* ]]; then
  pool=$source/shadertoys/ripple-pool
  options=(--size 64x36 "${date_option[@]}" --mouse-script "$pool/drag.json")
  "$toyhost" run "$pool" --headless --quiet --frames 30 "${options[@]}" --out "$work/pool-single/f_%06d.png" 2>/dev/null ||
    fail "buffers: the single run failed"
  echo "+ toyhost farm plan $pool --frames 30 --shards 3 --scheduler slurm --job $work/pool ${options[*]}"
  "$toyhost" farm plan "$pool" --frames 30 --shards 3 --scheduler slurm --job "$work/pool" "${options[@]}" >/dev/null ||
    fail "buffers: farm plan failed"
  [ -x "$work/pool/checkpoints.sh" ] || fail "buffers: no checkpoint chain in the plan"
  id=$(submit "$work/pool") || fail "buffers: sbatch refused the job"
  wait_job "$id" 300 || fail "buffers: job $id still queued after 300 s"
  for i in 1 2; do [ -s "$work/pool/checkpoints/start-$i.ckpt" ] || fail "buffers: no chain checkpoint start-$i.ckpt"; done
  same_frames "$work/pool/frames" "$work/pool-single" "buffers (3 array tasks from the checkpoint chain)" || show_logs "$work/pool"

  # A lost and a cut frame, both in shard 1 (frames 10-19).
  rm "$work/pool/frames/f_000013.png"
  head -c 100 "$work/pool-single/f_000017.png" > "$work/pool/frames/f_000017.png"
  status=$("$toyhost" farm status "$work/pool")
  code=$?
  echo "$status"
  [ "$code" -eq 1 ] || fail "farm status exited $code with a missing and a truncated frame (expected 1)"
  grep -q "^shard 1 (frames 10-19): 8/10 ok; missing 13; truncated 17" <<<"$status" ||
    fail "farm status does not name frame 13 missing and 17 truncated in shard 1"
  refusal=$("$toyhost" farm join "$work/pool" --out "$work/pool.mp4" 2>&1)
  code=$?
  [ "$code" -eq 1 ] && grep -q "frames 13, 17 of 30" <<<"$refusal" || fail "farm join did not refuse with the list: $refusal"
  [ ! -e "$work/pool.mp4" ] || fail "farm join left a video behind"
  # The shard again, through Slurm (it starts from the chain's checkpoint at frame 10).
  echo "+ sbatch --array=1 $work/pool/job.sbatch again"
  id=$(sbatch --parsable --array=1 "$work/pool/job.sbatch" again) || fail "buffers: resubmitting shard 1 failed"
  wait_job "$id" 300 || fail "buffers: shard 1 still queued after 300 s"
  "$toyhost" farm status "$work/pool" >/dev/null || fail "buffers: still incomplete after shard 1 ran again"
  same_frames "$work/pool/frames" "$work/pool-single" "buffers after the re-render"
  # Lossless RGB H.264, so the decoded video must equal the PNGs exactly.
  "$toyhost" farm join "$work/pool" --out "$work/pool.mp4" --codec libx264rgb --video-quality 0 ||
    fail "farm join failed on a complete job"
  video=$(ffmpeg -v error -i "$work/pool.mp4" -f rawvideo -pix_fmt rgb24 - | sha256sum)
  pngs=$(ffmpeg -v error -framerate 60 -i "$work/pool/frames/f_%06d.png" -f rawvideo -pix_fmt rgb24 - | sha256sum)
  frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$work/pool.mp4")
  [ "$frames" = 30 ] || fail "the joined video has $frames frames, not 30"
  [ "$video" = "$pngs" ] && echo "ok: the joined mp4's 30 decoded frames equal the PNGs" ||
    fail "the joined mp4's decoded frames differ from the PNGs"
fi

if [[ " ${cases[*]} " == *" mountains "* ]]; then
  lakes=$source/shadertoys/mountains-lakes
  [ -r "$source/../shared/shadertoys/7tSSDD/common.glsl" ] || fail "mountains: ../shared/shadertoys/7tSSDD is not beside the repository"
  options=(--size 64x36 "${date_option[@]}")
  "$toyhost" run "$lakes" --headless --quiet --frames 24 "${options[@]}" --out "$work/lakes-single/f_%06d.png" 2>/dev/null ||
    fail "mountains: the single run failed"
  echo "+ toyhost farm plan $lakes --frames 24 --shards 3 --scheduler slurm --job $work/lakes ${options[*]}"
  "$toyhost" farm plan "$lakes" --frames 24 --shards 3 --scheduler slurm --job "$work/lakes" "${options[@]}" >/dev/null ||
    fail "mountains: farm plan failed"
  [ -x "$work/lakes/checkpoints.sh" ] || fail "mountains: no checkpoint chain in the plan"
  id=$(submit "$work/lakes") || fail "mountains: sbatch refused the job"
  wait_job "$id" 300 || fail "mountains: job $id still queued after 300 s"
  for i in 1 2; do [ -s "$work/lakes/checkpoints/start-$i.ckpt" ] || fail "mountains: no chain checkpoint start-$i.ckpt"; done
  same_frames "$work/lakes/frames" "$work/lakes-single" "Mountains & Lakes (3 array tasks from the checkpoint chain)" ||
    show_logs "$work/lakes"
fi

done_releasing() {
  job_done "$1" && return 0
  if squeue -h -j "$1" -o '%r' 2>/dev/null | grep -q BeginTime; then
    scontrol update JobId="$(squeue -h -j "$1" -o '%i' | head -n 1)" StartTime=now
  fi
  return 1
}

if [[ " ${cases[*]} " == *" timeout "* ]]; then
  # A shadertoy with state; the one array task draws its 1500 frames at --fps 20 in wall time
  # (--paced), so it runs for at least 75 s whatever the machine's speed or load: past its first
  # SIGTERM (--signal=B:TERM@15 ahead of --time=1; Slurm checks every 30 s, so it comes about 30 to
  # 45 s in). Each attempt draws some 600 frames, so two or three requeues finish it (3000 frames
  # took five attempts and once ended the wait with the last 500 frames missing). --capture-every
  # keeps the files few.
  heavy=$work/heavy-state
  mkdir -p "$heavy"
  cat > "$heavy/manifest.json" <<'JSON'
{"name": "heavy-state", "passes": {
  "Buffer A": {"source": "a.glsl", "channels": {"iChannel0": {"buffer": "A", "filter": "nearest"}}},
  "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "A", "filter": "nearest"}}}}}
JSON
  cat > "$heavy/a.glsl" <<'GLSL'
void mainImage(out vec4 c, in vec2 f) {
    vec4 last = texelFetch(iChannel0, ivec2(f), 0);
    float s = 0.0;
    for (int i = 0; i < 200; i++) s = fract(s * 1.61803 + sin(float(i) * f.x * 0.01 + f.y + last.x));
    c = vec4(fract(last.x + s * 0.37 + 0.01), last.y + 1.0, s, 1.0);
}
GLSL
  cat > "$heavy/image.glsl" <<'GLSL'
void mainImage(out vec4 c, in vec2 f) { vec4 a = texelFetch(iChannel0, ivec2(f), 0); c = vec4(a.x, fract(a.y / 64.0), a.z, 1.0); }
GLSL
  options=(--size 32x18 "${date_option[@]}" --capture-every 500 --fps 20)
  frames=1500
  echo "+ toyhost farm plan $heavy --frames $frames --shards 1 --scheduler slurm --time 1 --job $work/heavy ${options[*]} --paced"
  "$toyhost" farm plan "$heavy" --frames "$frames" --shards 1 --scheduler slurm --time 1 --job "$work/heavy" "${options[@]}" --paced >/dev/null ||
    fail "timeout: farm plan failed"
  id=$(submit "$work/heavy") || fail "timeout: sbatch refused the job"
  # The uninterrupted run (unpaced: the same frames), meanwhile, on the other core.
  "$toyhost" run "$heavy" --headless --quiet --frames "$frames" "${options[@]}" --out "$work/heavy-single/f_%06d.png" 2>/dev/null ||
    fail "timeout: the single run failed"
  # Slurm holds a requeued job for a while before it is eligible again (BeginTime, 2 minutes
  # here): each time the task is back in the queue after its time limit, it is made eligible now.
  # (A resumed attempt has the same --time, so a long shard may be requeued more than once.)
  wait_until 600 done_releasing "$id" || fail "timeout: job $id still queued after 600 s"
  log=$(cat "$work"/heavy/logs/*.log 2>/dev/null)
  restarts=$(scontrol show job "${id}_0" 2>/dev/null | grep -o 'Restarts=[0-9]*')
  echo "timeout: job ${id}_0: $restarts"
  # --signal=B:TERM@15 (a quarter of --time 1) stops it ahead of its limit; the limit itself
  # (TIME LIMIT) when Slurm's timer comes late.
  grep -qE "SIGTERM ahead of the time limit|TIME LIMIT" <<<"$log" || fail "timeout: the task was not stopped at its time limit"
  grep -q "resume $work/heavy/checkpoints/shard-0.ckpt" <<<"$log" ||
    fail "timeout: the requeued task did not resume from its checkpoint"
  [ -n "$restarts" ] && [ "$restarts" != "Restarts=0" ] || fail "timeout: the task was never requeued ('$restarts')"
  "$toyhost" farm status "$work/heavy" || fail "timeout: incomplete after the requeue"
  same_frames "$work/heavy/frames" "$work/heavy-single" "time limit, SIGTERM, requeue and resume" || echo "$log"
fi

if ((failures)); then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all Slurm farm checks passed"
