#!/usr/bin/env python3
# Writes toyhost.1 (man, roff) from the built CLI's help (`toyhost --help` and every subcommand's,
# options as CLI11 prints them) and from README.md (the introduction, and the toyhost commands of its
# "Five common uses").
# Run by the build (packaging/CMakeLists.txt). Usage: make-manpage.py TOYHOST README VERSION OUT
import re
import sys

from cli_help import read_all


def roff(text):
    text = text.replace("\\", "\\e")
    text = re.sub(r"(?m)^([.'])", r"\\&\1", text)
    return text.replace("-", "\\-")


def markdown(text):
    text = re.sub(r"\[([^\]]+)\]\([^)]+\)", r"\1", text)       # links: their text
    text = roff(text)
    text = re.sub(r"`([^`]+)`", r"\\fB\1\\fR", text)           # code: bold
    return re.sub(r"\*\*([^*]+)\*\*", r"\\fB\1\\fR", text)


def readme_sections(readme):
    # {"": introduction, "The two commands": ..., ...} keyed by "## " headings.
    sections, name, lines = {}, "", []
    for line in readme.split("\n"):
        if line.startswith("## "):
            sections[name] = "\n".join(lines).strip()
            name, lines = line[3:].strip(), []
        elif not line.startswith("# "):
            lines.append(line)
    sections[name] = "\n".join(lines).strip()
    return sections


def paragraphs(markdown_text):
    # Prose paragraphs (no code blocks, headings or HTML such as the README's picture) as roff,
    # separated by .PP
    out, in_code = [], False
    for block in re.split(r"\n\s*\n", markdown_text):
        if block.lstrip().startswith("```") or in_code:
            in_code = block.count("```") % 2 == 1 if not in_code else block.count("```") % 2 == 0
            continue
        if block.lstrip().startswith(("#", "<")):
            continue
        out.append(markdown(" ".join(block.split())))
    return "\n.PP\n".join(out)


def shell_blocks(markdown_text):
    return re.findall(r"```sh\n(.*?)```", markdown_text, flags=re.S)


def options(title, entries):
    if not entries:
        return ""
    out = []
    for o in entries:
        label = ", ".join(o.names) + (f" {o.value}" if o.value else "")
        out.append(f".TP\n.B {roff(label)}\n{roff(o.text)}")
    return (f".PP\n{title}:\n" if title else "") + "\n".join(out)


def main():
    toyhost, readme_path, version, out_path = sys.argv[1:5]
    top, subcommands = read_all(toyhost)
    sections = readme_sections(open(readme_path, encoding="utf-8").read())
    page = [
        f'.TH TOYHOST 1 "" "toyhost {version}" "User Commands"',
        ".SH NAME", f"toyhost \\- {roff(top.summary)}",
        ".SH SYNOPSIS",
        "\n.br\n".join(f".B toyhost {roff(c.usage.split(' ', 1)[1])}" for c in [top, *subcommands]),
        ".SH DESCRIPTION", paragraphs(sections.get("", "")),
        ".SH OPTIONS", options("", top.options),
        ".SH COMMANDS",
    ]
    for c in subcommands:
        page.append(f".SS toyhost {roff(c.name)}")
        page.append(roff(c.summary) + ".")
        page.append(f".PP\nUsage: \\fBtoyhost {roff(c.usage.split(' ', 1)[1])}\\fR")
        page.append(options("Arguments", c.positionals))
        page.append(options("Options", c.options))
    # The shell examples of the README's uses that run toyhost itself (not the repository's scripts).
    examples = [b.rstrip("\n") for b in shell_blocks(sections.get("Five common uses", "")) if "tools/toyhost" in b]
    if examples:
        text = re.sub(r"\S*build\S*/tools/toyhost", "toyhost", "\n".join(examples))
        page += [".SH EXAMPLES", "In toyhost's source tree (its \\fBshadertoys/\\fR folder):", ".PP", ".nf", roff(text), ".fi"]
    if top.footer:
        page += [".SH EXIT STATUS", roff(top.footer)]
    page += [".SH SEE ALSO",
             "The README and the reference pages it links (/usr/share/doc/toyhost/README.md and "
             "/usr/share/doc/toyhost/docs/ where installed): docs/manifest.md for the manifest format, "
             "docs/running.md for messages and exit codes, docs/window.md for window mode, "
             "docs/capture.md for capture, docs/library.md for the library API "
             "(\\fBfind_package(toyhost)\\fR, \\fBpkg\\-config toyhost\\fR), docs/python.md for Python."]
    with open(out_path, "w", encoding="utf-8") as f:
        f.write("\n".join(p for p in page if p) + "\n")


if __name__ == "__main__":
    main()
