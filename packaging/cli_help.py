# The toyhost CLI's help text as data (for the man page and bash completion generators): the
# subcommands `toyhost --help` lists, and for each command its usage, positionals and options as
# CLI11 prints them. Runs the built binary; no GL needed (--help renders nothing).
import re
import subprocess
from dataclasses import dataclass, field


@dataclass
class Option:
    names: list          # ["-h", "--help"]
    value: str           # "TEXT", "INT", "FLOAT=180", "TEXT ..." or "" for a flag
    text: str


@dataclass
class Command:
    name: str            # "" for the top level
    summary: str
    usage: str
    positionals: list = field(default_factory=list)  # Option with names [name]
    options: list = field(default_factory=list)
    subcommands: list = field(default_factory=list)  # (name, summary)
    footer: str = ""


def _entry(line):
    # "  --size TEXT                 Canvas size" -> ("--size TEXT", "Canvas size")
    parts = re.split(r"\s{2,}", line.strip(), maxsplit=1)
    return parts[0], (parts[1] if len(parts) > 1 else "")


def parse(text, name=""):
    lines = text.rstrip("\n").split("\n")
    first = lines[0]
    summary = first.split(": ", 1)[1] if first.startswith("toyhost: ") else first
    command = Command(name=name, summary=summary, usage="")
    section = None
    for line in lines[1:]:
        if line.startswith("Usage: "):
            command.usage = line[len("Usage: "):]
        elif line in ("Positionals:", "Options:", "Subcommands:"):
            section = line
        elif not line.strip():
            section = None
        elif line.startswith("  ") and section:
            head, text_ = _entry(line)
            if section == "Subcommands:":
                command.subcommands.append((head, text_))
                continue
            words = head.split(" ", 1)
            value = words[1] if len(words) > 1 else ""
            if section == "Positionals:":
                command.positionals.append(Option([words[0]], value, text_))
            else:
                command.options.append(Option(words[0].split(","), value, text_))
        elif section is None:
            command.footer = (command.footer + "\n" + line).strip()
    return command


def read_all(toyhost):
    """The top level, and every command below it in the order `--help` lists them, a command's
    own subcommands right after it, named by their path ("farm", "farm plan", ...)."""
    def help_of(args):
        return subprocess.run([toyhost, *args, "--help"], check=True, capture_output=True, text=True).stdout

    commands = []

    def visit(path):
        command = parse(help_of(path), " ".join(path))
        commands.append(command)
        for sub, _ in command.subcommands:
            visit(path + [sub])

    top = parse(help_of([]))
    for sub, _ in top.subcommands:
        visit([sub])
    return top, commands
