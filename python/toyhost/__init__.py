"""toyhost from Python: run Shadertoy shaders headless and get their frames as numpy arrays.

    import toyhost
    ocean = toyhost.load("shadertoys/ocean")          # folder, manifest, export file or JSON text
    with toyhost.Session(ocean, size=(320, 180), fps=30) as session:
        session.step(mouse=(100, 50))                 # one frame, the mouse held at (100, 50)
        rgba = session.frame()                        # (180, 320, 4) uint8, top row first
        for index, frame in session.render(60, every=10):
            ...

Every session renders on a GL thread of its own (toyhost's public C++ Session underneath); calls
wait for it with the GIL released, so other Python threads run meanwhile. Problems raise
toyhost.Error subclasses carrying toyhost's diagnostics (file, pass, line, code...).
"""

import os
import pathlib
from typing import Any, Iterable, Iterator, Mapping, Optional, Sequence, Set, Tuple, Union

# Imported here, with the module, rather than by the first frame: importing numpy takes 70-90 ms,
# which would otherwise land on whatever first makes an array (a frame, in a timed loop).
import numpy

from . import _args as args
from . import _code
from . import _notebook
from . import _settings
from . import _toyhost
from ._compare import CompareReport, FrameDifference, compare, compare_images
from ._errors import (CompileError, Error, GlError, InputError, InternalError, ManifestError, OutputError,
                      StoppedError, UsageError, WatchdogError)
from ._keys import key_code
from ._toyhost import Diagnostic, InputEvent, Reloaded, Shadertoy

__version__: str = _toyhost.version_string()

# What the arguments may be (for type checkers: the module ships py.typed and _toyhost.pyi).
PathLike = Union[str, "os.PathLike[str]"]
Point = Tuple[float, float]
Keys = Iterable[Union[int, str]]
Defines = Union[str, Sequence[str], Mapping[str, Any]]

__all__ = [
    "load", "from_code", "Session", "compare", "compare_images", "CompareReport", "FrameDifference", "Shadertoy", "Diagnostic", "InputEvent", "Reloaded", "key_code", "Error", "UsageError", "InputError",
    "ManifestError", "CompileError", "OutputError", "GlError", "StoppedError", "WatchdogError", "InternalError",
    "defaults", "__version__",
]


def defaults() -> dict:
    """toyhost's defaults as a new dict, made from its one list (C++ toyhost/Defaults.h): what a
    Session takes for what it is not given ("width", "height", "fps", "supersample", "motion_blur",
    "shutter"), the bounds settings are checked against ("min_fps", "max_fps", "max_canvas_side",
    "max_supersample", "max_motion_blur", "max_samples_per_frame"), and the CLI's ("frames",
    "capture_every", "png_level", "capture_memory_mib", "frame_timeout", "compile_timeout" in
    seconds, "compare_frames", "sample_rate", "sound_seconds")."""
    return _toyhost.defaults()


def load(path_or_json: Union[PathLike, dict, list], name: str = "export.json",
         folder: Optional[PathLike] = None) -> Shadertoy:
    """A Shadertoy from a folder holding manifest.json, a manifest file, a Shadertoy JSON export file
    (API or site form), a lone .glsl/.frag file (an Image-only shadertoy; the common.glsl next to
    it joins as Common), the text of an export (a str starting with '{' or '['), or an export
    already parsed (a dict or list, as json.load gives it).

    ``name`` and ``folder`` apply to JSON text: the name messages use for it, and where files it
    names relatively would be found. Raises ManifestError (or another toyhost.Error) listing every
    problem found."""
    if isinstance(path_or_json, (dict, list)):
        path_or_json = _code.dumps(path_or_json)
    if isinstance(path_or_json, str) and path_or_json.lstrip()[:1] in ("{", "["):
        return _toyhost.load_export_json(path_or_json, name, os.fspath(folder) if folder is not None else "")
    return _toyhost.load_path(args.path("path_or_json", path_or_json))


