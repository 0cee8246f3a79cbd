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
grep -qE "^ Maintainer: .+ <[^@ ]+@[^@ ]+\.[a-z]+>\$" "$work/info.txt" || { echo "the .deb names no maintainer with an address"; status=1; }
if grep -qE "^ Maintainer: .*@localhost" "$work/info.txt"; then echo "the maintainer is a placeholder"; status=1; fi
# Debian's copyright file, and a shlibs file naming libtoyhost by its SONAME (and nothing CPack had
# to warn about: the Python module has no SONAME and is not in it).
dpkg-deb --fsys-tarfile "$deb" | tar -xO ./usr/share/doc/toyhost/copyright >"$work/copyright" 2>/dev/null \
  || { echo "the .deb lacks /usr/share/doc/toyhost/copyright"; status=1; }
grep -q "^Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/" "$work/copyright" \
  || { echo "the copyright file is not in Debian's format"; status=1; }
dpkg-deb -e "$deb" "$work/control"
soname="$(readelf -d "$build"/runtime/libtoyhost.so | sed -n 's/.*Library soname: \[libtoyhost\.so\.\(.*\)\]/\1/p')"
grep -qx "libtoyhost $soname toyhost (>= $version)" "$work/control/shlibs" \
  || { echo "shlibs does not name libtoyhost $soname:"; cat "$work/control/shlibs"; status=1; }
if grep -qi "missing soname" "$work/cpack.log"; then echo "cpack warned:"; grep -i -B2 "missing soname" "$work/cpack.log"; status=1; fi
depends="$(sed -n 's/^ Depends: //p' "$work/info.txt")"
for package in libegl1 libgles2 libdeflate0 libfftw3-single3 libstdc++6 libc6; do
  [[ ", $depends" == *", $package "* || ", $depends," == *", $package,"* ]] \
    || { echo "Depends lacks $package (dpkg-shlibdeps should have found it): $depends"; status=1; }
done
grep -q "libopenexr\|libOpenEXR" <<<"$depends" || { echo "Depends lacks OpenEXR: $depends"; status=1; }
for file in ./usr/bin/toyhost ./usr/bin/toyhost-compat ./usr/lib/libtoyhost.so ./usr/include/toyhost/Session.h \
            ./usr/include/toyhost/Version.h ./usr/lib/cmake/toyhost/toyhostConfig.cmake ./usr/lib/pkgconfig/toyhost.pc \
            ./usr/share/man/man1/toyhost.1.gz ./usr/share/bash-completion/completions/toyhost; do
  grep -qE " $file( ->|\$)" "$work/contents.txt" || { echo "the .deb lacks $file"; status=1; }
done

# The Python module goes where Debian's python3 looks (dist-packages for every Python 3), and the
# package depends on the Python it was built for and numpy; the description says so.
grep -qE " \./usr/lib/python3/dist-packages/toyhost/_toyhost\.cpython-[0-9]+-.*\.so\$" "$work/contents.txt" \
  || { echo "the .deb lacks the Python module in /usr/lib/python3/dist-packages/toyhost"; status=1; }
grep -qE " \./usr/lib/python3/dist-packages/toyhost/(py\.typed|__init__\.py)\$" "$work/contents.txt" \
  || { echo "the .deb lacks the Python package files"; status=1; }
if grep -q "python3\.[0-9]*/dist-packages" "$work/contents.txt"; then echo "the .deb installs into a versioned dist-packages"; status=1; fi
grep -qE "python3 \(>= 3\.[0-9]+\)" <<<"$depends" || { echo "Depends lacks python3 (>= 3.X): $depends"; status=1; }
[[ ", $depends," == *", python3-numpy,"* || ", $depends" == *", python3-numpy" ]] || { echo "Depends lacks python3-numpy: $depends"; status=1; }
grep -q "Python module" "$work/info.txt" || { echo "the description does not mention the Python module"; status=1; }
gzip -t <(dpkg-deb --fsys-tarfile "$deb" | tar -xO ./usr/share/man/man1/toyhost.1.gz) \
  || { echo "the man page is not gzipped"; status=1; }

# apt would install it here: its Depends are satisfiable (a simulation, nothing installed).
apt-get install -s "$deb" >"$work/apt.txt" 2>&1 || true
grep -q "^Inst toyhost " "$work/apt.txt" || { echo "apt-get install -s $deb:"; cat "$work/apt.txt"; status=1; }

# What it unpacks runs (its libraries come from the system, as Depends says).
dpkg-deb -x "$deb" "$work/root"
"$work/root/usr/bin/toyhost" --version | grep -qF "$version" || { echo "the unpacked toyhost --version does not say $version"; status=1; }
# ... and so does its Python module, run from a folder of no build (the unpacked /usr standing in for
# an installed one: its library from there, numpy from the system).
(cd "$work" && PYTHONPATH="$work/root/usr/lib/python3/dist-packages" LD_LIBRARY_PATH="$work/root/usr/lib" \
  /usr/bin/python3 -c "
import toyhost
assert toyhost.__file__.startswith('$work/root/usr/lib/python3/dist-packages/'), toyhost.__file__
with toyhost.Session(toyhost.from_code('void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0, 1.0, 0.0, 1.0); }'), size=(4, 4)) as s:
    s.step()
    assert s.frame()[0, 0].tolist() == [0, 255, 0, 255], s.frame()[0, 0]
") || { echo "the unpacked Python module does not render"; status=1; }
exit $status
