#!/usr/bin/env bash
# Regenerates docs/cli.md from the help text of a built toyhost (explicit refresh, never run by the
# tests; tests/gl/test_cli_reference.cpp fails while the two differ).
# Usage: scripts/update-cli-doc.sh [path/to/toyhost]   (default build-dev/tools/toyhost)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
toyhost="${1:-$root/build-dev/tools/toyhost}"
out="$root/docs/cli.md"
{
    echo "# toyhost command-line reference"
    echo
    echo "This page is the output of \`toyhost --help\` and of each command's \`--help\`, regenerated"
    echo "by \`scripts/update-cli-doc.sh\`; a test fails while they differ. What the messages and exit"
    echo "codes mean is in [running.md](running.md); the README shows examples."
    for command in "" run import inspect new media sound compare farm "farm plan" "farm status" "farm join"; do
        echo
        echo "## toyhost${command:+ $command}"
        echo
        echo '```text'
        # shellcheck disable=SC2086
        "$toyhost" $command --help
        echo '```'
    done
} > "$out.tmp"
mv "$out.tmp" "$out"
echo "wrote $out"
