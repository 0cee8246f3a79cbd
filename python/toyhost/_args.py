"""The Python module's argument checks: every value a caller passes goes through one of these
before it reaches the native layer, and a value that cannot be meant (a string for a number, NaN,
320.7 pixels, a number past what C++ holds, a folder given as a string where a list is expected)
raises UsageError naming the parameter, instead of pybind11's "incompatible function arguments"
or a silent conversion. Ranges that the CLI checks too (a size of 0, a negative fps) are checked
once, natively, with the CLI's words."""

import math
import numbers
import os

from . import _toyhost
from ._errors import UsageError

INT_MIN, INT_MAX = -2**31, 2**31 - 1
# The largest texture side a channel takes (C++ toyhost/Defaults.h, through the native module).
MAX_CANVAS_SIDE = _toyhost.defaults()["max_canvas_side"]


def usage(name, message):
    """A UsageError naming the parameter, in the form of the native layer's ("error: size: ...
    [usage]"), with ``field`` and ``message`` set as theirs are."""
    error = UsageError(f"error: {name}: {message} [usage]")
    error.field = name
    error.message = message
    return error


def integer(name, value, minimum=INT_MIN, maximum=INT_MAX):
    """A whole number (an int, or a float with no fraction) within [minimum, maximum]."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise usage(name, f"expected a whole number, got {value!r}")
    if not isinstance(value, numbers.Integral):
        if not math.isfinite(value) or not float(value).is_integer():
            raise usage(name, f"expected a whole number, got {value!r}")
    value = int(value)
    if not minimum <= value <= maximum:
        if (minimum, maximum) == (INT_MIN, INT_MAX):
            raise usage(name, f"{value} is beyond what a 32-bit integer holds")
        raise usage(name, f"{value} is out of range ({minimum}..{maximum})")
    return value


def real(name, value, finite=True):
    """A number (not a string, not a bool); NaN and infinities refused unless finite is False,
    for parameters whose native check says what they mean."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise usage(name, f"expected a number, got {value!r}")
    value = float(value)
    if finite and not math.isfinite(value):
        raise usage(name, f"expected a finite number, got {value}")
    return value


def flag(name, value):
    if isinstance(value, (bool, numbers.Integral)) and value in (0, 1):
        return bool(value)
    if hasattr(value, "dtype") and getattr(value, "shape", None) == () and value in (0, 1):  # numpy.bool_
        return bool(value)
    raise usage(name, f"expected True or False, got {value!r}")


def pair(name, value, convert, what):
    """Two values as `convert` takes them: (x, y), (width, height)."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise usage(name, f"expected {what}, got {value!r}")
    items = tuple(value)
    if len(items) != 2:
        raise usage(name, f"expected {what}, got {value!r}")
    return convert(name, items[0]), convert(name, items[1])


def size(name, value):
    return pair(name, value, integer, "(width, height)")


def point(name, value):
    return pair(name, value, real, "(x, y)")


def text(name, value):
    if not isinstance(value, str):
        raise usage(name, f"expected a string, got {value!r}")
    return value


def path(name, value):
    try:
        value = os.fspath(value)
    except TypeError:
        raise usage(name, f"expected a path, got {value!r}") from None
    # No file name holds one; the native layer's conversion would raise a bare ValueError.
    if ("\0" if isinstance(value, str) else b"\0") in value:
        raise usage(name, f"a path cannot hold a NUL byte, got {value!r}")
    return value


def paths(name, value):
    """One path or a list of them (a lone string is one folder, not its characters)."""
    if isinstance(value, (str, bytes, os.PathLike)):
        return [path(name, value)]
    try:
        items = list(value)
    except TypeError:
        raise usage(name, f"expected a path or a list of paths, got {value!r}") from None
    return [path(name, item) for item in items]


def defines(name, value):
    """--define macros: "NAME" / "NAME=VALUE" strings (one or a list), or {NAME: value} where True
    or None is the name alone; checked by the native side (names, one value per name)."""
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        out = []
        for key, item in value.items():
            if not isinstance(key, str):
                raise usage(name, f"expected macro names as keys, got {key!r}")
            if item is None or item is True:
                out.append(key)
            elif isinstance(item, bool):
                raise usage(name, f"{key}: False does not define a macro; leave the name out")
            elif isinstance(item, (str, int, float)):
                out.append(f"{key}={item}")
            else:
                raise usage(name, f"{key}: expected a string or a number as its value, got {item!r}")
        return out
    try:
        items = list(value)
    except TypeError:
        raise usage(name, f"expected \"NAME[=VALUE]\" strings or a dict, got {value!r}") from None
    return [text(name, item) for item in items]


def named_paths(name, value):
    """{stock name or id: path}."""
    if not hasattr(value, "items"):
        raise usage(name, f"expected a dict of name: path, got {value!r}")
    return [(text(name, key), path(name, item)) for key, item in value.items()]


def channel(name, value):
    """A channel as 0..3 or "iChannel0".."iChannel3" (ASCII digits: "iChannel²" is no channel)."""
    if isinstance(value, str):
        digits = value.removeprefix("iChannel")
        if not (digits.isascii() and digits.isdigit()):
            raise usage(name, f"expected 0..3 or \"iChannel0\" .. \"iChannel3\", got {value!r}")
        value = int(digits)
    return integer(name, value, minimum=0, maximum=3)


def channel_array(name, value):
    """A set_channel() array (numpy takes `value` as one): uint8 or float32 of shape (height, width)
    or (height, width, 1|3|4), at most MAX_CANVAS_SIDE a side; C-contiguous (copied only when it is
    not, and only once its shape passed: a 20000x20000 view of one pixel is refused, not first
    copied into 1.5 GiB)."""
    import numpy

    pixels = numpy.asarray(value)
    if pixels.dtype not in (numpy.uint8, numpy.float32):
        raise usage(name, f"dtype {pixels.dtype} is not taken: uint8 (0..255) or float32 "
                          "(convert with .astype(numpy.float32))")
    if pixels.ndim == 3 and pixels.shape[2] not in (1, 3, 4) or pixels.ndim not in (2, 3):
        raise usage(name, f"shape {pixels.shape}: expected (height, width) or (height, width, 1|3|4)")
    if pixels.shape[0] == 0 or pixels.shape[1] == 0:
        raise usage(name, f"shape {pixels.shape} has no pixels")
    if pixels.shape[0] > MAX_CANVAS_SIDE or pixels.shape[1] > MAX_CANVAS_SIDE:
        raise usage(name, f"shape {pixels.shape}: at most {MAX_CANVAS_SIDE} pixels a side")
    return numpy.ascontiguousarray(pixels)


def optional(convert, name, value, *args, **kwargs):
    return None if value is None else convert(name, value, *args, **kwargs)
