"""Keys as a shadertoy sees them: the JavaScript keyCode that indexes the keyboard texture
(docs/window.md, "Keyboard"; docs/input.md for the texture). Accepts a keyCode, a single character, or a name."""

import numbers

from ._args import usage

_NAMED = {
    "backspace": 8, "tab": 9, "enter": 13, "return": 13, "shift": 16, "ctrl": 17, "control": 17,
    "alt": 18, "pause": 19, "escape": 27, "esc": 27, "space": 32, "pageup": 33, "pagedown": 34,
    "end": 35, "home": 36, "left": 37, "up": 38, "right": 39, "down": 40, "insert": 45, "delete": 46,
}
_NAMED.update({f"f{n}": 111 + n for n in range(1, 13)})
_NAMED.update({f"kp{n}": 96 + n for n in range(10)})

# Chrome's codes for punctuation.
_PUNCTUATION = {";": 186, "=": 187, ",": 188, "-": 189, ".": 190, "/": 191, "`": 192, "[": 219,
                "\\": 220, "]": 221, "'": 222, " ": 32}


def key_code(key: "int | str") -> int:
    """The keyCode for ``key``: an int (taken as it is), one character ('a' and 'A' are 65) or a
    name ('Space', 'Left', 'F5', 'KP0'...)."""
    if isinstance(key, bool):
        raise usage("key", f"expected a keyCode, a character or a name, got {key!r}")
    if isinstance(key, numbers.Integral):
        key = int(key)
        if not 0 <= key <= 255:
            raise usage("key", f"keyCode {key} is outside 0..255 (the keyboard texture's width)")
        return key
    if isinstance(key, str):
        if len(key) == 1:
            if key.isascii() and key.isalnum():
                return ord(key.upper())
            if key in _PUNCTUATION:
                return _PUNCTUATION[key]
        elif key.lower() in _NAMED:
            return _NAMED[key.lower()]
        raise usage("key", f"unknown key {key!r} (a keyCode, a letter or digit, punctuation, or a name "
                         f"such as {', '.join(sorted(_NAMED)[:6])}...)")
    raise usage("key", f"expected a keyCode, a character or a name, got {key!r}")
