"""Session's signature, written from the settings' one list (C++ toyhost/Settings.h, read through
the native module's setting_fields()): Session.__init__'s keywords in python/toyhost/__init__.py
(for type checkers and help()) and its line in docs/python.md.

    PYTHONPATH=BUILD/python python3 -m toyhost._signature --write SOURCE_DIR

writes both after a row is added to the list; python/tests/test_defaults.py fails when either
differs from what the list writes (--check says which)."""

import re
import sys
from typing import Dict, List, Optional, Tuple

from . import _settings, _toyhost


_PAIR = ("Optional[Tuple[int, int]]", "None")  # two members under one key: size=(width, height)


def _parameters() -> List[Tuple[str, str, str]]:
    """(keyword, annotation, default) in the list's order, each keyword once."""
    rows: Dict[str, List[Tuple[str, str]]] = {}
    for _member, key, kind, _fallback, initial in _toyhost.setting_fields():
        rows.setdefault(key, []).append((kind, initial))
    out = []
    for key, members in rows.items():
        if len(members) == 2:
            annotation, default = _PAIR
        else:
            kind, initial = members[0]
            _convert, annotation, default_text = _settings.KINDS[kind]
            if kind == "flag":
                default = {"false": "False", "true": "True"}[initial]
            elif kind == "real":
                default = repr(float(initial))
            else:
                if initial != "{}":
                    raise ValueError(f"setting {key}: a {kind} starts not given ({{}}), not {initial}")
                default = str(default_text)
        out.append((key, annotation, default))
    return out


def _wrap(parts: List[str], first: str, indent: str, last: str, width: int) -> str:
    """first + parts + last in lines of at most width characters, never breaking a part."""
    lines = [first.rstrip(" ")]
    parts = parts[:-1] + [parts[-1] + last]
    for part in parts:
        if len(lines[-1]) + 1 + len(part) <= width:
            lines[-1] += " " + part
        else:
            lines.append(indent + part)
    return "\n".join(lines) + "\n"


def signature_source() -> str:
    """Session.__init__'s first lines, as python/toyhost/__init__.py has them."""
    parts = [f"{key}: {annotation} = {default}," for key, annotation, default in _parameters()]
    parts[-1] = parts[-1].rstrip(",")
    return _wrap(parts, "    def __init__(self, shadertoy: Union[Shadertoy, PathLike, dict, list], *,",
                 " " * 17, ") -> None:", 110)


def signature_docs() -> str:
    """Session's line in docs/python.md."""
    parts = [f"{key}={default}," for key, _annotation, default in _parameters()]
    parts[-1] = parts[-1].rstrip(",")
    return _wrap(parts, "- **`toyhost.Session(shadertoy, *,", "  ", ")`**:", 100)


# Where each text stands in its file: from the first line to the end of the signature.
_PLACES = {
    "python/toyhost/__init__.py": (re.compile(r"    def __init__\(self, shadertoy: .*?\) -> None:\n", re.S),
                                   signature_source),
    "docs/python.md": (re.compile(r"- \*\*`toyhost\.Session\(shadertoy, .*?\)`\*\*:\n", re.S), signature_docs),
}


def stale(source_dir: str) -> List[str]:
    """The files under source_dir whose Session signature is not what the list writes."""
    out = []
    for name, (pattern, make) in _PLACES.items():
        with open(f"{source_dir}/{name}", encoding="utf-8") as f:
            found = pattern.findall(f.read())
        if found != [make()]:
            out.append(name)
    return out


def _write(source_dir: str) -> None:
    for name, (pattern, make) in _PLACES.items():
        path = f"{source_dir}/{name}"
        with open(path, encoding="utf-8") as f:
            text = f.read()
        new, count = pattern.subn(lambda _match: make(), text)
        if count != 1:
            raise SystemExit(f"{path}: {count} Session signatures found, expected 1")
        with open(path, "w", encoding="utf-8") as f:
            f.write(new)


def main(argv: Optional[List[str]] = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2 or argv[0] not in ("--write", "--check"):
        print("usage: python3 -m toyhost._signature --write|--check SOURCE_DIR", file=sys.stderr)
        return 2
    if argv[0] == "--write":
        _write(argv[1])
        return 0
    for name in stale(argv[1]):
        print(f"{name}: Session's signature differs from the settings' list", file=sys.stderr)
    return 1 if stale(argv[1]) else 0


if __name__ == "__main__":
    sys.exit(main())
