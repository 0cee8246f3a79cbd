#!/usr/bin/env bash
# `cmake --install` into a staging prefix puts every installed file in place: the programs, the
# library with its SONAME link, the public headers (no internal ones), the CMake package, the
# pkg-config file, the man page (one section per subcommand of `toyhost --help`), the bash
# completion and the README with its reference pages (docs/); and the installed CLI runs from there.
# Usage: check_install.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src="$1" build="$2"
work="$build/test-output/package/install"
source "$src/tests/package/stage.sh"

status=0
expect() { for f in "$@"; do [[ -e "$stage/$f" ]] || { echo "missing after cmake --install: $f"; status=1; }; done; }
expect bin/toyhost bin/toyhost-compat \
  lib/libtoyhost.so lib/cmake/toyhost/toyhostConfig.cmake lib/cmake/toyhost/toyhostConfigVersion.cmake \
  lib/cmake/toyhost/toyhostTargets.cmake lib/pkgconfig/toyhost.pc \
  share/man/man1/toyhost.1.gz share/man/man1/toyhost-compat.1.gz share/bash-completion/completions/toyhost share/doc/toyhost/README.md \
  share/doc/toyhost/docs/cli.md share/doc/toyhost/docs/manifest.md share/doc/toyhost/docs/library.md
for header in "$src"/include/toyhost/*.h; do expect "include/toyhost/$(basename "$header")"; done
expect include/toyhost/Version.h
soname="$(objdump -p "$stage/lib/libtoyhost.so" | awk '/SONAME/ {print $2}')"
[[ -n "$soname" ]] && expect "lib/$soname" || { echo "libtoyhost.so has no SONAME"; status=1; }

# Only the public headers, and they include nothing but each other and the standard library.
extra="$(find "$stage/include" -type f ! -path "$stage/include/toyhost/*.h")"
[[ -z "$extra" ]] || { echo "installed beside the public headers: $extra"; status=1; }
if grep -hE '^\s*#include' "$stage"/include/toyhost/*.h | grep -vE '#include <(toyhost/[A-Za-z]+\.h|[a-z_]+)>'; then
  echo "a public header includes something that is neither public nor standard (above)"; status=1
fi

"$stage/bin/toyhost" --version | grep -q "$(sed -n 's/.*VERSION_STRING "\(.*\)"/\1/p' "$stage/include/toyhost/Version.h")" \
  || { echo "the installed toyhost --version differs from Version.h"; status=1; }

# The man page: every subcommand has its section (farm's plan, status and join too), every option of `toyhost run` is there.
# Installed compressed (Debian policy); read it uncompressed.
man="$stage/toyhost.1"
gzip -dc "$stage/share/man/man1/toyhost.1.gz" >"$man" || { echo "toyhost.1.gz is not gzip"; status=1; }
subcommands_of() { "$stage/bin/toyhost" "$@" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF {print $1}'; }
for command in $(subcommands_of); do
  grep -q "^\.SS toyhost $command\$" "$man" || { echo "toyhost.1 has no section for $command"; status=1; }
  for sub in $(subcommands_of "$command"); do  # farm plan, status, join
    grep -q "^\.SS toyhost $command $sub\$" "$man" || { echo "toyhost.1 has no section for $command $sub"; status=1; }
  done
done
grep -q "^\.SS toyhost farm plan\$" "$man" || { echo "toyhost.1 has no section for farm plan"; status=1; }
for option in $("$stage/bin/toyhost" run --help | grep -oE '^  -[-a-z,]+' | tr ',' ' '); do
  grep -qF -- "$(sed 's/-/\\-/g' <<<"$option")" "$man" || { echo "toyhost.1 does not document run $option"; status=1; }
done
warnings="$(groff -man -Tutf8 -ww "$man" 2>&1 >/dev/null)"
[[ -z "$warnings" ]] || { echo "groff warns about toyhost.1: $warnings"; status=1; }
grep -q "^\.SH EXIT STATUS" "$man" && grep -q "124" "$man" || { echo "toyhost.1's EXIT STATUS does not list 124"; status=1; }
# toyhost-compat has its page: every option of its --help is in it.
compat_man="$stage/toyhost-compat.1"
gzip -dc "$stage/share/man/man1/toyhost-compat.1.gz" >"$compat_man" || { echo "toyhost-compat.1.gz is not gzip"; status=1; }
for option in $("$stage/bin/toyhost-compat" --help | grep -oE '^  -[-a-z,-]+' | tr ',' ' '); do
  grep -qF -- "$(sed 's/-/\\-/g' <<<"$option")" "$compat_man" || { echo "toyhost-compat.1 does not document $option"; status=1; }
done
warnings="$(groff -man -Tutf8 -ww "$compat_man" 2>&1 >/dev/null)"
[[ -z "$warnings" ]] || { echo "groff warns about toyhost-compat.1: $warnings"; status=1; }

"$src/tests/package/check_completion.sh" "$stage/share/bash-completion/completions/toyhost" "$stage/bin/toyhost" || status=1
exit $status
