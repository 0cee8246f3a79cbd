#!/usr/bin/env bash
# Checks what docs/architecture.md says about the tree against the tree:
# - every path it names exists: a backticked word holding a slash and no space, parenthesis or
#   quote, from the source directory or, as the includes name them, from runtime/
#   (`core/Defaults.h`); placeholders (a `<build>`, `...`, `*`, or a capitals-only segment such as
#   `runtime/M/`) are not paths;
# - the module table ("## The modules") has one row per module of MODULES_TXT (the graph the
#   configure step writes from runtime/CMakeLists.txt, "module: dep dep ..." lines), and its "uses"
#   column lists exactly that module's DEPS: module names, comma-separated, "-" for none;
# - the layers table ("## The seams") names every module in exactly one layer;
# - every size claim holds. A claim names its file just before it: "`PATH` is under N lines"
#   (fewer than N), "`PATH` is N lines" (exactly N, as `wc -l` counts) or "`PATH` is limited to N
#   lines" (the limit arch.file_sizes applies to it, a runtime source file; check_sizes.sh
#   --limit-of says which). Any other number of lines in the page ("about 300 lines") is a claim
#   nobody checks, and fails.
# Prints every violation. Usage: check_docs_facts.sh SOURCE_DIR MODULES_TXT
set -euo pipefail
src="$1" graph="$2"
doc="$src/docs/architecture.md"
status=0
fail() { echo "docs facts: $*"; status=1; }
[[ -f "$doc" ]] || { fail "docs/architecture.md is missing"; exit 1; }

