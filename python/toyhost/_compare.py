"""toyhost.compare: two shadertoys rendered with the same inputs and compared frame by frame
(PSNR, largest and mean difference, the first differing frame and pixel, difference images), and
compare_images for two frames already in numpy. For ports ("does my port still match the
original?") and for scoring generated shader code against a reference."""

import math
from dataclasses import dataclass, field
from typing import Any, Iterable, Mapping, Optional, Sequence, Tuple, Union, List

import numpy

from . import _args as args
from . import _toyhost


@dataclass
class FrameDifference:
    """One frame of A against B. Samples are 8-bit levels (Image: R, G, B; a buffer: R, G, B, A).
    ``psnr`` is in dB, peak 255, ``math.inf`` when identical; ``first_x``/``first_y`` the first
    differing pixel scanning from the top row (None when none); ``diff_image`` |a - b| * gain as
    (height, width, 4) uint8 when kept, else None."""
    frame: int
    time: float
    psnr: float
    max_diff: int
    mean_diff: float
    differing_pixels: int
    first_x: Optional[int]
    first_y: Optional[int]
    within_tolerance: bool
    diff_image: object = field(default=None, repr=False)


@dataclass
class CompareReport:
    """Every compared frame, and the summary: the first frame beyond the tolerance (None: all
    equal), the worst PSNR, the largest difference. ``equal`` is what `toyhost compare`'s exit
    code says."""
    width: int
    height: int
    fps: float
    start_time: float
    pass_: str
    frames: List[FrameDifference]
    first_differing_frame: Optional[int]
    min_psnr: float
    max_diff: int

    @property
    def equal(self) -> bool:
        return self.first_differing_frame is None

    def __repr__(self):
        # A notebook shows an object's repr: the summary line, not every frame's dataclass.
        return f"<toyhost.CompareReport {self}>"

    def __str__(self):
        psnr = "inf" if math.isinf(self.min_psnr) else f"{self.min_psnr:.2f}"
        verdict = "equal" if self.equal else f"first differs at frame {self.first_differing_frame}"
        return (f"{self.pass_} {self.width}x{self.height}, {len(self.frames)} frames: min PSNR {psnr} dB, "
                f"max difference {self.max_diff}; {verdict}")


def _frame(values):
    return FrameDifference(**values)


def compare(a: Any, b: Any, *, frames: Optional[int] = None, size: Optional[Tuple[int, int]] = None,
            fps: Optional[float] = None, start_time: float = 0.0, date: Optional[str] = None, pass_: str = "Image",
            min_psnr: Optional[float] = None, max_diff: Optional[int] = None,
            mouse: Optional[Tuple[float, float]] = None, mouse_script: Optional[Any] = None,
            key_script: Optional[Any] = None, keep_diff_images: bool = False, diff_gain: int = 0,
            stop_at_first_difference: bool = False, media_folders: Union[Any, Sequence[Any]] = (),
            media_files: Optional[Mapping[str, Any]] = None, frame_timeout: Optional[float] = None,
            compile_timeout: Optional[float] = None) -> CompareReport:
    """Renders ``a`` and ``b`` (Shadertoys, or anything toyhost.load takes) headless with the same
    size, fps, start time, date and inputs, and compares ``pass_`` after every frame.

    Left out, ``frames``, ``size`` and ``fps`` come from A's manifest defaults, then B's, then
    toyhost's; ``date`` is fixed to now once for both. Frames count as equal when identical, or
    within ``min_psnr`` (dB) and/or ``max_diff`` (levels) when given. ``mouse=(x, y)`` presses the
    button there before frame 0 and holds it (the CLI's --mouse); ``mouse_script``/``key_script``
    are the CLI's JSON input scripts. ``keep_diff_images`` keeps a difference image (scaled by
    ``diff_gain``, 0: toyhost's default) for every frame beyond the tolerance;
    ``stop_at_first_difference`` ends the run there. ``media_folders``, ``media_files``,
    ``frame_timeout`` and ``compile_timeout`` are a Session's, for both. Returns a CompareReport; problems (a shadertoy
    that does not compile, a pass one of them lacks) raise toyhost errors naming the file."""
    from . import Shadertoy, load

    a = a if isinstance(a, Shadertoy) else load(a)
    b = b if isinstance(b, Shadertoy) else load(b)
    width, height = (None, None) if size is None else args.size("size", size)
    frames = args.optional(args.integer, "frames", frames, minimum=1)
    report = _toyhost.compare(
        a, b, width, height, args.optional(args.real, "fps", fps), args.real("start_time", start_time),
        args.optional(args.text, "date", date), args.paths("media_folders", media_folders),
        args.named_paths("media_files", media_files or {}), args.optional(args.real, "frame_timeout", frame_timeout),
        args.optional(args.real, "compile_timeout", compile_timeout), frames or 0, args.text("pass_", pass_),
        args.optional(args.real, "min_psnr", min_psnr, finite=False), args.optional(args.integer, "max_diff", max_diff),
        args.optional(args.point, "mouse", mouse), args.optional(args.path, "mouse_script", mouse_script),
        args.optional(args.path, "key_script", key_script), args.flag("keep_diff_images", keep_diff_images),
        args.integer("diff_gain", diff_gain), args.flag("stop_at_first_difference", stop_at_first_difference))
    report["frames"] = [_frame(f) for f in report["frames"]]
    return CompareReport(**report)


def compare_images(a: Any, b: Any, *, channels: int = 3, min_psnr: Optional[float] = None,
                   max_diff: Optional[int] = None, diff_image: bool = False, diff_gain: int = 0) -> FrameDifference:
    """Two frames as toyhost.Session.frame() gives them ((height, width, 4) uint8) compared as
    toyhost compare does: ``channels`` 3 compares R, G, B (as for Image, whose alpha is always 1),
    4 all four. Returns a FrameDifference (frame and time 0); ``diff_image`` asks for the
    difference image."""
    first = numpy.ascontiguousarray(a)
    second = numpy.ascontiguousarray(b)
    return _frame(_toyhost.compare_images(first, second, args.integer("channels", channels),
                                          args.optional(args.real, "min_psnr", min_psnr, finite=False),
                                          args.optional(args.integer, "max_diff", max_diff),
                                          args.flag("diff_image", diff_image), args.integer("diff_gain", diff_gain)))
