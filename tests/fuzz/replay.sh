#!/usr/bin/env bash
# replay.sh FUZZER [OPTION...] -- CORPUS_DIR... [--regressions REGRESSIONS_DIR]
# The ctest fuzz.<target>.replay test: runs every input of the CORPUS_DIRs (seeds/<target>/ and
# corpus/<target>/) once (one process), then every
# kept finding of REGRESSIONS_DIR in its own process, naming each one that still fails. Exits 1 when
# any input crashes, leaks, hits UB, times out or runs out of memory. A finding that depends on the
# contents of uninitialised memory has a sidecar INPUT.asan_options (e.g. malloc_fill_byte=13 with
# max_malloc_fill_size=4194304: ASan fills every new allocation with that byte), added to ASAN_OPTIONS.
set -uo pipefail
fuzzer=$1
shift
options=()
while (($#)) && [ "$1" != "--" ]; do options+=("$1"); shift; done
shift || true
corpus=()
regressions=
while (($#)); do
    if [ "$1" = --regressions ]; then regressions=${2:-}; shift 2 || shift; else corpus+=("$1"); shift; fi
done
((${#corpus[@]})) || { echo "replay: no corpus folder" >&2; exit 2; }

failed=0
if ! "$fuzzer" "${options[@]}" -runs=0 "${corpus[@]}"; then
    echo "replay: an input of ${corpus[*]} fails (see above)" >&2
    failed=1
fi
if [ -n "$regressions" ] && [ -d "$regressions" ]; then
    for input in "$regressions"/*; do
        [ -f "$input" ] || continue
        case "$input" in *.asan_options) continue ;; esac
        asan=${ASAN_OPTIONS:-}
        [ -f "$input.asan_options" ] && asan="${asan:+$asan:}$(tr -d '\n' <"$input.asan_options")"
        if log=$(ASAN_OPTIONS="$asan" "$fuzzer" "${options[@]}" "$input" 2>&1); then
            echo "replay: ok      $(basename "$input")"
        else
            why=$(grep -m1 -oE 'runtime error: .{0,100}|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer): .{0,80}|what\(\): .{0,80}' <<<"$log")
            echo "replay: FAILED  $(basename "$input"): ${why:-see the log below}" >&2
            grep -E '^ +#[0-9]+ .* in ' <<<"$log" | grep -vE 'fuzzer::|__sanitizer|__interceptor|libc\.so|_start' | head -6 >&2
            failed=1
        fi
    done
fi
exit "$failed"
