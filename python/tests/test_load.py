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


def test_a_lone_glsl_file_loads_as_an_image_only_shadertoy_and_renders_the_cli_frame(tmp_path):
    from support import DATE, read_png, run_cli
    file = tmp_path / "wave.glsl"
    file.write_text(IMAGE)
    toy = toyhost.load(file)
    assert toy.passes == ["Image"] and toy.name == "wave"
    with toyhost.Session(toy, size=(16, 8), date=DATE) as session:
        [(_, frame)] = list(session.render(1))
    code, output = run_cli("run", str(file), "--size", "16x8", "--frames", "1", "--date", DATE, "--out",
                           str(tmp_path / "f.png"), "--quiet")
    assert code == 0, output
    assert (frame == read_png(tmp_path / "f.png")).all()


def test_defines_switch_an_ifdef_and_bad_names_are_usage_errors(tmp_path):
    file = tmp_path / "toy.glsl"
    file.write_text("void mainImage(out vec4 c, in vec2 p) {\n#ifdef RED\n c = vec4(1, 0, 0, 1);\n#else\n"
                    " c = vec4(0, 0, 1, 1);\n#endif\n#ifdef LEVEL\n c.g = LEVEL;\n#endif\n}\n")

    def pixel(defines):
        with toyhost.Session(file, size=(4, 4), defines=defines) as session:
            [(_, frame)] = list(session.render(1))
            return [int(v) for v in frame[0, 0, :3]]

    assert pixel(()) == [0, 0, 255]
    assert pixel(["RED"]) == pixel({"RED": True}) == pixel("RED") == [255, 0, 0]
    assert pixel({"LEVEL": 0.2}) == pixel(["LEVEL=0.2"]) == [0, 51, 255]
    with pytest.raises(toyhost.UsageError) as raised:
        toyhost.Session(file, size=(4, 4), defines=["9LIVES"])
    assert raised.value.field == "defines"
    assert "'9LIVES' is not a macro name" in str(raised.value)


FEEDBACK_A = ("void mainImage(out vec4 c, in vec2 p) {\n"
              "    vec4 last = texelFetch(iChannel0, ivec2(p), 0);\n"
              "    c = vec4(fract(last.rgb + vec3(0.1, 0.05, 0.02) * shade(p)), 1.0);\n}\n")
FEEDBACK_IMAGE = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }\n"
FEEDBACK_COMMON = "float shade(vec2 p) { return 1.0 + p.x / 16.0; }\n"


def frames_of(toy, count=3):
    from support import DATE
    with toyhost.Session(toy, size=(16, 8), fps=30, date=DATE) as session:
        return [frame.tobytes() for _, frame in session.render(count)]


def test_from_code_load_dict_and_the_folder_give_the_same_frames(tmp_path):
    folder = tmp_path / "toy"
    write_shadertoy(folder, {
        "Buffer A": (FEEDBACK_A, {"iChannel0": {"buffer": "A", "filter": "nearest"}}),
        "Image": (FEEDBACK_IMAGE, {"iChannel0": {"buffer": "A", "filter": "nearest"}}),
    }, common=FEEDBACK_COMMON)
    coded = toyhost.from_code(image=FEEDBACK_IMAGE, common=FEEDBACK_COMMON, buffers={"A": FEEDBACK_A},
                              channels={"A": {0: {"buffer": "A", "filter": "nearest"}},
                                        "Image": {"iChannel0": {"buffer": "A", "filter": "nearest"}}})
    assert coded.passes == ["Buffer A", "Image"]
    parsed = json.loads(json.dumps(toyhost._code.export_of_code(
        FEEDBACK_IMAGE, common=FEEDBACK_COMMON, buffers={"A": FEEDBACK_A},
        channels={"A": {0: {"buffer": "A", "filter": "nearest"}}, "Image": {0: {"buffer": "A", "filter": "nearest"}}})))
    from_dict = toyhost.load(parsed)
    expected = frames_of(toyhost.load(folder))
    assert frames_of(coded) == expected
    assert frames_of(from_dict) == expected
    assert len(set(expected)) == 3  # the feedback moves: the frames say something


def test_from_code_names_what_is_wrong():
    with pytest.raises(toyhost.UsageError) as raised:
        toyhost.from_code(image=IMAGE, channels={"Image": {0: "E"}})
    assert raised.value.field == "channels" and "'E' is not a buffer" in str(raised.value)
    with pytest.raises(toyhost.UsageError):
        toyhost.from_code(image=IMAGE, channels={"B": {0: "A"}})  # no Buffer B given
    with pytest.raises(toyhost.UsageError):
        toyhost.from_code(image=IMAGE, channels={"Image": {4: "A"}})
    with pytest.raises(toyhost.UsageError):
        toyhost.from_code(image=5)
    with pytest.raises(toyhost.CompileError) as compile_error:
        toyhost.Session(toyhost.from_code(image="void mainImage(out vec4 c, in vec2 p) { c = nope; }\n"),
                        size=(4, 4))
    assert "nope" in str(compile_error.value)
    # The text is named as itself, not glued to the current folder it is not in (issue 45).
    assert compile_error.value.file == "code [Image]", compile_error.value.file
    assert str(compile_error.value).startswith("code [Image]:1:"), str(compile_error.value)
