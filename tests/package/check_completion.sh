#!/usr/bin/env bash
# The bash completion completes every subcommand `toyhost --help` lists (and theirs: farm plan,
# status, join) and every option each command's --help lists (read here from the help text itself, not from the generator), completes
# paths after an option taking TEXT, and nothing after one taking a number.
# Usage: check_completion.sh COMPLETION_FILE TOYHOST
set -uo pipefail
completion="$1" toyhost="$2"
# shellcheck disable=SC1090
source "$completion"
status=0

complete_line() {  # complete_line WORD...: the candidates for the last word
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _toyhost
  printf '%s\n' "${COMPREPLY[@]}"
}
# Reads all of its input: `grep -q` stops at the first match, and the writer then dies of SIGPIPE,
# which pipefail turned into a failed check whenever more candidates followed the match.
has() { grep -xF -- "$1" >/dev/null; }

subcommands_of() { "$toyhost" "$@" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF {print $1}'; }
# Every command path, the nested ones too ("farm", "farm plan", ...), each checked in its place.
paths=("")
for command in $(subcommands_of); do
  complete_line toyhost "${command:0:2}" | has "$command" || { echo "completion: toyhost ${command:0:2}<TAB> does not offer $command"; status=1; }
  paths+=("$command")
  for sub in $(subcommands_of "$command"); do
    complete_line toyhost "$command" "${sub:0:2}" | has "$sub" \
      || { echo "completion: toyhost $command ${sub:0:2}<TAB> does not offer $sub"; status=1; }
    complete_line toyhost "$command" "" | has "$sub" || { echo "completion: toyhost $command <TAB> does not offer $sub"; status=1; }
    paths+=("$command $sub")
  done
done
((${#paths[@]} > 10)) || { echo "completion: only ${#paths[@]} commands found in the help"; status=1; }
for command in "${paths[@]}"; do
  # shellcheck disable=SC2086
  help="$("$toyhost" $command --help)"
  for option in $(grep -oE '^  -[-a-zA-Z0-9,]+' <<<"$help" | tr ',' ' '); do
    words=(toyhost)
    # shellcheck disable=SC2206
    [[ -n "$command" ]] && words+=($command)
    complete_line "${words[@]}" "${option:0:3}" | has "$option" \
      || { echo "completion: toyhost $command ${option:0:3}<TAB> does not offer $option"; status=1; }
  done
done

# Values: paths after a TEXT option, nothing after a number.
tmp="$(mktemp -d)"
touch "$tmp/frames.json"
complete_line toyhost run --mouse-script "$tmp/fr" | has "$tmp/frames.json" || { echo "completion: no path after run --mouse-script"; status=1; }
[[ -z "$(complete_line toyhost run --frames "")" ]] || { echo "completion: offers words after run --frames (a number)"; status=1; }
complete_line toyhost farm plan --job "$tmp/fr" | has "$tmp/frames.json" || { echo "completion: no path after farm plan --job"; status=1; }
rm -rf "$tmp"
exit $status
