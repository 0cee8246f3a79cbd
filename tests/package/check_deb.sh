#!/usr/bin/env bash
# `cpack -G DEB` makes toyhost_VERSION_ARCH.deb: its control says the project version and a Depends
# computed by dpkg-shlibdeps (the EGL, GLES, PNG, OpenEXR, FFTW and C++ runtime packages, none
# typed by hand), it holds the programs, library, headers, CMake and pkg-config files, man page and
# completion under /usr, apt would install it (simulated) and the toyhost it unpacks runs.
# Usage: check_deb.sh SOURCE_DIR BUILD_DIR VERSION
set -euo pipefail
src="$1" build="$2" version="$3"
work="$build/test-output/package/deb"
rm -rf "$work" && mkdir -p "$work"
(cd "$build" && cpack -G DEB -B "$work" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; exit 1; }
deb="$(ls "$work"/toyhost_"$version"_*.deb)"
dpkg-deb -I "$deb" >"$work/info.txt"
dpkg-deb -c "$deb" >"$work/contents.txt"
cat "$work/info.txt"

status=0
grep -qE "^ Version: $version\$" "$work/info.txt" || { echo "the .deb's version is not $version"; status=1; }
grep -qE "^ Maintainer: .+" "$work/info.txt" || { echo "the .deb names no maintainer"; status=1; }
depends="$(sed -n 's/^ Depends: //p' "$work/info.txt")"
for package in libegl1 libgles2 libdeflate0 libfftw3-single3 libstdc++6 libc6; do
  [[ ", $depends" == *", $package "* || ", $depends," == *", $package,"* ]] \
    || { echo "Depends lacks $package (dpkg-shlibdeps should have found it): $depends"; status=1; }
done
grep -q "libopenexr\|libOpenEXR" <<<"$depends" || { echo "Depends lacks OpenEXR: $depends"; status=1; }
for file in ./usr/bin/toyhost ./usr/bin/toyhost-compat ./usr/lib/libtoyhost.so ./usr/include/toyhost/Session.h \
            ./usr/include/toyhost/Version.h ./usr/lib/cmake/toyhost/toyhostConfig.cmake ./usr/lib/pkgconfig/toyhost.pc \
            ./usr/share/man/man1/toyhost.1 ./usr/share/bash-completion/completions/toyhost; do
  grep -qE " $file( ->|\$)" "$work/contents.txt" || { echo "the .deb lacks $file"; status=1; }
done

# apt would install it here: its Depends are satisfiable (a simulation, nothing installed).
apt-get install -s "$deb" >"$work/apt.txt" 2>&1 || true
grep -q "^Inst toyhost " "$work/apt.txt" || { echo "apt-get install -s $deb:"; cat "$work/apt.txt"; status=1; }

# What it unpacks runs (its libraries come from the system, as Depends says).
dpkg-deb -x "$deb" "$work/root"
"$work/root/usr/bin/toyhost" --version | grep -qF "$version" || { echo "the unpacked toyhost --version does not say $version"; status=1; }
exit $status
