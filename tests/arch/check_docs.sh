#!/usr/bin/env bash
# Checks the map of the documentation: README.md stays a landing page (under 300 lines, the two
# set-up commands unchanged), docs/architecture.md's "Where is X" index answers the questions it
# promises (that the paths it names exist is check_docs_facts.sh's), and every relative link of
# README.md and docs/*.md reaches a file. Prints every violation. Usage: check_docs.sh SOURCE_DIR
set -euo pipefail
src="$1"
status=0
fail() { echo "docs: $*"; status=1; }

# --- README.md: a landing page ---------------------------------------------------------------------
readme="$src/README.md"
if [[ ! -f "$readme" ]]; then
  fail "README.md is missing"
else
  lines=$(wc -l < "$readme")
  (( lines < 300 )) || fail "README.md has $lines lines; the landing page stays under 300 (reference goes to docs/)"
  # The two set-up commands, byte for byte: scripts, CI and people copy them from here.
  for command in \
    "./scripts/main-job.sh   # builds toyhost and renders afl_ext's ocean headless at 1280x720 into out/ocean/*.png" \
    "./scripts/test.sh       # builds everything and runs the whole test suite (CTest)"; do
    grep -Fxq -- "$command" "$readme" || fail "README.md lost the set-up command line: $command"
  done
fi

# --- docs/architecture.md: the "Where is X" index ----------------------------------------------------
arch="$src/docs/architecture.md"
if [[ ! -f "$arch" ]]; then
  fail "docs/architecture.md is missing"
else
  index="$(awk '/^## Where is X/ {inside = 1; next} /^## / {inside = 0} inside' "$arch")"
  [[ -n "$index" ]] || fail "docs/architecture.md has no \"## Where is X\" section"
  # That the files it names exist is checked with every path of the page (check_docs_facts.sh).
  # The questions the index must answer, each in a row of its own that names at least one file.
  for topic in "iMouse" "the watchdog" "PNG writing" "exit codes" "the shader wrapper" "the keyboard texture" \
               "ping-pong" "checkpoints" "video output" "the Python module" "the CLI options" "defaults"; do
    # The row whose first cell, without backticks, starts with the topic.
    row="$(awk -F'|' -v topic="$topic" '{cell = $2; gsub(/`/, "", cell); sub(/^ +/, "", cell)}
                                         index(cell, topic) == 1 {print; exit}' <<<"$index")"
    if [[ -z "$row" ]]; then
      fail "docs/architecture.md's index has no row for \"$topic\""
    elif ! grep -qE '`[^` ]+/[^` ]*`' <<<"$row"; then
      fail "docs/architecture.md's index row for \"$topic\" names no file"
    fi
  done
fi

# --- relative links between the pages ---------------------------------------------------------------
shopt -s nullglob
for page in "$src/README.md" "$src"/docs/*.md; do
  [[ -f "$page" ]] || continue
  dir="${page%/*}"
  while IFS= read -r target; do
    target="${target%%#*}"
    [[ -z "$target" || "$target" == *://* || "$target" == mailto:* ]] && continue
    [[ -e "$dir/$target" ]] || fail "${page#"$src"/} links to $target, which does not exist"
  done < <(grep -oE '\]\([^) ]+\)|(href|src)="[^"]+"' "$page" | sed -E 's/^\]\((.*)\)$/\1/; s/^(href|src)="(.*)"$/\2/')
done

if (( status == 0 )); then echo "docs: README is a landing page, the architecture index answers its questions, every link resolves"; fi
exit $status
