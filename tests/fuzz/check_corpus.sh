#!/usr/bin/env bash
# The corpus policy (tests/fuzz/README.md), checked before every CI fuzzing run: seeds/<target>/
# holds named inputs written by hand, corpus/<target>/ only what libFuzzer's merge kept (files named
# by their SHA-1), and every target has seeds. Exits 1 naming each file in the wrong place.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
failed=0
for dir in "$here"/seeds/* "$here"/corpus/*; do
    [ -d "$dir" ] || continue
    kind=$(basename "$(dirname "$dir")")
    for file in "$dir"/*; do
        [ -e "$file" ] || continue
        name=$(basename "$file")
        hashed=0
        [[ "$name" =~ ^[0-9a-f]{40}$ ]] && hashed=1
        if [ "$kind" = corpus ] && [ "$hashed" = 0 ]; then
            echo "check_corpus: $file: a named input belongs in seeds/$(basename "$dir")/" >&2
            failed=1
        elif [ "$kind" = seeds ] && [ "$hashed" = 1 ]; then
            echo "check_corpus: $file: a grown input belongs in corpus/ (tests/fuzz/run.sh merge puts it there)" >&2
            failed=1
        fi
    done
done
for target in "$here"/fuzz_*.cpp; do
    t=$(basename "$target" .cpp)
    if [ -z "$(ls -A "$here/seeds/$t" 2>/dev/null)" ]; then
        echo "check_corpus: seeds/$t/ is empty: every target starts from named seeds" >&2
        failed=1
    fi
done
exit "$failed"
