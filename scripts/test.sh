#!/usr/bin/env bash
# The whole test suite: installs what is missing, configures a fresh build, builds everything and
# runs CTest (unit tests without GL, then GL tests on EGL surfaceless / llvmpipe).
# BUILD_DIR (default build-test) and CMAKE_ARGS (more configure options, e.g. -DTOYHOST_WERROR=ON)
# may be set in the environment.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"

build="${BUILD_DIR:-$root/build-test}"
# shellcheck disable=SC2086  # CMAKE_ARGS is a list of options
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j"$(nproc)"
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 600