def from_code(image: str, *, common: Optional[str] = None, buffers: Optional[Mapping[str, str]] = None,
              channels: Optional[Mapping[str, Mapping[Union[int, str], Any]]] = None, name: str = "code") -> Shadertoy:
    """A Shadertoy from code strings: ``image`` (mainImage), ``common``, ``buffers`` ({"A": code,
    ...}) and ``channels`` ({"Image" or "A".."D": {0..3 or "iChannel0".. : source}}), where a source
    is a buffer ("A".."D", read linear and clamped as the site's default, or {"buffer": "A",
    "filter": "nearest", "wrap": "repeat"}), "keyboard", an input as the site's export writes it
    (a dict with "ctype"), or a numpy array: every Session made from the shadertoy shows it in that
    channel as Session.set_channel does (linear, clamped; call set_channel for other settings or
    new pixels). The passes run as the same code in an export or a folder: the frames are the
    same, byte for byte. Compile errors name the pass ("code [Buffer A]:LINE")."""
    arrays: dict = {}
    document = _code.export_of_code(image, common=common, buffers=buffers, channels=channels, name=name,
                                    arrays=arrays)
    shadertoy = _toyhost.load_export_json(_code.dumps(document), name, "")
    if arrays:
        shadertoy._arrays = arrays
    return shadertoy


