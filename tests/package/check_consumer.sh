#!/usr/bin/env bash
# A program outside the tree finds an installed toyhost and renders with it: installs into a staging
# prefix, builds tests/package/consumer with find_package(toyhost) (MODE cmake) or with
# `pkg-config toyhost` alone (MODE pkgconfig), runs it on shadertoys, and compares its frames with
# the installed CLI's raw frames (`toyhost run --out -`) byte for byte: ripple-pool (a buffer with
# feedback), uniform-probe (three buffers, a texture file, the uniforms) and the ocean. Nothing is
# downloaded.
# Usage: check_consumer.sh SOURCE_DIR BUILD_DIR cmake|pkgconfig
set -euo pipefail
src="$1" build="$2" mode="$3"
work="$build/test-output/package/consumer-$mode"
source "$src/tests/package/stage.sh"

exe="$work/consumer"
case "$mode" in
  cmake)
    cmake -S "$src/tests/package/consumer" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$stage" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$work/configure.log" 2>&1 \
      || { cat "$work/configure.log"; exit 1; }
    grep -q "toyhost_DIR:PATH=$stage/" "$work/build/CMakeCache.txt" \
      || { echo "find_package found a toyhost outside the staging prefix:"; grep toyhost_DIR "$work/build/CMakeCache.txt"; exit 1; }
    cmake --build "$work/build" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
    exe="$work/build/consumer" ;;
  pkgconfig)
    export PKG_CONFIG_PATH="$stage/lib/pkgconfig"
    flags="$(pkg-config --cflags --libs toyhost)"
    [[ "$flags" == *"-I$stage/"* ]] \
      || { echo "pkg-config toyhost does not point into the staging prefix: $flags"; exit 1; }
    # shellcheck disable=SC2086
    g++ -std=c++20 -O1 "$src/tests/package/consumer/consumer.cpp" -o "$exe" $flags \
      -Wl,-rpath,"$(pkg-config --variable=libdir toyhost)" ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
# ldd's whole output first: `ldd | grep -q` under pipefail fails when grep exits early and ldd
# gets SIGPIPE on its next line (seen on CI).
libs="$(ldd "$exe")"
grep -q "$stage/.*libtoyhost.so" <<<"$libs" \
  || { echo "the consumer does not load the staged libtoyhost.so:"; echo "$libs"; exit 1; }

compare() {  # compare NAME SHADERTOY SIZE FRAMES
  local name="$1" shadertoy="$2" size="$3" frames="$4"
  "$exe" "$shadertoy" "$size" "$frames" "$work/$name.library.raw"
  "$stage/bin/toyhost" run "$shadertoy" --headless --size "$size" --frames "$frames" --fps 30 \
    --date 2026-01-01T00:00:00 --quiet --out - >"$work/$name.cli.raw" 2>"$work/$name.cli.log" \
    || { cat "$work/$name.cli.log"; exit 1; }
  cmp "$work/$name.library.raw" "$work/$name.cli.raw" \
    || { echo "$name: the consumer's frames differ from the CLI's"; exit 1; }
  echo "$name: $frames frames at $size equal to the CLI's ($(stat -c %s "$work/$name.cli.raw") bytes)"
}
compare ripple-pool "$src/shadertoys/ripple-pool" 64x36 4
compare uniform-probe "$src/shadertoys/uniform-probe" 64x36 3
if [[ -e "$src/../shared/shadertoys/MdXyzX/image.glsl" ]]; then
  compare ocean "$src/shadertoys/ocean" 96x54 2
else
  echo "ocean: ../shared/shadertoys is not beside the repository; compared ripple-pool and uniform-probe only"
fi
