#!/usr/bin/env bash
# The CI fuzzing run of one target (ctest fuzz.<target>.short): libFuzzer with seed 1 for a fixed
# number of inputs, from the checked-in seeds and corpus, new units into an emptied scratch folder,
# so the run is the same on every machine and every time.
# Usage: short.sh SCRATCH RUNS FUZZER [OPTIONS...] -- CORPUS_DIR...
set -euo pipefail
scratch="$1" runs="$2" fuzzer="$3"
shift 3
options=()
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do options+=("$1"); shift; done
shift  # --
rm -rf "$scratch"
mkdir -p "$scratch"
exec "$fuzzer" "${options[@]}" -seed=1 -runs="$runs" "$scratch" "$@"
