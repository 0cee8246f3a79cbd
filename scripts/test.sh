#!/usr/bin/env bash
# The whole test suite: installs what is missing, configures a fresh build, builds everything and
# runs CTest (unit tests without GL, then GL tests on EGL surfaceless / llvmpipe).
# BUILD_DIR (default build-test) may be set in the environment.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"

build="${BUILD_DIR:-$root/build-test}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)"
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 600
