"""The module's types: py.typed and the native module's stub ship with the package, and mypy (Debian's
`mypy`) accepts a small script written against the public API, and refuses one that misuses it
(so the check can fail)."""

import os
import pathlib
import subprocess
import sys

import toyhost

GOOD = '''
import numpy
import toyhost

toy: toyhost.Shadertoy = toyhost.load("shadertoys/bench-trivial")
coded = toyhost.from_code("void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }", buffers={"A": "..."})
with toyhost.Session(toy, size=(64, 36), fps=30.0, date="2026-01-01T00:00:00", defines=["TRUTH"]) as session:
    frame_number: int = session.step(mouse=(10.0, 5.0), keys={"W"})
    image: numpy.ndarray = session.frame()
    for iframe, array in session.render(10, every=5):
        total: float = float(array.mean()) + iframe
    width, height = session.size
report = toyhost.compare(toy, coded, frames=2, size=(16, 8))
ok: bool = report.equal
difference = toyhost.compare_images(image, image, channels=4)
psnr: float = difference.psnr
notices: list = toy.notices
code: int = toyhost.key_code("Space")
try:
    toyhost.load("missing")
except toyhost.ManifestError as error:
    line: int = error.line
'''

BAD = '''
import toyhost

with toyhost.Session("x", size=(64, 36)) as session:
    name: str = session.step()
    session.render("ten")
toyhost.Session("x", (64, 36))
'''


def mypy(tmp_path, text):
    script = tmp_path / "script.py"
    script.write_text(text)
    module_dir = pathlib.Path(toyhost.__file__).resolve().parents[1]
    env = {**os.environ, "MYPYPATH": str(module_dir), "PYTHONPATH": str(module_dir)}
    return subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
                           "--python-executable", sys.executable, str(script)],
                          capture_output=True, text=True, env=env, cwd=tmp_path, check=False)


def test_the_package_ships_its_types():
    folder = pathlib.Path(toyhost.__file__).parent
    assert (folder / "py.typed").exists()
    assert (folder / "_toyhost.pyi").exists()


def test_mypy_accepts_a_script_using_the_api(tmp_path):
    done = mypy(tmp_path, GOOD)
    assert done.returncode == 0, done.stdout + done.stderr


def test_mypy_refuses_a_script_misusing_it(tmp_path):
    done = mypy(tmp_path, BAD)
    assert done.returncode == 1, done.stdout + done.stderr
    out = done.stdout
    assert 'Incompatible types in assignment (expression has type "int", variable has type "str")' in out, out
    assert 'Argument 1 to "render" of "Session" has incompatible type "str"' in out, out
    assert "Too many positional arguments" in out, out


def test_the_package_itself_is_mypy_clean(tmp_path):
    """`mypy -p toyhost` on the package as built (issue 45: it had two errors of its own)."""
    module_dir = pathlib.Path(toyhost.__file__).resolve().parents[1]
    env = {**os.environ, "MYPYPATH": str(module_dir), "PYTHONPATH": str(module_dir)}
    done = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
                           "--python-executable", sys.executable, "-p", "toyhost"],
                          capture_output=True, text=True, env=env, cwd=tmp_path, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
