"""toyhost.defaults(): the library's defaults (toyhost::runDefaults, from core/Defaults.h), the same
numbers a Session takes for what it is not given and the CLI shows in --help."""

import re

import toyhost
from support import run_cli, write_shadertoy

IMAGE = "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n"


def test_defaults_are_a_fresh_dict_of_every_value():
    d = toyhost.defaults()
    assert set(d) == {"width", "height", "fps", "min_fps", "max_fps", "max_canvas_side", "frames",
                      "compare_frames", "capture_every", "png_level", "capture_memory_mib", "sample_rate",
                      "sound_seconds", "frame_timeout", "compile_timeout"}
    assert (d["width"], d["height"], d["fps"], d["sample_rate"]) == (800, 450, 60.0, 44100.0)
    d["width"] = 1
    assert toyhost.defaults()["width"] == 800


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
