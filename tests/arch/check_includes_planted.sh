#!/usr/bin/env bash
# The include check (check_includes.sh) can fail: on a copy of the sources in a temporary folder it
# passes as the tree is, then fails, naming the file, on each include planted in turn in tools/
# and python/src that their declarations (toyhost_include_rules) do not allow, and in a module of
# runtime/ that its declared dependencies do not allow; and on a facade header of the public API
# included in an engine module or a vocabulary header, and on an exception to that rule whose
# include is gone.
# Usage: check_includes_planted.sh SOURCE_DIR MODULES_TXT CLIENTS_TXT
set -euo pipefail
src="$1" graph="$2" clients="$3"
check="$(dirname "${BASH_SOURCE[0]}")/check_includes.sh"
copy="$(mktemp -d)"
trap 'rm -rf "$copy"' EXIT
mkdir -p "$copy/python"
cp -r "$src/runtime" "$src/tools" "$src/include" "$copy/"
cp -r "$src/python/src" "$copy/python/"

status=0
if ! output="$("$check" "$copy" "$graph" "$clients" 2>&1)"; then
  echo "the unchanged copy fails the check already:"; echo "$output"; exit 1
fi

# plant FILE LINE [RULE]: the check must fail and name FILE (with RULE's words, when given); the
# file goes again afterwards.
plant() {
  local file="$1" line="$2" rule="${3:-}" output
  mkdir -p "$(dirname "$copy/$file")"
  printf '%s\n' "$line" > "$copy/$file"
  if output="$("$check" "$copy" "$graph" "$clients" 2>&1)"; then
    echo "FAIL: $file with '$line' passed the include check"; status=1
  elif ! grep -F "$file" <<<"$output" | grep -qF "$rule"; then
    echo "FAIL: $file with '$line' failed the check without naming it${rule:+ and \"$rule\"}:"; echo "$output"; status=1
  else
    echo "ok: $file with '$line' is refused"
  fi
  rm -f "$copy/$file"
}

plant python/src/Planted.cpp '#include "core/Defaults.h"'            # an internal header in Python
plant python/src/Planted.h '#include <session/SessionCore.h>'        # also in angle brackets
plant tools/toyhost/Planted.cpp '#include "player/Player.h"'         # under the session, from the CLI
plant tools/toyhost/Planted.cpp '#include "../../runtime/core/Defaults.h"'  # by path
plant tools/compat/Planted.cpp '#include "render/Renderer.h"'        # beyond what compat declares
plant tools/bench/Planted.cpp '#include "core/Result.h"'
plant tools/newtool/Planted.cpp '#include "core/Result.h"'           # a tool declaring nothing: public only
plant runtime/core/Planted.cpp '#include "gl/GlThread.h"'            # and the runtime's own graph
facade="includes the facade header"
plant runtime/render/Planted.cpp '#include <toyhost/Session.h>' "$facade"   # a facade header in the engine
plant runtime/drivers/window/Planted.h '#include "toyhost/Shadertoy.h"' "$facade"
plant runtime/compare/Planted.cpp '#include <toyhost/Compare.h>' "$facade"  # beside the module's exceptions
plant include/toyhost/Planted.h '#include <toyhost/Session.h>' "$facade"    # in a vocabulary header

# An exception whose include is gone fails: a copy of the check excepting an include nobody has.
sed 's|^facade_exceptions=($|&\n  "runtime/core/Result.h toyhost/Session.h"|' "$check" > "$copy/check_includes.sh"
chmod +x "$copy/check_includes.sh"
if output="$("$copy/check_includes.sh" "$copy" "$graph" "$clients" 2>&1)"; then
  echo "FAIL: a stale facade exception passed the include check"; status=1
elif ! grep -qF '"runtime/core/Result.h toyhost/Session.h", an include that is gone' <<<"$output"; then
  echo "FAIL: a stale facade exception failed the check without naming it:"; echo "$output"; status=1
else
  echo "ok: a stale facade exception is refused"
fi
exit $status
