#!/usr/bin/env bash
# Builds and runs toyhost's libFuzzer targets (tests/fuzz/README.md).
#   run.sh ci               configure and build the fuzz build folder if needed, replay every seed and
#                           kept finding once, then fuzz each target 20 s on its corpus (ctest -L fuzz);
#                           fails on any crash, leak, UB, timeout or out-of-memory
#   run.sh long SECONDS [TARGET...]
#                           fuzz each target (default: all) for SECONDS, one after the other, adding
#                           new inputs to tests/fuzz/corpus/<target>/; findings go to
#                           <build>/tests/fuzz/artifacts/<target>/, logs to <build>/fuzz-logs/
#   run.sh merge [TARGET...]
#                           minimise corpus/<target>/ in place (libFuzzer -merge=1)
# Environment: BUILD_DIR (default build-fuzz in the repository), JOBS (build jobs, default 1),
# KEEP_GOING=1 (long: fork mode, going on past crashes/OOMs/timeouts and saving each one).
# The machine is shared: run it as `nice -n 15 tests/fuzz/run.sh ...`.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD_DIR:-$root/build-fuzz}
jobs=${JOBS:-1}
targets_all=(fuzz_manifest fuzz_export fuzz_input_script fuzz_output_pattern fuzz_image)
flags='-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined'
options=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

usage() { sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; exit 2; }

dict_of() {
    local d="$here/dict/${1#fuzz_}.dict"
    [ -f "$d" ] && echo "-dict=$d"
}

build_fuzzers() {
    if [ ! -f "$build/CMakeCache.txt" ]; then
        CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DTOYHOST_FUZZ=ON \
            -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags"
    fi
    cmake --build "$build" --target toyhost_fuzzers -j "$jobs"
}

mode=${1:-}
case "$mode" in
ci)
    build_fuzzers
    # Each target's tests one after the other (one fuzzer at a time).
    ctest --test-dir "$build" -L fuzz --output-on-failure -j 1
    ;;
long)
    seconds=${2:-}
    [[ "$seconds" =~ ^[0-9]+$ ]] || usage
    shift 2
    targets=("$@")
    ((${#targets[@]})) || targets=("${targets_all[@]}")
    build_fuzzers
    mkdir -p "$build/fuzz-logs"
    failed=0
    for t in "${targets[@]}"; do
        artifacts="$build/tests/fuzz/artifacts/$t"
        mkdir -p "$artifacts" "$here/corpus/$t"
        extra=()
        [ "${KEEP_GOING:-0}" = 1 ] && extra=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
        echo "== $t: ${seconds}s (log: $build/fuzz-logs/$t.log)"
        touch "$build/fuzz-logs/$t.log.start"
        set +e
        (cd "$artifacts" && "$build/tests/fuzz/$t" "${options[@]}" $(dict_of "$t") "${extra[@]}" \
            -artifact_prefix="$artifacts/" -max_total_time="$seconds" "$here/corpus/$t") \
            >"$build/fuzz-logs/$t.log" 2>&1
        rc=$?
        set -e
        # The last progress line (fork mode: "#N: cov: ... oom/timeout/crash: a/b/c"), the final stats.
        grep -E '^#[0-9]+' "$build/fuzz-logs/$t.log" | tail -1 || true
        grep -E '^(stat::|Done )' "$build/fuzz-logs/$t.log" || true
        echo "   corpus/$t: $(ls "$here/corpus/$t" | wc -l) inputs, $(du -sh "$here/corpus/$t" | cut -f1)"
        found=$(find "$artifacts" -newer "$build/fuzz-logs/$t.log.start" -type f | wc -l)
        if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
            echo "== $t: FAILED (exit $rc, $found new findings in $artifacts)" >&2
            failed=1
        fi
    done
    exit "$failed"
    ;;
merge)
    shift
    targets=("$@")
    ((${#targets[@]})) || targets=("${targets_all[@]}")
    build_fuzzers
    for t in "${targets[@]}"; do
        fresh=$(mktemp -d)
        "$build/tests/fuzz/$t" "${options[@]}" -merge=1 "$fresh" "$here/corpus/$t" >/dev/null 2>&1
        rm -rf "$here/corpus/$t"
        mv "$fresh" "$here/corpus/$t"
        chmod 755 "$here/corpus/$t"
        echo "$t: $(ls "$here/corpus/$t" | wc -l) inputs, $(du -sh "$here/corpus/$t" | cut -f1)"
    done
    ;;
*) usage ;;
esac
