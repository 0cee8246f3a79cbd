#!/usr/bin/env bash
# Checks the runtime's layering against the module graph runtime/CMakeLists.txt declares (written
# at configure time as "module: dep dep ..." lines): every `#include "other/..."` in a module's
# files names the module itself or one of its declared dependencies, and the graph has no cycle,
# so no module includes a higher one. Prints every violation.
# Usage: check_includes.sh SOURCE_DIR MODULES_TXT
set -euo pipefail
src="$1" graph="$2"
declare -A deps
while IFS=: read -r module list; do
  deps[$module]="$list"
done < "$graph"

# The module an included path belongs to: the longest declared module that is a prefix of its
# folder ("drivers/window/WindowContext.h" -> drivers/window), or its first folder when none is.
module_of() {
  local path="$1" best="" m
  for m in "${!deps[@]}"; do
    if [[ "$path" == "$m/"* && ${#m} -gt ${#best} ]]; then best="$m"; fi
  done
  [[ -n "$best" ]] && echo "$best" || echo "${path%%/*}"
}

status=0
for module in "${!deps[@]}"; do
  allowed=" $module ${deps[$module]} "
  while IFS= read -r line; do
    file="${line%%:*}"
    included="$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"$line")"
    target="$(module_of "$included")"
    if [[ "$allowed" != *" $target "* ]]; then
      echo "layering: ${file#$src/} includes $target/, which $module does not declare (declared: ${deps[$module]:- none})"
      status=1
    fi
  done < <(grep -HE '^\s*#include "[^/"]+/' "$src/runtime/$module"/*.h "$src/runtime/$module"/*.cpp 2>/dev/null || true)
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

if (( status == 0 )); then echo "layering: ${#deps[@]} modules, every include follows the declared graph"; fi
exit $status
