"""toyhost.defaults(): the library's defaults (toyhost::runDefaults, from the one list of
toyhost/Defaults.h), the same numbers a Session takes for what it is not given and the CLI shows
in --help; Session's keywords, from the settings' one list (toyhost/Settings.h)."""

import inspect
import os
import pathlib
import re

import pytest

import toyhost
from support import run_cli, write_shadertoy

IMAGE = "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n"


def test_defaults_are_a_fresh_dict_of_every_value():
    d = toyhost.defaults()
    assert set(d) == {"width", "height", "fps", "min_fps", "max_fps", "max_canvas_side", "frames",
                      "compare_frames", "capture_every", "png_level", "capture_memory_mib", "sample_rate",
                      "sound_seconds", "frame_timeout", "compile_timeout", "supersample", "motion_blur",
                      "shutter", "max_supersample", "max_motion_blur", "max_samples_per_frame"}
    assert (d["width"], d["height"], d["fps"], d["sample_rate"]) == (800, 450, 60.0, 44100.0)
    # The sampling defaults the list gained (they read 0 when runDefaults() was kept by hand).
    assert (d["supersample"], d["motion_blur"], d["shutter"]) == (1, 1, 180.0)
    assert (d["max_supersample"], d["max_motion_blur"], d["max_samples_per_frame"]) == (16, 256, 4096)
    assert all(value > 0 for value in d.values()), d
    d["width"] = 1
    assert toyhost.defaults()["width"] == 800


def test_every_setting_of_the_list_is_a_session_keyword_with_a_fallback():
    """The settings' one list (C++ toyhost/Settings.h) makes Session's keywords: a row without a
    keyword, or a keyword that is no row, fails here; so does a fallback that is neither a default
    nor the field's initial value."""
    fields = toyhost._toyhost.setting_fields()
    keys = {key for _member, key, _kind, _fallback, _initial in fields}
    parameters = set(inspect.signature(toyhost.Session.__init__).parameters) - {"self", "shadertoy"}
    assert parameters == keys
    assert {"size", "fps", "supersample", "motion_blur", "shutter", "dither", "defines"} <= keys
    for member, key, kind, fallback, _initial in fields:
        assert kind in toyhost._settings.KINDS, (member, kind)
        assert fallback == "initial" or fallback[0].islower(), (member, fallback)


def test_sessions_signature_and_its_docs_are_what_the_list_writes():
    """Session.__init__'s keywords (types and defaults) and docs/python.md's Session line are
    written from the settings' list; a row added without rewriting them fails here."""
    from toyhost import _signature
    source = os.environ.get("TOYHOST_SOURCE_DIR", str(pathlib.Path(__file__).resolve().parents[2]))
    assert _signature.stale(source) == [], \
        "run: PYTHONPATH=BUILD/python python3 -m toyhost._signature --write " + source
    parameters = list(inspect.signature(toyhost.Session.__init__).parameters.values())[2:]
    assert [(p.name, p.default) for p in parameters] == \
        [(key, eval(default)) for key, _annotation, default in _signature._parameters()]


def test_a_stale_signature_is_found(tmp_path):
    """The check itself: a keyword's default edited by hand in a copy is caught."""
    from toyhost import _signature
    source = os.environ.get("TOYHOST_SOURCE_DIR", str(pathlib.Path(__file__).resolve().parents[2]))
    for name in ("python/toyhost/__init__.py", "docs/python.md"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text((pathlib.Path(source) / name).read_text())
    assert _signature.stale(str(tmp_path)) == []
    init = tmp_path / "python/toyhost/__init__.py"
    init.write_text(init.read_text().replace("dither: bool = False", "dither: bool = True"))
    assert _signature.stale(str(tmp_path)) == ["python/toyhost/__init__.py"]
    _signature._write(str(tmp_path))
    assert _signature.stale(str(tmp_path)) == []


def test_a_setting_given_reaches_the_session_and_a_wrong_keyword_is_refused(tmp_path):
    toy = write_shadertoy(tmp_path / "toy", {"Image": IMAGE})
    with toyhost.Session(toy, size=(24, 8), fps=12.5) as session:
        assert session.size == (24, 8)
        assert session.fps == 12.5
    with pytest.raises(TypeError, match="unexpected keyword argument 'sise'"):
        toyhost.Session(toy, sise=(24, 8))


def test_a_session_given_nothing_takes_the_defaults(tmp_path):
    d = toyhost.defaults()
    with toyhost.Session(write_shadertoy(tmp_path / "toy", {"Image": IMAGE})) as session:
        assert session.size == (d["width"], d["height"])
        assert session.fps == d["fps"]


def test_the_cli_help_shows_the_same_defaults():
    d = toyhost.defaults()
    code, text = run_cli("run", "--help")
    assert code == 0, text
    assert f"{d['width']}x{d['height']}" in text
    assert re.search(r"default %d\b" % d["frames"], text), text