# sort_into NAME WORDS...: the words sorted, each followed by a space, into the variable NAME
# (plain bash: it runs for every row, and the check runs many times in its self-test).
sort_into() {
  local -n out="$1"
  shift
  local ordered=() word i
  for word in "$@"; do
    for ((i = ${#ordered[@]}; i > 0; i--)); do
      [[ "${ordered[i - 1]}" > "$word" ]] || break
      ordered[i]="${ordered[i - 1]}"
    done
    ordered[i]="$word"
  done
  out=""
  for word in "${ordered[@]}"; do out+="$word "; done
}

sorted="" listed=""  # set by sort_into
declare -A deps
while IFS=: read -r module list; do
  [[ -z "$module" ]] && continue
  # shellcheck disable=SC2086  # the list is words
  sort_into sorted $list
  deps[$module]="$sorted"
done < "$graph"
(( ${#deps[@]} > 0 )) || fail "$graph declares no module"

# The lines of the section whose heading starts with $1 ("## The modules"), up to the next "## ".
section() { awk -v heading="$1" 'index($0, heading) == 1 {inside = 1; next} /^## / {inside = 0} inside' "$doc"; }
# A cell's items, comma-separated, without backticks, a trailing slash or surrounding spaces, into
# the array `items`.
cell_items() {
  local item
  items=()
  IFS=, read -ra parts <<<"${1//\`/}"
  for item in "${parts[@]}"; do
    item="${item#"${item%%[! ]*}"}" item="${item%"${item##*[! ]}"}" item="${item%/}"
    [[ -n "$item" ]] && items+=("$item")
  done
  return 0
}

# --- every path named exists --------------------------------------------------------------------
paths=0
while IFS= read -r token; do
  [[ "$token" == */* && "$token" != *[[:space:]\(\)\"\'\<\*]* && "$token" != *...* ]] || continue
  [[ "/$token/" =~ /[A-Z]+/ ]] && continue  # a placeholder segment: runtime/M/, runtime/NAME/
  paths=$((paths + 1))
  [[ -e "$src/$token" || -e "$src/runtime/$token" ]] ||
    fail "docs/architecture.md names $token, which does not exist (from the source directory or runtime/)"
done < <(grep -o '`[^`]*`' "$doc" | tr -d '`')
(( paths > 0 )) || fail "docs/architecture.md names no path"

# --- the module table: one row per module, "uses" = DEPS ------------------------------------------
declare -A rows
while IFS='|' read -r _ first _ uses _; do
  cell_items "$first"
  module="${items[0]:-}"
  if [[ -z "${deps[$module]+x}" ]]; then
    fail "the module table has a row for $module, which runtime/CMakeLists.txt does not declare"; continue
  fi
  [[ -n "${rows[$module]+x}" ]] && fail "the module table has two rows for $module"
  rows[$module]=1
  cell_items "$uses"
  [[ "${items[*]}" == - ]] && items=()
  for word in "${items[@]}"; do
    [[ -n "${deps[$word]+x}" ]] || fail "the module table's row for $module uses \"$word\", which is not a module"
  done
  sort_into listed "${items[@]}"
  [[ "$listed" == "${deps[$module]}" ]] ||
    fail "the module table's row for $module uses [${listed% }], its DEPS are [${deps[$module]% }]"
done < <(section "## The modules" | grep -E '^\| `')
for module in "${!deps[@]}"; do
  [[ -n "${rows[$module]+x}" ]] || fail "the module table has no row for $module"
done

# --- the layers table: every module in exactly one layer ----------------------------------------
declare -A layer_of
layer_rows=0
while IFS='|' read -r _ layer cell _; do
  layer_rows=$((layer_rows + 1))
  for module in $(grep -o '`[^`]*`' <<<"$cell" | tr -d '`'); do
    if [[ -z "${deps[$module]+x}" ]]; then
      fail "the layers table's row \"${layer# }\" names $module, which is not a module"
    elif [[ -n "${layer_of[$module]+x}" ]]; then
      fail "the layers table names $module in two layers"
    fi
    layer_of[$module]=1
  done
done < <(section "## The seams" | awk '/^\| layer \| modules \|/ {inside = 1; next} inside && /^\|---/ {next}
                                       inside && /^\|/ {print; next} {inside = 0}')
(( layer_rows > 0 )) || fail "\"## The seams\" has no layers table (| layer | modules | GL? |)"
for module in "${!deps[@]}"; do
  [[ -n "${layer_of[$module]+x}" ]] || fail "the layers table names $module in no layer"
done

# --- size claims --------------------------------------------------------------------------------
# The page as one line, so that a claim wrapped over two lines is still one claim.
text="$(tr '\n' ' ' < "$doc" | tr -s ' ')"
claim_re='`([^` ]+)` is (under |limited to )?([0-9]+) lines'
claims=0
while IFS= read -r claim; do
  [[ "$claim" =~ $claim_re ]] || continue
  path="${BASH_REMATCH[1]}" kind="${BASH_REMATCH[2]}" n="${BASH_REMATCH[3]}"
  claims=$((claims + 1))
  if [[ ! -f "$src/$path" ]]; then
    fail "\"$claim\": $path is not a file"; continue
  fi
  actual=$(wc -l < "$src/$path")
  case "$kind" in
    "under ") (( actual < n )) || fail "\"$claim\", but it has $actual lines" ;;
    "limited to ")
      if [[ "$path" != runtime/*.cpp && "$path" != runtime/*.h ]]; then
        fail "\"$claim\", but arch.file_sizes limits runtime source files only"; continue
      fi
      limit="$("$src/tests/arch/check_sizes.sh" --limit-of "$path")"
      (( limit == n )) || fail "\"$claim\", but arch.file_sizes limits it to $limit (tests/arch/check_sizes.sh)" ;;
    *) (( actual == n )) || fail "\"$claim\", but it has $actual lines" ;;
  esac
done < <(grep -oE "$claim_re" <<<"$text" || true)
while IFS= read -r other; do
  fail "\"$other\" is a size claim in no checked form (\`PATH\` is [under |limited to ]N lines)"
done < <(sed -E "s/$claim_re//g" <<<"$text" | grep -oE '([^ ]+ ){0,3}[0-9][0-9,]*( |-)lines?\b' || true)

if (( status == 0 )); then
  echo "docs facts: docs/architecture.md names $paths existing paths, its module table is the DEPS of ${#deps[@]} modules, each in one layer; its $claims size claim(s) hold"
fi
exit $status
