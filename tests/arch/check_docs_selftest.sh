#!/usr/bin/env bash
# Shows that check_docs.sh fails on each defect it exists for: a copy of the tree's README.md and
# docs/ (the rest linked in) passes as it is, and fails, naming the defect, with a README of 300
# lines, a set-up command changed, an index row gone, and a broken link (a path of the index that
# does not exist: check_docs_facts_selftest.sh). Usage: check_docs_selftest.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src="$(cd "$1" && pwd)" work="$2"
check="$src/tests/arch/check_docs.sh"
status=0

# A tree like the source, with README.md and docs/ as copies that a case may change.
make_tree() {
  local tree="$work/$1"
  rm -rf "$tree" && mkdir -p "$tree"
  ln -s "$src"/* "$tree"/
  rm "$tree/README.md" "$tree/docs"
  cp "$src/README.md" "$tree/README.md"
  cp -r "$src/docs" "$tree/docs"
  echo "$tree"
}

# expect_failure NAME MESSAGE: check_docs.sh on the tree fails and prints MESSAGE.
expect_failure() {
  local output
  if output="$("$check" "$work/$1" 2>&1)"; then
    echo "selftest: $1: check_docs.sh passed a tree with the defect"; status=1
  elif ! grep -qF -- "$2" <<<"$output"; then
    echo "selftest: $1: check_docs.sh failed without saying \"$2\":"; echo "$output"; status=1
  else
    echo "selftest: $1: fails as it should ($2)"
  fi
}

tree="$(make_tree unchanged)"
if ! "$check" "$tree" >/dev/null; then echo "selftest: the unchanged copy fails:"; "$check" "$tree" || true; status=1; fi

tree="$(make_tree long_readme)"
for ((i = $(wc -l < "$tree/README.md"); i < 300; i++)); do echo "more reference text"; done >> "$tree/README.md"
expect_failure long_readme "README.md has 300 lines"

tree="$(make_tree changed_command)"
sed -i 's|^\./scripts/test\.sh       #|./scripts/test.sh #|' "$tree/README.md"
expect_failure changed_command "README.md lost the set-up command line: ./scripts/test.sh"

tree="$(make_tree missing_row)"
sed -i '/^| the watchdog |/d' "$tree/docs/architecture.md"
expect_failure missing_row "no row for \"the watchdog\""

tree="$(make_tree broken_link)"
echo "See [the old reference](old-reference.md)." >> "$tree/docs/running.md"
expect_failure broken_link "docs/running.md links to old-reference.md, which does not exist"

exit $status
