#!/usr/bin/env bash
# `cpack -G DEB` makes Debian's package set (docs/packaging.md): the shared library package named
# from its SONAME (libtoyhost.so.0.1: libtoyhost0.1) with only the versioned library, its shlibs and
# an ldconfig trigger (no maintainer scripts); libtoyhost-dev (headers, .so link, CMake package,
# pkg-config) depending on exactly that library version; python3-toyhost (the module in
# dist-packages, for the Python it was built for, with numpy); toyhost (programs, man pages,
# completion, docs). Each has its copyright file and changelog, stripped binaries, a description
# in 80 columns and a Depends computed by dpkg-shlibdeps; together they hold what `cmake --install`
# installs; apt would install them (simulated); lintian finds no error and no warning that
# docs/packaging.md does not explain; and the unpacked toyhost and Python module run.
# Usage: check_deb.sh SOURCE_DIR BUILD_DIR VERSION [PYBIND11_VERSION]
set -euo pipefail
src="$1" build="$2" version="$3" pybind11="${4:-}"
work="$build/test-output/package/deb"
rm -rf "$work" && mkdir -p "$work"
(cd "$build" && cpack -G DEB -B "$work" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; exit 1; }
status=0
fail() { echo "$*"; status=1; }

# The package names: the library's from its SONAME as Debian's policy has it.
soname="$(readelf -d "$build"/runtime/libtoyhost.so | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')"
soversion="${soname#libtoyhost.so.}"
lib="libtoyhost$soversion"
packages=("$lib" libtoyhost-dev toyhost)
python=0
[[ -d "$build/python/toyhost" ]] && { python=1; packages+=(python3-toyhost); }
mapfile -t made < <(cd "$work" && ls -- *.deb | sed 's/_.*//' | sort)
[[ "$(printf '%s\n' "${packages[@]}" | sort)" == "$(printf '%s\n' "${made[@]}")" ]] \
  || fail "cpack made ${made[*]}, not ${packages[*]}"
if grep -qi "missing soname\|CMake Warning" "$work/cpack.log"; then fail "cpack warned:"; cat "$work/cpack.log"; fi

declare -A deb depends
for p in "${packages[@]}"; do
  deb[$p]="$(ls "$work/$p"_*.deb 2>/dev/null | head -1)"
  [[ -n "${deb[$p]}" ]] || { fail "no .deb for $p"; continue; }
  d="$work/$p"
  dpkg-deb -I "${deb[$p]}" >"$d.info"
  dpkg-deb -c "${deb[$p]}" | awk '{print $6}' | sed 's|/$||' >"$d.contents"
  dpkg-deb -e "${deb[$p]}" "$d.control"
  dpkg-deb -x "${deb[$p]}" "$work/root"
  dpkg-deb -x "${deb[$p]}" "$d.root"
  depends[$p]="$(sed -n 's/^ Depends: //p' "$d.info")"
  # The version is the project's with a Debian revision; the maintainer a real address.
  grep -qE "^ Version: $version-[0-9]+\$" "$d.info" || fail "$p's version is not $version-REVISION"
  grep -qE "^ Maintainer: .+ <[^@ ]+@[^@ ]+\.[a-z]+>\$" "$d.info" || fail "$p names no maintainer with an address"
  if grep -qE "^ Maintainer: .*@localhost" "$d.info"; then fail "$p's maintainer is a placeholder"; fi
  # The description: a summary and lines of at most 80 columns.
  dpkg-deb -f "${deb[$p]}" Description | awk -v p="$p" 'length($0) > 80 {print p ": description line over 80 columns: " $0; bad=1} END {exit bad}' \
    || status=1
  # Debian's copyright file and changelog in /usr/share/doc/PKG.
  grep -q "^Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/" "$d.root/usr/share/doc/$p/copyright" 2>/dev/null \
    || fail "$p lacks /usr/share/doc/$p/copyright in Debian's format"
  zcat "$d.root/usr/share/doc/$p/changelog.Debian.gz" 2>/dev/null | head -1 | grep -qE "^toyhost \($version-[0-9]+\) " \
    || fail "$p lacks /usr/share/doc/$p/changelog.Debian.gz naming version $version"
  # Binaries stripped; an ELF that needs libtoyhost makes its package depend on the library package.
  while IFS= read -r f; do
    file -b "$f" | grep -q "not stripped" && fail "$p: ${f#"$d.root"} is not stripped"
    if readelf -d "$f" | grep -q "NEEDED.*\[$soname\]" && [[ ", ${depends[$p]}" != *", $lib "* ]]; then
      fail "$p: ${f#"$d.root"} needs $soname but Depends lacks $lib: ${depends[$p]}"
    fi
  done < <(find "$d.root" -type f -exec sh -c 'file -b "$1" | grep -q "^ELF"' _ {} \; -print)
