"""Docs that run (issue 45): every code block of docs/python.md is executed here, so an example
cannot drift from the module again. The page's ```python blocks run in order as one script (as a
reader pastes them into one notebook), then each ```sh block, from a folder laid out as a checkout's
top (shadertoys/, examples/, build/ as links to this source tree and this build, ../shared beside
it), with `python3`
being the interpreter that runs the tests."""

import os
import pathlib
import re
import subprocess
import sys

from support import SHARED_DIR, SOURCE_DIR, require_shared

BLOCK = re.compile(r"^```(\w+)\n(.*?)^```", re.S | re.M)
BUILD_DIR = pathlib.Path(os.environ.get("TOYHOST_BUILD_DIR", SOURCE_DIR / "build"))


def blocks(page):
    return BLOCK.findall((SOURCE_DIR / page).read_text())


def checkout_like(tmp_path):
    top = tmp_path / "top"
    top.mkdir()
    for name in ("shadertoys", "examples"):
        (top / name).symlink_to(SOURCE_DIR / name)
    (top / "build").symlink_to(BUILD_DIR)
    (tmp_path / "shared").symlink_to(SHARED_DIR)  # beside the checkout, as the manifests expect
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    (bin_dir / "python3").symlink_to(sys.executable)
    env = {**os.environ, "PATH": f"{bin_dir}:{os.environ['PATH']}", "PYTHONPATH": str(BUILD_DIR / "python"),
           "PYTHONDONTWRITEBYTECODE": "1"}
    return top, env


def test_the_pages_blocks_are_found():
    """The extraction itself: a page whose fences changed would otherwise run nothing and pass."""
    kinds = [kind for kind, _code in blocks("docs/python.md")]
    assert kinds.count("python") >= 2 and kinds.count("sh") >= 1, kinds
    assert set(kinds) <= {"python", "sh"}, f"a block of a kind this test does not run: {kinds}"


def test_docs_python_md_runs(tmp_path):
    require_shared("shadertoys")  # shadertoys/ocean reads the original there
    top, env = checkout_like(tmp_path)
    page = blocks("docs/python.md")
    script = "\n\n".join(code for kind, code in page if kind == "python")
    done = subprocess.run([sys.executable, "-c", script], cwd=top, env=env, capture_output=True, text=True,
                          timeout=900, check=False)
    assert done.returncode == 0, f"docs/python.md's python blocks failed:\n{done.stdout}\n{done.stderr}"
    assert "Image 320x180, 10 frames" in done.stdout, done.stdout  # the compare block's print(report)
    for kind, code in page:
        if kind != "sh":
            continue
        done = subprocess.run(["bash", "-euo", "pipefail", "-c", code], cwd=top, env=env, capture_output=True,
                              text=True, timeout=900, check=False)
        assert done.returncode == 0, f"docs/python.md's block failed:\n{code}\n{done.stdout}\n{done.stderr}"
    assert (top / "out" / "ripple-grid.png").stat().st_size > 0
