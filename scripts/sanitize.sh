#!/usr/bin/env bash
# The sanitizer step of CI: the unit and io tests and a subset of the GL tests built and run under
# AddressSanitizer + UndefinedBehaviorSanitizer (any report fails), and the capture pipeline's
# threaded tests (frame queue, encoder pool, capture formats and error paths) under
# ThreadSanitizer. Builds into build-asan/ and build-tsan/ (BUILD_ROOT may move them).
# Mesa's own allocations are not ours to fix: leak detection is off for the GL tests only.
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
cmake --build "$asan" -j"$jobs" --target toyhost toyhost_unit_tests toyhost_io_tests toyhost_gl_tests
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" "$asan/tests/toyhost_unit_tests" --gtest_brief=1
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" "$asan/tests/toyhost_io_tests" --gtest_brief=1
# GL tests through the Player and the CLI (the toyhost they run is the sanitized one); Mesa's
# llvmpipe keeps allocations for the life of the process, so no leak check here.
ASAN_OPTIONS="detect_leaks=0:abort_on_error=1" "$asan/tests/toyhost_gl_tests" --gtest_brief=1 \
    --gtest_filter='PingPong.*:PlayerTest.*:PortTools.*:NonFinite.*:CliErrors.*:Uniforms.*:CapturePipeline.*:RipplePool.*:ExportCompileErrors.*:RunOptions.*'

echo "== TSan (capture pipeline)"
tsan="$builds/build-tsan"
configure "$tsan" "-fsanitize=thread"
cmake --build "$tsan" -j"$jobs" --target toyhost_io_tests
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1" "$tsan/tests/toyhost_io_tests" --gtest_brief=1 \
    --gtest_filter='FrameQueue.*:EncoderPool.*:ChildProcess.*:AtomicFile.*'
echo "sanitizers: no reports"