done
has() { grep -qxF "./$2" "$work/$1.contents" || fail "$1 lacks /$2"; }
lacks() { if grep -qE "$2" "$work/$1.contents"; then fail "$1 holds $(grep -E "$2" "$work/$1.contents" | head -3 | tr '\n' ' ')"; fi; }
depends_on() { [[ ", ${depends[$1]}," == *", $2,"* || ", ${depends[$1]}," == *", $2 ("* ]] || fail "$1's Depends lacks $2: ${depends[$1]}"; }

# The library: the versioned files only, its shlibs naming it by SONAME, an ldconfig trigger, no
# maintainer scripts, and what the library links computed by dpkg-shlibdeps.
has "$lib" "usr/lib/$soname"
has "$lib" "usr/lib/$soname.${version##*.}"
lacks "$lib" '^\./usr/(include|bin|share/man)|\.so$'
grep -qx "libtoyhost $soversion $lib (>= $version)" "$work/$lib.control/shlibs" \
  || { fail "shlibs does not name libtoyhost $soversion $lib:"; cat "$work/$lib.control/shlibs" || true; }
grep -qx "activate-noawait ldconfig" "$work/$lib.control/triggers" 2>/dev/null || fail "$lib has no ldconfig trigger"
for script in preinst postinst prerm postrm; do
  [[ ! -e "$work/$lib.control/$script" ]] || fail "$lib has a $script: $(cat "$work/$lib.control/$script")"
done
for package in libegl1 libgles2 libdeflate0 libfftw3-single3 libstdc++6 libc6; do depends_on "$lib" "$package"; done
grep -q "libopenexr\|libOpenEXR" <<<"${depends[$lib]}" || fail "$lib's Depends lacks OpenEXR: ${depends[$lib]}"

# The development files, on exactly this library version.
for f in usr/lib/libtoyhost.so usr/include/toyhost/Session.h usr/include/toyhost/Version.h \
         usr/lib/cmake/toyhost/toyhostConfig.cmake usr/lib/pkgconfig/toyhost.pc; do has libtoyhost-dev "$f"; done
lacks libtoyhost-dev '\.so\.[0-9]'
debversion="$(dpkg-deb -f "${deb[$lib]}" Version)"
depends_on libtoyhost-dev "$lib (= $debversion)"

# The programs, man pages, completion and docs; their libraries computed (EGL, GLES, PNG, ...).
for f in usr/bin/toyhost usr/bin/toyhost-compat usr/share/man/man1/toyhost.1.gz usr/share/man/man1/toyhost-compat.1.gz \
         usr/share/bash-completion/completions/toyhost usr/share/doc/toyhost/README.md; do has toyhost "$f"; done
for package in libegl1 libgles2 libdeflate0 libstdc++6 libc6; do depends_on toyhost "$package"; done
gzip -t "$work/toyhost.root/usr/share/man/man1/toyhost.1.gz" || fail "the man page is not gzipped"

