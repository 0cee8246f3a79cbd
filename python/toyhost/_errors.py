"""toyhost's errors as Python exceptions: one class per kind of problem, each carrying every
diagnostic toyhost reported and the place of the first one as attributes."""


class Error(Exception):
    """A toyhost problem. ``diagnostics`` holds every problem reported (toyhost reports all it finds
    at once); ``code``, ``message``, ``file``, ``pass_``, ``channel``, ``field``, ``line`` and
    ``column`` are those of the first (``""``/``0``/``None`` when it has none); ``str(error)`` is
    toyhost's own formatted text, source excerpts included."""

    # code and category of an error raised by the Python layer itself (no diagnostics)
    _default_code, _default_category = "internal", "internal"

    def __init__(self, text, diagnostics=()):
        super().__init__(text)
        self.diagnostics = list(diagnostics)
        first = self.diagnostics[0] if self.diagnostics else None
        self.code = first.code if first else self._default_code
        self.category = first.category if first else self._default_category
        self.message = first.message if first else text
        self.file = first.file if first else ""
        self.pass_ = first.pass_ if first else ""
        self.channel = first.channel if first else None
        self.field = first.field if first else ""
        self.line = first.line if first else 0
        self.column = first.column if first else 0

    def __reduce__(self):
        # The diagnostics are native objects: a pickled error (one a Dask worker raises) keeps its
        # text and the first diagnostic's attributes, with an empty `diagnostics`.
        return _restore, (type(self), str(self), {k: v for k, v in vars(self).items() if k != "diagnostics"})


class UsageError(Error, ValueError):
    """An argument toyhost refuses (a size, a date, a pass to read that does not exist)."""

    _default_code, _default_category = "usage", "usage"


class InputError(Error):
    """The user's files: images, media, scripts, files that cannot be read."""


class ManifestError(InputError):
    """A manifest or Shadertoy export that is not valid (manifest.*, export.*, json.* codes)."""


class CompileError(Error):
    """A pass that does not compile or link; ``pass_`` and ``line`` say where (the line within
    the pass's own file)."""


class OutputError(Error):
    """Writing results failed."""


class GlError(Error):
    """The GL driver or EGL failed (no context, a missing feature, a failed readback)."""


class StoppedError(Error):
    """A stop was asked for while toyhost worked."""


class WatchdogError(Error):
    """A frame or a compilation took longer than the session's limit."""


class InternalError(Error):
    """A bug in toyhost."""


def _restore(kind, text, attributes):
    error = kind(text)
    vars(error).update(attributes)
    return error


_BY_CATEGORY = {
    "usage": UsageError,
    "input": InputError,
    "shader": CompileError,
    "output": OutputError,
    "gl": GlError,
    "interrupted": StoppedError,
    "watchdog": WatchdogError,
    "internal": InternalError,
}

_MANIFEST_PREFIXES = ("manifest.", "export.", "json.")


def from_diagnostics(category, text, diagnostics):
    """The exception for a toyhost Error (called by the native module)."""
    kind = _BY_CATEGORY.get(category, Error)
    if kind is InputError and diagnostics and diagnostics[0].code.startswith(_MANIFEST_PREFIXES):
        kind = ManifestError
    return kind(text.rstrip("\n"), diagnostics)


# Tracebacks and reprs name the classes as the package exports them (toyhost.UsageError, not
# toyhost._errors.UsageError); pickling (Dask workers) finds them there too.
for _class in [c for c in list(globals().values()) if isinstance(c, type) and issubclass(c, Error)]:
    _class.__module__ = "toyhost"
del _class
