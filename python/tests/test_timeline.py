"""One scripted run (mouse and key scripts, start time, date, fps) through Python's step() and
render(): byte-identical to the CLI's frames, because both step the same fixed-step input
(timing/Timeline.h). The C++ Session and compare are checked in tests/gl/test_timeline_surfaces.cpp."""

import numpy

import toyhost
from support import SOURCE_DIR, read_png, run_cli

PROBE = SOURCE_DIR / "shadertoys/timeline-probe"
DATE = "2024-02-29T23:59:58"
FRAMES = 9
MOUSE = """[{"frame": 1, "type": "down", "x": 8, "y": 6},
            {"frame": 2, "type": "move", "to": {"frame": 6, "x": 20, "y": 25}},
            {"time": 1.7, "type": "up"}]"""
KEYS = """[{"frame": 3, "type": "down", "key": 65}, {"frame": 5, "type": "up", "key": 65},
           {"time": 1.75, "type": "tap", "key": 65}]"""


def scripts(tmp_path):
    (tmp_path / "mouse.json").write_text(MOUSE)
    (tmp_path / "keys.json").write_text(KEYS)
    return tmp_path / "mouse.json", tmp_path / "keys.json"


def cli_frames(tmp_path, mouse, keys):
    code, output = run_cli("run", PROBE, "--headless", "--size", "48x32", "--frames", FRAMES, "--fps", 24,
                           "--start-time", 1.5, "--date", DATE, "--mouse-script", mouse, "--key-script", keys,
                           "--quiet", "--out", tmp_path / "f_%d.png")
    assert code == 0, output
    return [read_png(tmp_path / f"f_{n}.png") for n in range(FRAMES)]


def session(mouse, keys):
    return toyhost.Session(toyhost.load(PROBE), size=(48, 32), fps=24, start_time=1.5, date=DATE,
                           mouse_script=mouse, key_script=keys)


def test_step_gives_the_clis_scripted_frames(tmp_path):
    mouse, keys = scripts(tmp_path)
    cli = cli_frames(tmp_path, mouse, keys)
    assert not numpy.array_equal(cli[2], cli[6]), "the scripts change the picture"
    with session(mouse, keys) as s:
        for n in range(FRAMES):
            assert s.step() == n
            assert s.frame().tobytes() == cli[n].tobytes(), f"frame {n}"


def test_render_gives_the_clis_scripted_frames(tmp_path):
    mouse, keys = scripts(tmp_path)
    cli = cli_frames(tmp_path, mouse, keys)
    with session(mouse, keys) as s:
        got = dict(s.render(FRAMES))
    assert sorted(got) == list(range(FRAMES))
    for n in range(FRAMES):
        assert got[n].tobytes() == cli[n].tobytes(), f"frame {n}"


def test_without_the_key_script_the_frames_differ(tmp_path):
    mouse, keys = scripts(tmp_path)
    cli = cli_frames(tmp_path, mouse, keys)
    with session(mouse, None) as s:
        for _ in range(4):
            s.step()
        assert s.frame().tobytes() != cli[3].tobytes()
