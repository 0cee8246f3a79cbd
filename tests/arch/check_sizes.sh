#!/usr/bin/env bash
# Keeps the runtime's files small enough to read (one concern per file): every runtime source file
# (runtime/**/*.cpp, *.h) stays within its line limit, below, unless the allow-list
# (tests/arch/size-allowlist.txt) gives it a higher one and says why. An allow-list line that is no
# longer needed (the file is back within its limit, or gone) fails too, so the list cannot rot.
# Prints every violation.
# Usage: check_sizes.sh SOURCE_DIR [ALLOWLIST]  check the tree (ALLOWLIST: the tree's by default)
#        check_sizes.sh --limit-of PATH         print the limit of PATH (from the source directory),
#                                               the allow-list aside (docs/architecture.md's "is
#                                               limited to N lines" claims are checked against it)
set -euo pipefail

# The limits, written here only. A file passes its limit when it has more lines than this.
default_limit=600
# SessionCore is the loop only (docs/architecture.md, "The session layer"): what is not the loop
# lives beside it or in a driver.
declare -A file_limits=([runtime/session/SessionCore.cpp]=350)

# The limit of a file, into $limit (no subshell: it runs for every file of the tree).
limit_of() { limit="${file_limits[$1]:-$default_limit}"; }

if [[ "${1:-}" == --limit-of ]]; then
  limit_of "$2"
  echo "$limit"
  exit 0
fi

src="$1" allowlist="${2:-$1/tests/arch/size-allowlist.txt}"
status=0
fail() { echo "sizes: $*"; status=1; }

declare -A lines
while read -r n file; do
  [[ "$file" == total ]] && continue  # wc's sum (the files themselves are $src/runtime/...)
  lines[${file#"$src"/}]=$n
done < <(find "$src/runtime" -type f \( -name '*.cpp' -o -name '*.h' \) -exec wc -l {} +)
(( ${#lines[@]} > 0 )) || fail "no runtime source file under $src/runtime"

# A file's own limit belongs to a file that exists.
for file in "${!file_limits[@]}"; do
  [[ -n "${lines[$file]+x}" ]] || fail "check_sizes.sh sets a limit for $file, which is not a runtime source file"
done

# The allow-list: "PATH LIMIT REASON" lines; a line starting with '#' is a comment.
declare -A allowed
if [[ ! -f "$allowlist" ]]; then
  fail "the allow-list $allowlist is missing"
else
  number=0
  while IFS= read -r line || [[ -n "$line" ]]; do
    number=$((number + 1))
    [[ "$line" =~ ^[[:space:]]*(#|$) ]] && continue
    where="${allowlist##*/}:$number"
    read -r path most reason <<<"$line"
    reason="${reason:-}"
    if [[ ! "${most:-}" =~ ^[0-9]+$ ]]; then
      fail "$where: \"$line\" is not PATH LIMIT REASON (the limit a number of lines)"; continue
    fi
    [[ -n "$reason" ]] || fail "$where: $path has no reason: say why it may be longer"
    if [[ -n "${allowed[$path]+x}" ]]; then fail "$where: $path is listed twice"; continue; fi
    allowed[$path]=$most
    limit_of "$path"
    if [[ -z "${lines[$path]+x}" ]]; then
      fail "$where: $path is not a runtime source file (any more): remove its line"
    elif (( most <= limit )); then
      fail "$where: $path is allowed $most lines, no more than its limit of $limit: remove its line"
    elif (( ${lines[$path]} <= limit )); then
      fail "$where: $path has ${lines[$path]} lines, within its limit of $limit: remove its line"
    fi
  done < "$allowlist"
fi

over=0
for file in $(printf '%s\n' "${!lines[@]}" | sort); do
  n=${lines[$file]}
  limit_of "$file"
  (( n > limit )) || continue
  over=$((over + 1))
  if [[ -z "${allowed[$file]+x}" ]]; then
    fail "$file has $n lines, over its limit of $limit: split it (one concern per file), or give it an allow-list line saying why"
  elif (( n > ${allowed[$file]} )); then
    fail "$file has $n lines, more than the ${allowed[$file]} its allow-list line allows"
  else
    echo "sizes: $file has $n lines, over its limit of $limit, allowed ${allowed[$file]} by the allow-list"
  fi
done

if (( status == 0 )); then
  echo "sizes: ${#lines[@]} runtime source files within their limits, $over of them by an allow-list line"
fi
exit $status
