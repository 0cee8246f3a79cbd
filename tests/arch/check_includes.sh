#!/usr/bin/env bash
# Checks the runtime's layering against the module graph runtime/CMakeLists.txt declares (written
# at configure time as "module: dep dep ..." lines): every `#include "other/..."` in a module's
# files names the module itself or one of its declared dependencies, and the graph has no cycle,
# so no module includes a higher one. Then the runtime's users, tools/*/ and python/src: each may
# include the public headers (<toyhost/...>) and only the runtime modules its CLIENTS_TXT line
# declares ("tools/compat: core player ...", written from toyhost_include_rules() calls at
# configure time); a folder without a line may include the public headers only. Prints every
# violation. No engine module (all but api) includes a facade header of the public API, and no other
# public header does (facade_headers, below, with the known exceptions).
# Usage: check_includes.sh SOURCE_DIR MODULES_TXT [CLIENTS_TXT]
set -euo pipefail
src="$1" graph="$2" clients="${3:-}"
declare -A deps
while IFS=: read -r module list; do
  deps[$module]="$list"
done < "$graph"

# The module an included path belongs to, into $target: the longest declared module that is a
# prefix of its folder ("drivers/window/WindowContext.h" -> drivers/window), or its first folder
# when none is. No subshell: the check runs over every include of the tree, several times in tests.
module_of() {
  local path="$1" m
  target=""
  for m in "${!deps[@]}"; do
    if [[ "$path" == "$m/"* && ${#m} -gt ${#target} ]]; then target="$m"; fi
  done
  [[ -n "$target" ]] || target="${path%%/*}"
}
include_re='^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]([^">]+)[">]'

status=0
for module in "${!deps[@]}"; do
  allowed=" $module ${deps[$module]} "
  while IFS= read -r line; do
    file="${line%%:*}"
    [[ "${line#*:}" =~ $include_re ]] || continue
    module_of "${BASH_REMATCH[1]}"
    if [[ "$allowed" != *" $target "* ]]; then
      echo "layering: ${file#$src/} includes $target/, which $module does not declare (declared: ${deps[$module]:- none})"
      status=1
    fi
  done < <(grep -HE '^\s*#include "[^/"]+/' "$src/runtime/$module"/*.h "$src/runtime/$module"/*.cpp 2>/dev/null || true)
done

# The public API's facade headers: classes and functions that the api module implements over the
# engine (Shadertoy holds the engine's ManifestDesc, Session runs a SessionCore, compareShadertoys
# two Sessions). No engine module (every module but api) includes one: it would depend on the layer
# built on it. The engine uses the public vocabulary headers (Result.h, Diagnostic.h, Input.h,
# Defaults.h, ...), and those include no facade header, so none reaches the engine through them.
facade_headers=(toyhost/Session.h toyhost/Compare.h toyhost/Shadertoy.h)
# Known includes of a facade header in the engine, "FILE HEADER", each with its reason. An entry
# whose include is gone fails the check, so the list only shrinks.
facade_exceptions=(
)
declare -A facade_excepted
for entry in "${facade_exceptions[@]}"; do facade_excepted[$entry]=0; done
# facade_includes WHO FILE...: every include of a facade header in the files fails, unless excepted.
facade_includes() {
  local who="$1" line file included entry
  shift
  while IFS= read -r line; do
    [[ -z "$line" ]] && continue
    file="${line%%:*}"
    [[ "${line#*:}" =~ $include_re ]] || continue
    included="${BASH_REMATCH[1]}"
    [[ " ${facade_headers[*]} " == *" $included "* ]] || continue
    entry="${file#"$src"/} $included"
    if [[ -n "${facade_excepted[$entry]+x}" ]]; then
      facade_excepted[$entry]=1
    else
      echo "layering: ${file#"$src"/} includes the facade header <$included>, which $who may not (the vocabulary headers only)"
      status=1
    fi
  done < <(grep -HE '^\s*#\s*include\s*["<]toyhost/' "$@" 2>/dev/null || true)
}
for module in "${!deps[@]}"; do
  [[ "$module" == api ]] && continue
  facade_includes "an engine module ($module)" "$src/runtime/$module"/*.h "$src/runtime/$module"/*.cpp
done
vocabulary=()
for header in "$src"/include/toyhost/*; do
  [[ " ${facade_headers[*]} " == *" toyhost/${header##*/} "* ]] || vocabulary+=("$header")
done
facade_includes "a public header that is not a facade" "${vocabulary[@]}"
for entry in "${!facade_excepted[@]}"; do
  if (( ! facade_excepted[$entry] )); then
    echo "layering: check_includes.sh excepts \"$entry\", an include that is gone: remove it from facade_exceptions"
    status=1
  fi
done

# Every runtime folder holding sources is a declared module (folders such as drivers/ only group
# modules).
while IFS= read -r dir; do
  name="${dir#"$src"/runtime/}"
  if [[ -z "${deps[$name]+x}" ]]; then
    echo "layering: runtime/$name is not declared as a module in runtime/CMakeLists.txt"
    status=1
  fi
done < <(find "$src/runtime" -mindepth 1 -type f \( -name '*.h' -o -name '*.cpp' \) -printf '%h\n' | sort -u)

# No cycles: repeatedly remove modules whose dependencies are all removed.
declare -A done
remaining=${#deps[@]}
while (( remaining > 0 )); do
  progress=0
  for module in "${!deps[@]}"; do
    [[ -n "${done[$module]+x}" ]] && continue
    ready=1
    for dep in ${deps[$module]}; do
      [[ -z "${done[$dep]+x}" ]] && ready=0
    done
    if (( ready )); then done[$module]=1; remaining=$((remaining - 1)); progress=1; fi
  done
  if (( !progress )); then
    echo "layering: the module graph has a cycle among the modules not yet ordered"
    status=1
    break
  fi
done

# The runtime's users. Their folders: every tools/*/ holding C++ sources, and python/src.
declare -A uses
if [[ -n "$clients" ]]; then
  while IFS=: read -r folder list; do
    [[ -z "$folder" ]] && continue
    uses[$folder]="$list"
    for module in $list; do
      if [[ -z "${deps[$module]+x}" ]]; then
        echo "layering: $folder declares runtime module $module, which runtime/CMakeLists.txt does not"
        status=1
      fi
    done
  done < "$clients"
fi
client_folders=()
while IFS= read -r dir; do client_folders+=("${dir#"$src"/}"); done < <(
  { find "$src/tools" -mindepth 1 -maxdepth 1 -type d 2>/dev/null; [[ -d "$src/python/src" ]] && echo "$src/python/src"; } | sort)
clients_checked=0
for folder in "${client_folders[@]}"; do
  files="$(find "$src/$folder" -type f \( -name '*.h' -o -name '*.hpp' -o -name '*.cpp' -o -name '*.cc' \) | sort)"
  [[ -z "$files" ]] && continue
  clients_checked=$((clients_checked + 1))
  allowed=" ${uses[$folder]:-} "
  while IFS= read -r line; do
    [[ -z "$line" ]] && continue
    file="${line%%:*}"
    [[ "${line#*:}" =~ $include_re ]] || continue
    included="${BASH_REMATCH[1]}"
    if [[ "$included" == *runtime/* ]]; then
      echo "layering: ${file#$src/} includes $included by its path into runtime/"
      status=1
      continue
    fi
    module_of "$included"
    [[ -z "${deps[$target]+x}" ]] && continue  # not a runtime module: the public headers, a library, its own
    if [[ "$allowed" != *" $target "* ]]; then
      echo "layering: ${file#$src/} includes $target/, which $folder does not declare (declared: ${uses[$folder]:- none: public headers only})"
      status=1
    fi
  done < <(xargs grep -HE '^\s*#\s*include\s*["<][^">]+/' <<<"$files" || true)
done

if (( status == 0 )); then
  echo "layering: ${#deps[@]} modules, every include follows the declared graph, no engine module includes a facade header (${#facade_exceptions[@]} known exceptions); $clients_checked users of the runtime include only what they declare"
fi
exit $status
