#!/usr/bin/env bash
# libtoyhost.so exports the public API only: every dynamic symbol it defines is in namespace toyhost
# and names something declared in include/toyhost/ (no module internals, no GL loader, no
# third-party code), and the API's entry points are among them.
# Usage: check_exports.sh SOURCE_DIR LIBRARY
set -euo pipefail
src="$1" library="$2"
symbols="$(nm -D --defined-only -C "$library" | awk '$2 ~ /[TWDBRVu]/ {$1 = ""; $2 = ""; print substr($0, 3)}')"
status=0
while IFS= read -r symbol; do
  [[ -z "$symbol" ]] && continue
  name="$(sed -E 's/^(typeinfo (name )?for |vtable for )//; s/\(.*//' <<<"$symbol")"
  if [[ "$name" != toyhost::* ]]; then echo "exported, not toyhost's API: $symbol"; status=1; continue; fi
  first="$(sed -E 's/^toyhost::([A-Za-z_0-9]+).*/\1/' <<<"$name")"
  grep -qE "(class|struct|enum class) (TOYHOST_API )?$first\b|TOYHOST_API [^(]*[ *&]$first\(" \
    "$src"/include/toyhost/*.h "$src"/include/toyhost/Version.h.in \
    || { echo "exported, not declared in include/toyhost: $symbol"; status=1; }
done <<<"$symbols"
for api in 'toyhost::Session::createHeadless' 'toyhost::Shadertoy::load' 'toyhost::versionString()' 'toyhost::formatDiagnostics'; do
  grep -qF "$api" <<<"$symbols" || { echo "not exported: $api"; status=1; }
done
echo "$(wc -l <<<"$symbols") symbols exported"
exit $status
