#!/usr/bin/env bash
# Shows that check_docs_facts.sh fails on each wrong fact it exists for: a copy of the tree's
# docs/architecture.md (the rest linked in) passes as it is, and with true size claims added; it
# fails, naming the defect, with a path that does not exist (in the index and in the prose), a
# module row whose uses has a module more or one less than its DEPS, or prose instead of modules,
# a module's row gone, a row for a module that is not declared, a module in no layer, a false size
# claim of each form (one wrapped over two lines), a limit claimed for a file arch.file_sizes does
# not check, and a number of lines in no checked form.
# Usage: check_docs_facts_selftest.sh SOURCE_DIR MODULES_TXT WORK_DIR
set -euo pipefail
src="$(cd "$1" && pwd)" graph="$2" work="$3"
check="$src/tests/arch/check_docs_facts.sh"
status=0

# A tree like the source, the rest linked in, with docs/architecture.md a copy that a case may
# change, into $doc.
make_tree() {
  tree="$work/$1"
  rm -rf "$tree" && mkdir -p "$tree"
  ln -s "$src"/* "$tree"/
  rm "$tree/docs" && mkdir "$tree/docs"
  ln -s "$src"/docs/* "$tree/docs/"
  doc="$tree/docs/architecture.md"
  rm "$doc" && cp "$src/docs/architecture.md" "$doc"
}
# change SED_SCRIPT: applies it to the copy's architecture.md, which must change.
change() {
  sed -i.before "$1" "$doc"
  if cmp -s "$doc" "$doc.before"; then echo "selftest: $(basename "$tree"): \"$1\" changed nothing"; status=1; fi
  rm "$doc.before"
}

expect_pass() {
  local output
  if output="$("$check" "$work/$1" "$graph" 2>&1)"; then
    echo "selftest: $1: passes as it should"
  else
    echo "selftest: $1: check_docs_facts.sh fails:"; echo "$output"; status=1
  fi
}
expect_failure() {
  local output
  if output="$("$check" "$work/$1" "$graph" 2>&1)"; then
    echo "selftest: $1: check_docs_facts.sh passed a page with the defect"; status=1
  elif ! grep -qF -- "$2" <<<"$output"; then
    echo "selftest: $1: check_docs_facts.sh failed without saying \"$2\":"; echo "$output"; status=1
  else
    echo "selftest: $1: fails as it should ($2)"
  fi
}

make_tree unchanged; expect_pass unchanged

# True claims of each form, one wrapped over two lines.
small=runtime/core/Diagnostic.h n=$(wc -l < "$src/runtime/core/Diagnostic.h")
make_tree true_claims
printf '%s\n' "\`$small\` is $n lines, and \`$small\` is under" "$((n + 1)) lines; \`$small\` is limited to $("$src/tests/arch/check_sizes.sh" --limit-of "$small") lines." >> "$doc"
expect_pass true_claims

make_tree missing_index_path
change 's#^| `iMouse` | #&`runtime/input/NoSuchMouse.h`, #'
expect_failure missing_index_path "names runtime/input/NoSuchMouse.h, which does not exist"

make_tree missing_prose_path
change 's#^- `runtime/session/Recording.h`:#- `runtime/session/Recorder.h`:#'
expect_failure missing_prose_path "names runtime/session/Recorder.h, which does not exist"

make_tree extra_dep
change 's#^\(| `graph/` |.*| core, manifest\) |$#\1, shader |#'
expect_failure extra_dep "the module table's row for graph uses [core manifest shader], its DEPS are [core manifest]"

make_tree missing_dep
change 's#^\(| `session/` |.*| capture, core, \)export, #\1#'
expect_failure missing_dep "the module table's row for session uses [capture core gl"

make_tree prose_uses
change 's#^\(| `drivers/headless/` |.*| \)[^|]*|$#\1session and the modules above |#'
expect_failure prose_uses "the module table's row for drivers/headless uses \"session and the modules above\", which is not a module"

make_tree row_gone
change '/^| `farm\/` |/d'
expect_failure row_gone "the module table has no row for farm"

make_tree undeclared_row
change 's#^| `farm/` |#| `plugins/` | plugins loaded at run time | core |\n&#'
expect_failure undeclared_row "the module table has a row for plugins, which runtime/CMakeLists.txt does not declare"

make_tree no_layer
change 's#^\(| pure data.*\), `farm` |#\1 |#'
expect_failure no_layer "the layers table names farm in no layer"

make_tree false_under
printf '%s\n' "Its oldest file: \`runtime/api/Session.cpp\` is under" "300 lines." >> "$doc"
expect_failure false_under "\"\`runtime/api/Session.cpp\` is under 300 lines\", but it has"

make_tree false_exact
echo "\`$small\` is $((n + 1)) lines." >> "$doc"
expect_failure false_exact "\"\`$small\` is $((n + 1)) lines\", but it has $n lines"

make_tree false_limit
change 's#`runtime/session/SessionCore.cpp`$#`runtime/session/SessionCore.cpp` is limited to 9999 lines, and#'
expect_failure false_limit "\"\`runtime/session/SessionCore.cpp\` is limited to 9999 lines\", but arch.file_sizes limits it to"

make_tree unchecked_limit
echo "\`README.md\` is limited to 600 lines." >> "$doc"
expect_failure unchecked_limit "\"\`README.md\` is limited to 600 lines\", but arch.file_sizes limits runtime source files only"

make_tree unchecked_claim
echo "The loop is about 300 lines." >> "$doc"
expect_failure unchecked_claim "\"loop is about 300 lines\" is a size claim in no checked form"

exit $status
