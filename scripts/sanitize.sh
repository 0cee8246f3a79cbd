#!/usr/bin/env bash
# The sanitizer step of CI: the unit and io tests, and the GL paths through the CLI, built and run
# under AddressSanitizer + UndefinedBehaviorSanitizer (any report fails), and the threaded tests
# (frame queue, encoder pool, child processes, atomic files, the video decoding thread) under
# ThreadSanitizer. Builds into build-asan/ and build-tsan/ (BUILD_ROOT may move them).
# Mesa's own allocations are not ours to fix: leak detection is off for the GL runs only.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
builds="${BUILD_ROOT:-$root}"
jobs="$(nproc)"

configure() {  # configure DIR FLAGS (-O1 -g1: reports with file:line, and CI time kept short)
    cmake -S "$root" -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=Sanitize \
        -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" -DCMAKE_C_FLAGS_SANITIZE="-O1 -g1" \
        -DCMAKE_CXX_FLAGS="$2 -fno-omit-frame-pointer" -DCMAKE_C_FLAGS="$2 -fno-omit-frame-pointer" \
        -DCMAKE_EXE_LINKER_FLAGS="$2" >/dev/null
}

echo "== ASan + UBSan"
asan="$builds/build-asan"
configure "$asan" "-fsanitize=address,undefined -fno-sanitize-recover=undefined"
cmake --build "$asan" -j"$jobs" --target toyhost toyhost_unit_tests toyhost_io_tests
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" "$asan/tests/toyhost_unit_tests" --gtest_brief=1
# ImageMemory.* lower RLIMIT_AS in a child and expect std::bad_alloc; under ASan that limit meets the
# sanitizer's own shadow reservation and its allocator reports "out of memory" instead of throwing,
# so they cannot mean the same thing here. They run in every normal build (./scripts/test.sh).
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" "$asan/tests/toyhost_io_tests" --gtest_brief=1 \
    --gtest_filter='-ImageMemory.*'
# The GL paths through the sanitized CLI (compiling the GL test executable too would double this
# step's time): buffers and feedback, input scripts, every capture kind, checkpoint and resume,
# import, a starter, errors. Mesa's llvmpipe keeps allocations for the life of the process, so no
# leak check here; any ASan or UBSan report fails the run.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1"
toyhost="$asan/tools/toyhost"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cd "$root"
run() { echo "+ toyhost $*"; "$toyhost" "$@" --headless --quiet; }
run run shadertoys/pingpong-probe --size 16x8 --frames 4 --capture-pass B --out "$out/b_%d.exr"
run run shadertoys/uniform-probe --size 64x36 --frames 3 --out "$out/u_%d.png"
run run shadertoys/ripple-pool --size 96x54 --frames 45 --capture-every 20 --mouse-script shadertoys/ripple-pool/drag.json \
    --check-finite --out "$out/r_%04d.png"
run run shadertoys/lake-optics --size 64x36 --frames 4 --key-script shadertoys/lake-optics/keys-muddy.json --out "$out/l.mp4"
run run shadertoys/ripple-pool --size 64x36 --frames 10 --out - > "$out/raw"
run run shadertoys/ripple-pool --size 64x36 --frames 6 --checkpoint "$out/c.ckpt"
run run shadertoys/ripple-pool --size 64x36 --frames 12 --resume "$out/c.ckpt" --out "$out/res_%d.png"
run run shadertoys/ripple-pool --size 64x36 --frames 12 --shard 1/3 --out "$out/s_%d.png"
"$toyhost" new "$out/starter" --passes common,a,b,image
run run "$out/starter" --size 32x18 --frames 3
"$toyhost" inspect "$out/b_3.exr" "$out/u_2.png" > /dev/null
"$toyhost" media > /dev/null
if [ -f ../shared/shadertoys/7tSSDD/7tSSDD.json ]; then
    "$toyhost" import ../shared/shadertoys/7tSSDD/7tSSDD.json "$out/ml"
    run run "$out/ml" --size 320x256 --frames 20 --capture-every 10 --capture-pass C --out "$out/ml_%d.exr"
fi
# Every pass and input: Cube A (captured), Sound (WAV, and muxed), stand-in cubemap, volume, video.
run run shadertoys/cube-probe --size 64x36 --frames 3 --out "$out/cp_%d.png"
run run shadertoys/cube-probe --size 64x36 --frames 2 --capture-pass "Cube A" --out "$out/cube_%d.exr"
run run shadertoys/cube-probe --size 64x36 --frames 12 --out "$out/cp.mp4"
"$toyhost" sound shadertoys/cube-probe --seconds 7 --quiet --out "$out/cp.wav"
# Better pixels: samples averaged on the GPU, tiles written band by band on their writer thread.
run run shadertoys/sampling-probe --size 40x24 --frames 3 --supersample 3 --motion-blur 2 --shutter 270 --dither \
    --out "$out/ss_%d.png"
run run shadertoys/tile-probe --size 300x170 --tile 64 --frames 2 --out "$out/tile_%d.png"
run run shadertoys/sampling-probe --size 300x170 --tile 128 --supersample 2 --out "$out/tile.exr"
# A pass Mesa's preprocessor refuses, compiled after preprocessing as browsers do.
mkdir -p "$out/pp"
printf '#define NEG(x) -x\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(NEG(-.5)); }\n' > "$out/pp/image.glsl"
printf '{"passes": {"Image": {"source": "image.glsl"}}}' > "$out/pp/manifest.json"
run run "$out/pp" --size 8x8
# INT_MIN / -1 and % -1 in constant expressions: Mesa's folder traps, toyhost's division trap
# (core/DivisionOverflowTrap.h) completes them, with ASan's own SIGFPE handler put back after.
printf 'const int K = int(0x80000000u) / -1;\nconst int R = (-2147483647 - 1) %% -1;\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(float(K & 255) + float(R)); }\n' \
    > "$out/pp/image.glsl"
run run "$out/pp" --size 8x8
for id in 7dyfzW ds3BW7 fd3yW8 Dd2SWh; do  # video, music, mic, stock cubemap (wild corpus)
    if [ -f "../shared/corpus/wild/$id.json" ]; then run run "../shared/corpus/wild/$id.json" --size 48x27 --frames 3; fi
done
# toyhost compare: two sessions at once, difference images and frames through the writer thread
# (exit 1: they differ from frame 3).
code=0
"$toyhost" compare tests/gl/compare/base tests/gl/compare/diverge --size 40x20 --fps 10 --frames 6 --json \
    --diff-out "$out/cmp" --frames-out "$out/cmp" > /dev/null || code=$?
if [ "$code" -ne 1 ]; then echo "toyhost compare exited $code, expected 1 (different)"; exit 1; fi
printf '{"passes": {"Image": {"source": "nope.glsl", "bogus": 1}}, "passes": {}}' > "$out/bad.json"
if "$toyhost" run "$out/bad.json" --headless 2>/dev/null; then echo "a bad manifest was accepted"; exit 1; fi
unset ASAN_OPTIONS

echo "== TSan (capture pipeline, the video decoding thread)"
tsan="$builds/build-tsan"
configure "$tsan" "-fsanitize=thread"
cmake --build "$tsan" -j"$jobs" --target toyhost_io_tests
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1" "$tsan/tests/toyhost_io_tests" --gtest_brief=1 \
    --gtest_filter='FrameQueue.*:EncoderPool.*:ChildProcess.*:AtomicFile.*:*VideoStream*'
echo "sanitizers: no reports"
