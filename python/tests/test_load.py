"""toyhost.load: a folder, a manifest file, an export file and export JSON text all give a
Shadertoy; problems raise toyhost errors naming the file and place."""

import json

import pytest

import toyhost
from support import SOURCE_DIR, write_shadertoy

IMAGE = "void mainImage(out vec4 c, in vec2 p) { c = vec4(p / iResolution.xy, 0.25, 1.0); }\n"


def api_export(code=IMAGE, name="Synthetic"):
    return json.dumps({"Shader": {"ver": "0.1", "info": {"id": "tSt123", "name": name, "username": "tester"},
                                  "renderpass": [{"inputs": [], "outputs": [{"id": 37, "channel": 0}],
                                                  "code": code, "name": "Image", "type": "image"}]}})


def test_a_folder_and_its_manifest_file_load_the_same_shadertoy():
    folder = toyhost.load(SOURCE_DIR / "shadertoys/pingpong-probe")
    manifest = toyhost.load(str(SOURCE_DIR / "shadertoys/pingpong-probe/manifest.json"))
    assert folder.name == manifest.name == "pingpong-probe"
    assert folder.passes == manifest.passes == ["Buffer A", "Buffer B", "Image"]
    assert folder.path == manifest.path == SOURCE_DIR / "shadertoys/pingpong-probe/manifest.json"
    assert not folder.has_sound


def test_an_export_file_and_its_text_load(tmp_path):
    file = tmp_path / "toy.json"
    file.write_text(api_export())
    from_file = toyhost.load(file)
    from_text = toyhost.load(api_export(), name="inline.json", folder=tmp_path)
    assert from_file.name == from_text.name == "Synthetic (tSt123 by tester)"
    assert from_file.passes == from_text.passes == ["Image"]
    assert from_text.path == tmp_path / "inline.json"
    # Leading white space is still JSON text, not a path.
    assert toyhost.load("\n  " + api_export()).passes == ["Image"]


def test_a_missing_path_raises_an_input_error_naming_it(tmp_path):
    missing = tmp_path / "nothing-here"
    with pytest.raises(toyhost.InputError) as raised:
        toyhost.load(missing)
    assert raised.value.code == "io.not-found"
    assert raised.value.file == str(missing)
    assert str(missing) in str(raised.value)


def test_every_manifest_problem_is_reported_with_its_field(tmp_path):
    folder = write_shadertoy(tmp_path / "bad", {"Image": IMAGE})
    (folder / "manifest.json").write_text(json.dumps({"passes": {
        "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "E"}}},
        "Buffer Q": {"source": "image.glsl"}}}))
    with pytest.raises(toyhost.ManifestError) as raised:
        toyhost.load(folder)
    error = raised.value
    assert isinstance(error, toyhost.InputError) and isinstance(error, toyhost.Error)
    assert len(error.diagnostics) >= 2, "every problem at once"
    assert all(d.file.endswith("manifest.json") for d in error.diagnostics)
    codes = {d.code for d in error.diagnostics}
    assert "manifest.unknown-pass" in codes, codes
    fields = " ".join(d.field for d in error.diagnostics)
    assert "iChannel0" in fields, fields
    assert error.code == error.diagnostics[0].code and error.file == error.diagnostics[0].file


def test_a_broken_export_text_raises_a_manifest_error():
    with pytest.raises(toyhost.ManifestError) as raised:
        toyhost.load('{"Shader": {"renderpass": 3}}', name="pasted.json")
    assert raised.value.code.startswith("export."), raised.value.code
    assert "pasted.json" in raised.value.file


def test_the_version_is_the_librarys():
    parts = toyhost.__version__.split(".")
    assert len(parts) == 3 and all(p.isdigit() for p in parts), toyhost.__version__