# The Python module where Debian's python3 looks, for the Python it was built for, with numpy
# (numpy 1 only when pybind11 is older than 2.12: Debian's numpy 1 versions have epoch 1).
if ((python)); then
  grep -qE "^\./usr/lib/python3/dist-packages/toyhost/_toyhost\.cpython-[0-9]+-.*\.so\$" "$work/python3-toyhost.contents" \
    || fail "python3-toyhost lacks the module in /usr/lib/python3/dist-packages/toyhost"
  has python3-toyhost usr/lib/python3/dist-packages/toyhost/__init__.py
  has python3-toyhost usr/lib/python3/dist-packages/toyhost/py.typed
  lacks python3-toyhost 'python3\.[0-9]+/dist-packages|^\./usr/(bin|include)'
  grep -qE "(^|, )python3 \(>= 3\.[0-9]+\), python3 \(<< 3\.[0-9]+\)" <<<"${depends[python3-toyhost]}" \
    || fail "python3-toyhost's Depends lacks python3 (>= 3.X), python3 (<< 3.X+1): ${depends[python3-toyhost]}"
  if [[ -n "$pybind11" ]] && dpkg --compare-versions "$pybind11" lt 2.12; then
    depends_on python3-toyhost "python3-numpy (<< 1:2)"
  else
    depends_on python3-toyhost python3-numpy
  fi
  abi="$(sed -n 's/^abi \([0-9]*\)$/\1/p' /usr/share/numpy3/versions 2>/dev/null || true)"
  [[ -z "$abi" ]] || depends_on python3-toyhost "python3-numpy-abi$abi"
  grep -q "Python module" "$work/python3-toyhost.info" || fail "python3-toyhost's description does not mention the Python module"
fi

# Together they hold every file `cmake --install` installs under /usr (and only the Debian
# changelogs and copyright files beside).
DESTDIR="$work/install" cmake --install "$build" --prefix /usr >"$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }
(cd "$work/install" && find . ! -type d | sort) >"$work/installed.txt"
(cd "$work/root" && find . ! -type d | grep -vE '^\./usr/share/doc/[^/]+/changelog\.Debian\.gz$' \
  | grep -vxE "\./usr/share/doc/(${lib//./\\.}|libtoyhost-dev|python3-toyhost)/copyright" | sort) >"$work/packaged.txt"
diff "$work/installed.txt" "$work/packaged.txt" >"$work/installed-vs-packaged.diff" \
  || { fail "the packages do not hold what cmake --install installs (< installed only, > packaged only):"; cat "$work/installed-vs-packaged.diff"; }

# apt would install the set here: its Depends are satisfiable (a simulation, nothing installed).
debs=(); for p in "${packages[@]}"; do debs+=("${deb[$p]}"); done
apt-get install -s "${debs[@]}" >"$work/apt.txt" 2>&1 || true
for p in "${packages[@]}"; do grep -q "^Inst $p " "$work/apt.txt" || { fail "apt-get install -s would not install $p:"; cat "$work/apt.txt"; }; done

# lintian: no error, and no warning that docs/packaging.md's allow-list does not explain (its
# table rows "| `W: TAG` | why |" under "lintian").
mapfile -t allowed < <(sed -n 's/^| `W: \([a-z0-9+.-]*\)` |.*/\1/p' "$src/docs/packaging.md")
for p in "${packages[@]}"; do
  lintian --no-cfg --display-level ">=warning" "${deb[$p]}" >"$work/$p.lintian" 2>&1 || true
  while IFS= read -r line; do
    case "$line" in
      E:*) fail "lintian: $line" ;;
      W:*) tag="$(sed -E 's/^W: [^:]+: ([^ ]+).*/\1/' <<<"$line")"
           printf '%s\n' "${allowed[@]}" | grep -qxF "$tag" || fail "lintian (not explained in docs/packaging.md): $line" ;;
    esac
  done <"$work/$p.lintian"
done

# What they unpack runs (their libraries come from the system, as Depends says).
"$work/root/usr/bin/toyhost" --version | grep -qF "$version" || fail "the unpacked toyhost --version does not say $version"
# ... and so does the Python module, run from a folder of no build (the unpacked /usr standing in
# for an installed one: numpy from the system).
if ((python)); then
  (cd "$work" && PYTHONPATH="$work/root/usr/lib/python3/dist-packages" LD_LIBRARY_PATH="$work/root/usr/lib" \
    /usr/bin/python3 -c "
import toyhost
assert toyhost.__file__.startswith('$work/root/usr/lib/python3/dist-packages/'), toyhost.__file__
with toyhost.Session(toyhost.from_code('void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0, 1.0, 0.0, 1.0); }'), size=(4, 4)) as s:
    s.step()
    assert s.frame()[0, 0].tolist() == [0, 255, 0, 255], s.frame()[0, 0]
") || fail "the unpacked Python module does not render"
fi
exit $status
