#!/usr/bin/env bash
# Builds and runs toyhost's libFuzzer targets (tests/fuzz/README.md).
#   run.sh ci               configure and build the fuzz build folder if needed, replay every seed,
#                           corpus input and kept finding once, then fuzz each target from its seeds
#                           and corpus for a fixed number of inputs (ctest -L fuzz); fails on any
#                           crash, leak, UB, timeout or out-of-memory. Writes nothing in the tree.
#   run.sh long SECONDS [TARGET...]
#                           fuzz each target (default: all) for SECONDS, one after the other, from
#                           seeds/<target>/ and corpus/<target>/; new inputs go to the cache
#                           <build>/fuzz-cache/<target>/ (never into the source tree), findings to
#                           <build>/tests/fuzz/artifacts/<target>/, logs to <build>/fuzz-logs/
#   run.sh merge [TARGET...]
#                           minimise corpus/<target>/ together with the cache (libFuzzer -merge=1):
#                           it keeps the inputs that add coverage beyond seeds/<target>/, and commits
#                           tests/fuzz/corpus on its own ("fuzz corpus merged: ..."), never with other
#                           changes (NO_COMMIT=1: leave the result uncommitted)
# Environment: BUILD_DIR (default build-fuzz in the repository), JOBS (build jobs, default 1),
# KEEP_GOING=1 (long: fork mode, going on past crashes/OOMs/timeouts and saving each one).
# The machine is shared: run it as `nice -n 15 tests/fuzz/run.sh ...`.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD_DIR:-$root/build-fuzz}
jobs=${JOBS:-1}
targets_all=(fuzz_manifest fuzz_export fuzz_input_script fuzz_output_pattern fuzz_image fuzz_png_encode fuzz_shader_text fuzz_farm)
flags='-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined'
options=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

usage() { sed -n '2,21p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; exit 2; }

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
    "$here/check_corpus.sh"
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
        cache="$build/fuzz-cache/$t"
        mkdir -p "$artifacts" "$cache"
        extra=()
        [ "${KEEP_GOING:-0}" = 1 ] && extra=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
        echo "== $t: ${seconds}s (log: $build/fuzz-logs/$t.log)"
        touch "$build/fuzz-logs/$t.log.start"
        set +e
        # libFuzzer writes new inputs into the first folder only: the cache.
        (cd "$artifacts" && "$build/tests/fuzz/$t" "${options[@]}" $(dict_of "$t") "${extra[@]}" \
            -artifact_prefix="$artifacts/" -max_total_time="$seconds" "$cache" "$here/seeds/$t" "$here/corpus/$t") \
            >"$build/fuzz-logs/$t.log" 2>&1
        rc=$?
        set -e
        # The last progress line (fork mode: "#N: cov: ... oom/timeout/crash: a/b/c"), the final stats.
        grep -E '^#[0-9]+' "$build/fuzz-logs/$t.log" | tail -1 || true
        grep -E '^(stat::|Done )' "$build/fuzz-logs/$t.log" || true
        echo "   cache $cache: $(ls "$cache" | wc -l) inputs (run.sh merge $t keeps what adds coverage)"
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
    summary=()
    for t in "${targets[@]}"; do
        work=$(mktemp -d)
        mkdir -p "$work/merged" "$build/fuzz-cache/$t"
        # The seeds go in first, so that only inputs adding coverage beyond them are taken from the
        # corpus and the cache; then the seeds are taken out again (they live in seeds/).
        cp "$here/seeds/$t/"* "$work/merged/"
        before=$(ls "$here/corpus/$t" | wc -l)
        "$build/tests/fuzz/$t" "${options[@]}" -merge=1 "$work/merged" "$here/corpus/$t" "$build/fuzz-cache/$t" \
            >"$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
        for seed in "$here/seeds/$t/"*; do rm -f "$work/merged/$(basename "$seed")"; done
        rm -rf "$here/corpus/$t"
        mkdir -p "$here/corpus/$t"
        mv "$work/merged/"* "$here/corpus/$t/" 2>/dev/null || true
        rm -rf "$work" "$build/fuzz-cache/$t"
        after=$(ls "$here/corpus/$t" | wc -l)
        echo "$t: corpus $before -> $after inputs ($(du -sh "$here/corpus/$t" | cut -f1))"
        summary+=("$t $before -> $after")
    done
    "$here/check_corpus.sh"
    if [ "${NO_COMMIT:-0}" != 1 ] && git -C "$root" rev-parse --git-dir >/dev/null 2>&1; then
        git -C "$root" add -A -- tests/fuzz/corpus
        if git -C "$root" diff --cached --quiet -- tests/fuzz/corpus; then
            echo "corpus unchanged: nothing to commit"
        else
            # --only: this commit holds the corpus and nothing else, whatever else is staged.
            git -C "$root" commit --quiet --only -m "Fuzz corpus merged (libFuzzer -merge=1 over corpus/ and the local cache, beyond seeds/): $(printf '%s; ' "${summary[@]}" | sed 's/; $//')" -- tests/fuzz/corpus
            git -C "$root" log --oneline -1
        fi
    fi
    ;;
*) usage ;;
esac
