#!/usr/bin/env python3
# Writes toyhost-compat.1 (man, roff) from the built compatibility runner's --help and
# docs/compat.md's introduction. Run by the build (packaging/CMakeLists.txt).
# Usage: make-compat-manpage.py TOYHOST_COMPAT COMPAT_MD VERSION OUT
import re
import subprocess
import sys

from cli_help import parse

# The page shares make-manpage.py's conversions.
sys.path.insert(0, __file__.rsplit("/", 1)[0])
manpage = __import__("make-manpage")


def main():
    binary, doc_path, version, out_path = sys.argv[1:5]
    text = subprocess.run([binary, "--help"], check=True, capture_output=True, text=True).stdout
    command = parse(text)
    summary = command.summary.split(": ", 1)[1] if command.summary.startswith("toyhost-compat: ") else command.summary
    doc = open(doc_path, encoding="utf-8").read()
    intro = manpage.readme_sections(doc).get("", "")
    intro = re.sub(r"\s*Back to the \[README\]\([^)]*\)\.", "", intro)  # the docs' own navigation
    usage = command.usage.split(" ", 1)[1] if " " in command.usage else ""
    page = [
        f'.TH TOYHOST-COMPAT 1 "" "toyhost {version}" "User Commands"',
        ".SH NAME", f"toyhost\\-compat \\- {manpage.roff(summary)}",
        ".SH SYNOPSIS", f".B toyhost\\-compat {manpage.roff(usage)}",
        ".SH DESCRIPTION", manpage.paragraphs(intro),
        ".SH ARGUMENTS", manpage.options("", command.positionals),
        ".SH OPTIONS", manpage.options("", command.options),
        ".SH EXIT STATUS",
        "0 the run completed and, with \\fB\\-\\-min\\-pass\\-rate\\fR, at least that share of the shaders "
        "passed; 1 fewer passed, or a table could not be written; 2 bad command\\-line usage or nothing to run.",
        ".SH SEE ALSO", "\\fBtoyhost\\fR(1); docs/compat.md (/usr/share/doc/toyhost/docs/compat.md where installed).",
    ]
    with open(out_path, "w", encoding="utf-8") as f:
        f.write("\n".join(p for p in page if p) + "\n")


if __name__ == "__main__":
    main()