class Session:
    """A shadertoy running headless at a fixed time step: frame n has iTime = start_time + n / fps.

    ``size`` is the canvas (iResolution), ``date`` iDate at time 0 ("YYYY-MM-DDTHH:MM:SS", local;
    default: now; fix it for repeatable frames), ``media_folders`` / ``media_files`` real files for
    Shadertoy's stock media (else deterministic stand-ins), ``float_image`` renders Image into 32-bit
    floats, ``frame_timeout`` / ``compile_timeout`` are limits in seconds (None or 0: none), ``mouse_script``
    / ``key_script`` are the CLI's --mouse-script / --key-script JSON files, replayed by step() and
    render() before their own input (the same frames as the CLI with those scripts). Left out
    (None), size and fps are the manifest's defaults, else toyhost's (800x450, 60); a value given
    is checked (``size=(0, 2)`` or ``fps=0`` raise UsageError naming the setting).

    Better pixels than the site (docs/sampling.md): ``supersample=N`` draws Image N x N times a frame
    with fragCoord on a grid inside each pixel, ``motion_blur=S`` at S times inside the shutter
    interval (``shutter`` degrees of the frame step, default 180), and the draws are averaged
    (buffers still run once a frame); ``dither=True`` dithers the average before it is rounded to 8
    bits. The same frames as the CLI's --supersample, --motion-blur, --shutter and --dither.

    ``defines`` adds macros to every pass after the site's header, before Common, as the CLI's
    --define: ``["TRUTH", "STEPS=64"]`` or ``{"TRUTH": True, "STEPS": 64}`` (a name alone, True or
    None is defined as 1). A name that is not a GLSL macro name raises UsageError naming ``defines``.

    Close it (``close()`` or ``with``) to free its GL context at once rather than at garbage
    collection."""

    def __init__(self, shadertoy: Union[Shadertoy, PathLike, dict, list], *,
                 size: Optional[Tuple[int, int]] = None, fps: Optional[float] = None, start_time: float = 0.0,
                 date: Optional[str] = None, media_folders: Union[PathLike, Sequence[PathLike]] = (),
                 media_files: Optional[Mapping[str, PathLike]] = None, float_image: bool = False,
                 frame_timeout: Optional[float] = None, compile_timeout: Optional[float] = None,
                 mouse_script: Optional[PathLike] = None, key_script: Optional[PathLike] = None,
                 supersample: Optional[int] = None, motion_blur: Optional[int] = None,
                 shutter: Optional[float] = None, dither: bool = False, shutter_offset: Optional[str] = None,
                 sample_space: Optional[str] = None, defines: Defines = ()) -> None:
        if not isinstance(shadertoy, Shadertoy):
            shadertoy = load(shadertoy)
        # The keywords above are written from the settings' one list (_signature.py); what each
        # becomes and how it is checked is the same list (_settings.py).
        given = _settings.native({key: value for key, value in locals().items() if key in _settings.KEYWORDS})
        self._fps = given["fps"] if "fps" in given else _toyhost.defaults()["fps"]
        self._native = _toyhost.NativeSession(shadertoy, given)
        self.shadertoy = shadertoy
        self._drawn = False  # frame() has nothing to show before the first step (restart keeps the picture)
        self._mouse_held = False
        self._keys_held: Set[int] = set()
        for (pass_name, channel), array in getattr(shadertoy, "_arrays", {}).items():
            self.set_channel(pass_name, channel, array)

    # --- rendering -------------------------------------------------------------------------------

    def step(self, *, mouse: Union[Point, bool, None] = None, keys: Optional[Keys] = None, time: Optional[float] = None,
             time_delta: Optional[float] = None, frame_rate: Optional[float] = None,
             events: Iterable[InputEvent] = ()) -> int:
        """Renders the next frame and returns its iFrame. Returns once the frame is submitted to
        the GPU, which draws it while Python goes on; frame() waits for it.

        ``mouse``: None leaves the mouse as it is; ``(x, y)`` holds the button down at canvas pixel
        (x, y), origin bottom-left (a press when it was up, a drag when already held); False
        releases it. ``keys``: None leaves the keys as they are; otherwise the keys held down from
        this frame on (keyCodes, characters or names: ``{"W", "Space"}``; an empty set releases
        all): presses and releases follow from the difference. ``events``: further InputEvents,
        applied after those. ``time``: iTime of this frame instead of the fixed step, with
        iTimeDelta ``time_delta`` (default 1/fps) and iFrameRate ``frame_rate`` (default fps)."""
        if time is None:  # the fixed step sets both; a value given alone would be silently ignored
            for name, value in (("time_delta", time_delta), ("frame_rate", frame_rate)):
                if value is not None:
                    raise args.usage(name, "is given with time=... only (the fixed step sets it otherwise)")
        iframe = self._native.step(self._events(mouse, keys, events), args.optional(args.real, "time", time),
                                   1.0 / self._fps if time_delta is None else args.real("time_delta", time_delta),
                                   self._fps if frame_rate is None else args.real("frame_rate", frame_rate))
        self._drawn = True
        return iframe

    def seek(self, frame: int) -> None:
        """Goes on until iFrame ``frame`` is the next frame, reading nothing back, as the CLI's
        ``--frame-range`` and ``--shard`` reach their first frame: the frames before it are simulated
        at the fixed step (with the mouse and key scripts' events), buffers and Cube A running and
        Image not rendered; a shadertoy without them renders nothing (only iFrame and the input
        advance; an Image that may ``discard`` is drawn, as it keeps earlier frames' pixels). From
        there step() and render() give the frames of a session that stepped there, byte for byte.
        A frame before ``next_frame`` raises UsageError (a session only goes forward; restart()
        goes back to 0); ``next_frame`` itself does nothing."""
        self._native.seek(args.integer("frame", frame))

    def frame(self, pass_: str = "Image", dtype: Any = "uint8", out: Optional[numpy.ndarray] = None) -> numpy.ndarray:
        """The latest output of a pass ("Image", "Buffer A".."Buffer D") as a numpy array of shape
        (height, width, 4), RGBA, top row first. ``uint8``: what the screen shows (a buffer's floats
        clamped and rounded); ``float32``: a buffer's floats as they are (Image's are its 8-bit levels
        / 255 unless the session has float_image). ``out``: an array of that shape and type to read
        into instead of a new one (C-contiguous, writeable), returned. Before the first step() or
        render() there is no frame: UsageError."""
        dtype = _dtype_name(dtype)
        pass_ = args.text("pass_", pass_)
        if not self._drawn:
            raise UsageError("error: no frame has been rendered yet: call step() or render() first [usage]")
        if out is not None:
            if not isinstance(out, numpy.ndarray):
                raise UsageError(f"out: expected a numpy array, got {type(out).__name__}")
            return (self._native.read_into_uint8 if dtype == "uint8" else self._native.read_into_float32)(pass_, out)
        if dtype == "uint8":
            return self._native.read_uint8(pass_)
        return self._native.read_float32(pass_)

    def render(self, frames: int, *, every: int = 1, pass_: str = "Image", dtype: Any = "uint8",
               mouse: Union[Point, bool, None] = None, keys: Optional[Keys] = None) -> Iterator[Tuple[int, numpy.ndarray]]:
        """Renders ``frames`` frames and yields ``(iframe, array)`` for those whose iFrame is a
        multiple of ``every`` and the last of them (as the CLI's --capture-every: counted on
        iFrame, so a render from iFrame 100 with every=30 yields 120, 150, ... and its last), each
        array as frame() gives it. ``mouse`` and ``keys`` are applied before the first frame, as
        step() takes them, and stay.

        The frames go through the same frame stream as the CLI's recordings, rendered ahead of the
        loop as the CLI renders ahead of its encoders: while your loop handles a frame, the next
        ones render and are read back (at most 7 frames ahead of the one yielded). Each frame is
        yielded as soon as its read completes (frame 0 of ``render(301, every=100)`` long before
        frame 100 renders). So inside the loop the session is already further on (``next_frame``,
        ``frame()``, and a ``step()`` there renders after the frames already rendered), and leaving
        the loop early leaves the session up to 7 frames past the last one yielded; frames rendered
        but not taken are dropped. Ctrl-C while the loop waits for a frame raises
        KeyboardInterrupt; the rendering stops after the frame being rendered when the signal came
        (no frame starts after it)."""
        frames = args.integer("frames", frames, minimum=0)
        every = args.integer("every", every, minimum=1)
        pass_ = args.text("pass_", pass_)
        readable = [p for p in self.shadertoy.passes if p == "Image" or p.startswith("Buffer ")]
        if pass_ not in readable:  # said before any frame renders
            raise UsageError(f'render: no pass "{pass_}" to read (this shadertoy has {", ".join(readable)})')
        stream = self._native.render(self._events(mouse, keys, ()), frames, every, pass_,
                                     _dtype_name(dtype) == "float32")
        try:
            while (item := stream.next()) is not None:
                self._drawn = True
                yield item
            if self.closed:
                raise UsageError("the session was closed while render() ran")
        finally:
            stream.cancel()

    def record(self, out: PathLike, frames: int, *, every: int = 1, pass_: str = "Image",
               mouse: Union[Point, bool, None] = None, keys: Optional[Keys] = None) -> list:
        """Renders ``frames`` frames (as render() steps them) and writes the 0th, every ``every``-th
        and the last through toyhost's own encoders, as the CLI's ``--out`` does: ``out`` is a PNG or
        EXR pattern ("f_%04d.png", numbered from 0 as the CLI numbers a run's files) or a video
        ("take.mp4", .webm, .mov, .mkv; needs ffmpeg). A fresh session with the CLI's settings
        writes the CLI's files byte for byte (a video: the same decoded frames). Returns the paths
        written. On an error nothing half written is left (an unfinished video is removed)."""
        frames = args.integer("frames", frames, minimum=1)
        every = args.integer("every", every, minimum=1)
        files = self._native.record(self._events(mouse, keys, ()), args.path("out", out), frames, every,
                                    args.text("pass_", pass_))
        self._drawn = True
        return [pathlib.Path(f) for f in files]

    def set_channel(self, pass_: str, channel: Union[int, str], array: Any, *, filter: str = "linear",
                    wrap: str = "clamp") -> None:
        """Shows ``array`` in channel ``channel`` (0..3 or "iChannel0".."iChannel3") of ``pass_``
        ("Image", "Buffer A".."Buffer D", "Cube A") from the next frame on: a numpy array of shape
        (height, width) or (height, width, 1|3|4), uint8 (0..255 sampled as 0..1) or float32 (sampled
        as it is, unclamped), top row first as frame() gives one, so a frame passed back shows upright.
        The texture's size and format follow the array (iChannelResolution too); one component
        samples as (r, 0, 0, 1), three as (r, g, b, 1). ``filter``: "nearest", "linear" or
        "mipmap" (uint8 only); ``wrap``: "clamp" or "repeat". Call it again before any step() with new
        pixels (frames of a video, a simulation's field); they are uploaded straight from the
        array's memory (a copy is made only to make a non-contiguous array contiguous). The channel
        must be unbound or show a picture (replaced); a buffer, cubemap, video or keyboard channel
        raises UsageError, as do other dtypes or shapes."""
        pass_ = args.text("pass_", pass_)
        channel = args.channel("channel", channel)
        if filter not in _code.FILTERS:
            raise args.usage("filter", f"must be one of {', '.join(_code.FILTERS)}, got {filter!r}")
        if wrap not in _code.WRAPS:
            raise args.usage("wrap", f"must be one of {', '.join(_code.WRAPS)}, got {wrap!r}")
        if not _code.is_array(array) or isinstance(array, (str, bytes, dict)):
            raise args.usage("array", f"expected a numpy array, got {type(array).__name__}")
        self._native.set_channel(pass_, channel, args.channel_array("array", array), filter, wrap)

    def render_sound(self, seconds: float = 0.0) -> numpy.ndarray:
        """The Sound pass (mainSound) as the site renders it: float32 samples of shape (n, 2), stereo
        at 44100 Hz, ``seconds`` long (0: the site's 180 s; negative, NaN, infinite or more than an
        hour raise UsageError naming ``seconds``)."""
        return self._native.render_sound(args.real("seconds", seconds, finite=False))

    def reload(self, shadertoy: Optional[Shadertoy] = None) -> Reloaded:
        """Switches to the shadertoy's files as they are now (`shadertoy`: loaded anew from this
        session's path when left out) without restarting: changed passes are recompiled, a pass
        that fails keeps its last good program, a changed structure keeps the buffers that still
        exist; iFrame and time go on. Returns a Reloaded (applied, structure_changed, recompiled,
        problems: Diagnostics, empty when everything runs). Loading problems raise as load() does."""
        if shadertoy is None:
            shadertoy = load(self.shadertoy.path)
        elif not isinstance(shadertoy, Shadertoy):
            shadertoy = load(shadertoy)
        outcome = self._native.reload(shadertoy)
        if outcome.applied:
            self.shadertoy = shadertoy
        return outcome

    def restart(self) -> None:
        """iFrame back to 0 and every buffer cleared (the site's restart); mouse and keys stay."""
        self._native.restart()

    def resize(self, size: Tuple[int, int]) -> None:
        """A new canvas size; buffers keep their content bottom-left, iFrame goes on."""
        self._native.resize(*args.size("size", size))

    # --- notebooks -------------------------------------------------------------------------------

    def show(self, frames: int = 60, *, every: int = 1, mouse: Union[Point, bool, None] = None,
             keys: Optional[Keys] = None, strip: bool = False, scale: int = 1) -> "_notebook.Animation":
        """Renders ``frames`` frames (as render(), keeping every ``every``-th) and returns an
        Animation that Jupyter plays inline: an animated PNG at the session's fps / every, looping,
        or with ``strip=True`` the frames side by side as one still. ``scale`` enlarges it on screen
        (pixels stay sharp). ``mouse`` / ``keys`` as render() takes them. The session goes on from
        where it is, as after render()."""
        frames = args.integer("frames", frames, minimum=1)  # an animation of no frames is no picture
        every = args.integer("every", every)
        scale = args.integer("scale", scale)
        if scale < 1 or scale > 16:
            raise args.usage("scale", f"must be 1..16, got {scale}")
        taken = list(self.render(frames, every=every, mouse=mouse, keys=keys))
        return _notebook.Animation(taken, self._fps / max(1, every), strip=args.flag("strip", strip), scale=scale)

    def _repr_png_(self):
        """Jupyter's inline picture: the latest Image frame; none before the first step."""
        if self.closed or not self._drawn:
            return None
        return _notebook.png_bytes(self.frame())

    # --- state -----------------------------------------------------------------------------------

    @property
    def next_frame(self) -> int:
        """iFrame of the next frame (the number of frames rendered since the start or a restart)."""
        return self._native.next_frame

    @property
    def size(self) -> Tuple[int, int]:
        return (self._native.width, self._native.height)

    @property
    def fps(self) -> float:
        return self._fps

    @property
    def notices(self) -> list:
        """Diagnostics about the run so far (the shadertoy's own notices from loading, stand-ins used,
        passes preprocessed), oldest first."""
        return self._native.notices

    @property
    def backend(self) -> str:
        """The GL backend ("EGL surfaceless; OpenGL ES 3.2 Mesa ...")."""
        return self._native.backend

    def close(self) -> None:
        """Frees the session's GL context and objects now; later calls raise UsageError."""
        self._native.close()

    @property
    def closed(self) -> bool:
        return self._native.closed

    def __enter__(self) -> "Session":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def __repr__(self):
        state = "closed" if self.closed else f"{self.size[0]}x{self.size[1]}, next frame {self.next_frame}"
        return f"<toyhost.Session '{self.shadertoy.name}' {state}>"

    # --- input -----------------------------------------------------------------------------------

    def _events(self, mouse, keys, events):
        out = []
        if mouse is False:
            if self._mouse_held:
                out.append(InputEvent.mouse_up())
            self._mouse_held = False
        elif mouse is not None:
            if mouse is True:
                raise args.usage("mouse", "expected (x, y), False or None, got True")
            x, y = args.point("mouse", mouse)
            out.append(InputEvent.mouse_move(x, y) if self._mouse_held else InputEvent.mouse_down(x, y))
            self._mouse_held = True
        if keys is not None:
            held = {key_code(k) for k in ([keys] if isinstance(keys, (str, int)) else keys)}
            out += [InputEvent.key_up(k) for k in sorted(self._keys_held - held)]
            out += [InputEvent.key_down(k) for k in sorted(held - self._keys_held)]
            self._keys_held = held
        for event in events:
            if not isinstance(event, InputEvent):
                raise args.usage("events", f"expected toyhost.InputEvent, got {event!r}")
            out.append(event)
        return out


def _dtype_name(dtype):
    if dtype == "uint8" or dtype == "float32":
        return dtype
    try:
        name = numpy.dtype(dtype).name
    except TypeError:
        raise UsageError(f"dtype: uint8 or float32, got {dtype!r}") from None
    if name not in ("uint8", "float32"):
        raise UsageError(f"dtype: uint8 or float32, got {name}")
    return name


PREVIEW_SIZE = (400, 225)
PREVIEW_DATE = "2026-01-01T00:00:00"


def _shadertoy_png(shadertoy):
    """Jupyter's inline picture of a Shadertoy: its frame 0 at 400x225 (iDate 2026-01-01), rendered
    in a session of its own."""
    with Session(shadertoy, size=PREVIEW_SIZE, date=PREVIEW_DATE) as session:
        session.step()
        return _notebook.png_bytes(session.frame())


setattr(Shadertoy, "_repr_png_", _shadertoy_png)  # the native class gains the notebook preview

