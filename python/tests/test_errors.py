"""Diagnostics as Python exceptions: a pass that does not compile raises CompileError naming the
pass, its file and the line within it; the class follows the problem's category."""

import pytest

import toyhost
from support import write_shadertoy

GOOD = "void mainImage(out vec4 c, in vec2 p) { c = vec4(1); }\n"
BROKEN = ("void mainImage(out vec4 c, in vec2 p) {\n"
          "    vec3 base = vec3(0.5);\n"
          "    c = vec4(mix(base, undefined_thing, 0.5), 1.0);\n"
          "}\n")


def test_a_compile_error_names_the_pass_file_and_line(tmp_path):
    folder = write_shadertoy(tmp_path / "broken", {"Buffer A": BROKEN, "Image": GOOD})
    shadertoy = toyhost.load(folder)  # loading checks no GLSL
    with pytest.raises(toyhost.CompileError) as raised:
        toyhost.Session(shadertoy, size=(8, 4))
    error = raised.value
    assert isinstance(error, toyhost.Error)
    assert error.category == "shader"
    assert error.code == "shader.compile"
    assert error.pass_ == "Buffer A"
    assert error.file.endswith("buffer_a.glsl"), error.file
    assert error.line == 3, "the line within the pass's own file"
    assert "undefined_thing" in str(error)
    assert "Buffer A" in str(error)
    assert error.diagnostics[0].excerpt, "the source line with a caret"


def test_a_compile_error_in_an_export_names_the_pass(tmp_path):
    import json
    text = json.dumps({"Shader": {"info": {"id": "x", "name": "E"}, "renderpass": [
        {"inputs": [], "outputs": [{"id": 37, "channel": 0}], "code": BROKEN, "name": "Image", "type": "image"}]}})
    with pytest.raises(toyhost.CompileError) as raised:
        toyhost.Session(toyhost.load(text, name="pasted.json", folder=tmp_path), size=(8, 4))
    assert raised.value.pass_ == "Image" and raised.value.line == 3
    assert "pasted.json" in raised.value.file


def test_errors_raised_by_python_carry_a_code_too():
    error = toyhost.UsageError("size: bad")
    assert error.code == "usage" and error.category == "usage" and error.diagnostics == []
    assert isinstance(error, ValueError), "usage errors are ValueErrors too"


def test_a_failing_session_can_be_retried_after_the_fix(tmp_path):
    folder = write_shadertoy(tmp_path / "fixme", {"Image": BROKEN})
    with pytest.raises(toyhost.CompileError):
        toyhost.Session(folder, size=(8, 4))  # a path is loaded for you
    (folder / "image.glsl").write_text(GOOD)
    with toyhost.Session(folder, size=(8, 4)) as session:
        session.step()
        assert (session.frame() == 255).all()


def test_the_classes_are_named_as_the_package_exports_them():
    """Tracebacks say toyhost.UsageError, not toyhost._errors.UsageError (issue 45); an error
    survives pickling (a Dask worker's)."""
    import pickle
    import traceback
    for name in ("Error", "UsageError", "InputError", "ManifestError", "CompileError", "OutputError", "GlError",
                 "StoppedError", "WatchdogError", "InternalError"):
        assert getattr(toyhost, name).__module__ == "toyhost", name
    try:
        toyhost.Session(toyhost.from_code(image=GOOD), size=(0, 2))
    except toyhost.UsageError as e:
        text = "".join(traceback.format_exception_only(type(e), e))
        assert text.startswith("toyhost.UsageError: "), text
        back = pickle.loads(pickle.dumps(e))  # as a Dask worker's error reaches the client
        assert type(back) is toyhost.UsageError and str(back) == str(e)
        assert (back.code, back.field, back.diagnostics) == (e.code, e.field, [])
    else:
        raise AssertionError("size=(0, 2) was accepted")
