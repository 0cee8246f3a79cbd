"""Session's keyword arguments as the settings' one list (C++ toyhost/Settings.h, read through the
native module's setting_fields()) says them: each keyword, the native members it sets and how its
value is checked. Session's signature is written from the same list (_signature.py)."""

from typing import Any, Callable, Dict, List, Mapping, Optional, Tuple

from . import _args as args
from . import _toyhost

# Each kind of C++ field: how a value is checked and converted, its annotation in Session's
# signature and its default there when the list's initial value is "{}" (a "?" kind takes None for
# "not given"; "flag" and "real" show the list's initial value).
KINDS: Dict[str, Tuple[Callable[[str, Any], Any], str, Optional[str]]] = {
    "flag": (args.flag, "bool", None),
    "real": (args.real, "float", None),
    "int?": (lambda name, value: args.optional(args.integer, name, value), "Optional[int]", "None"),
    "real?": (lambda name, value: args.optional(args.real, name, value), "Optional[float]", "None"),
    "text?": (lambda name, value: args.optional(args.text, name, value), "Optional[str]", "None"),
    "path?": (lambda name, value: args.optional(args.path, name, value), "Optional[PathLike]", "None"),
    "paths": (args.paths, "Union[PathLike, Sequence[PathLike]]", "()"),
    "named_paths": (lambda name, value: args.named_paths(name, value if value is not None else {}),
                    "Optional[Mapping[str, PathLike]]", "None"),
    "macros": (args.defines, "Defines", "()"),
}


def _keywords() -> Dict[str, List[Tuple[str, str]]]:
    """key -> [(member, kind)], in the list's order; two members under one key are a pair given
    together (size=(width, height))."""
    keys: Dict[str, List[Tuple[str, str]]] = {}
    for member, key, kind, _fallback, _initial in _toyhost.setting_fields():
        keys.setdefault(key, []).append((member, kind))
    return keys


KEYWORDS = _keywords()


def native(given: Mapping[str, Any], owner: str = "Session") -> Dict[str, Any]:
    """The native layer's settings (by C++ member) from a Session's keywords, each checked:
    UsageError naming the keyword for a value that cannot be meant, TypeError for a keyword that
    is not a setting (as Python's own for an unknown keyword)."""
    out: Dict[str, Any] = {}
    for key, value in given.items():
        members = KEYWORDS.get(key)
        if members is None:
            raise TypeError(f"{owner}() got an unexpected keyword argument '{key}'")
        if len(members) == 2:
            if value is not None:
                for (member, _kind), item in zip(members, args.size(key, value)):
                    out[member] = item
            continue
        member, kind = members[0]
        converted = KINDS[kind][0](key, value)
        if converted is not None:
            out[member] = converted
    return out


