// The native module `toyhost._toyhost`: toyhost's public C++ API (include/toyhost/) as Python
// sees it: diagnostics, input events, loading a shadertoy, the version, shard spans, the session
// (SessionBinding) and comparisons (CompareBinding). The Pythonic layer on top is
// toyhost/__init__.py. No GL here.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <string>

#include <toyhost/Defaults.h>
#include <toyhost/Diagnostic.h>
#include <toyhost/Input.h>
#include <toyhost/Shadertoy.h>
#include <toyhost/Shards.h>
#include <toyhost/Version.h>

#include "CompareBinding.h"
#include "Errors.h"
#include "Gil.h"
#include "SessionBinding.h"

namespace py = pybind11;
using namespace toyhost;
using toyhost::python::valueOrThrow;

namespace {

// A coordinate as Python would write it (12.0 -> "12", 12.5 -> "12.5").
std::string number(float value) {
    std::string text = py::str(py::float_(value));
    if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0) text.resize(text.size() - 2);
    return text;
}

void bindDiagnostic(py::module_& m) {
    py::class_<Diagnostic>(m, "Diagnostic", "One problem or notice: what, where, and a stable code.")
        .def_property_readonly("severity", [](const Diagnostic& d) { return std::string(severityName(d.severity)); })
        .def_property_readonly("code", [](const Diagnostic& d) { return std::string(codeName(d.code)); })
        .def_property_readonly("category",
                               [](const Diagnostic& d) { return std::string(categoryName(categoryOf(d.code))); })
        .def_readonly("message", &Diagnostic::message)
        .def_readonly("file", &Diagnostic::file)
        .def_readonly("pass_", &Diagnostic::pass)
        .def_property_readonly("channel",
                               [](const Diagnostic& d) { return d.channel < 0 ? py::none() : py::cast(d.channel); })
        .def_readonly("field", &Diagnostic::field)
        .def_readonly("line", &Diagnostic::line)
        .def_readonly("column", &Diagnostic::column)
        .def_readonly("excerpt", &Diagnostic::excerpt)
        .def("__str__", [](const Diagnostic& d) { return formatDiagnostic(d); })
        .def("__repr__", [](const Diagnostic& d) { return "<toyhost.Diagnostic " + formatDiagnostic(d) + ">"; });
}

void bindInputEvent(py::module_& m) {
    py::class_<InputEvent> event(m, "InputEvent",
                                 "One thing the user did: mouse in canvas pixels (origin bottom-left) or a key "
                                 "as a JavaScript keyCode.");
    py::enum_<InputEvent::Type>(event, "Type")
        .value("MOUSE_DOWN", InputEvent::Type::MouseDown)
        .value("MOUSE_MOVE", InputEvent::Type::MouseMove)
        .value("MOUSE_UP", InputEvent::Type::MouseUp)
        .value("KEY_DOWN", InputEvent::Type::KeyDown)
        .value("KEY_UP", InputEvent::Type::KeyUp);
    event.def_readonly("type", &InputEvent::type)
        .def_readonly("x", &InputEvent::x)
        .def_readonly("y", &InputEvent::y)
        .def_readonly("key", &InputEvent::key)
        .def_static("mouse_down", &InputEvent::mouseDown, py::arg("x"), py::arg("y"))
        .def_static("mouse_move", &InputEvent::mouseMove, py::arg("x"), py::arg("y"))
        .def_static("mouse_up", &InputEvent::mouseUp)
        .def_static("key_down", &InputEvent::keyDown, py::arg("key"))
        .def_static("key_up", &InputEvent::keyUp, py::arg("key"))
        .def("__repr__", [](const InputEvent& e) {
            switch (e.type) {
            case InputEvent::Type::MouseDown: return "InputEvent.mouse_down(" + number(e.x) + ", " + number(e.y) + ")";
            case InputEvent::Type::MouseMove: return "InputEvent.mouse_move(" + number(e.x) + ", " + number(e.y) + ")";
            case InputEvent::Type::MouseUp: return std::string("InputEvent.mouse_up()");
            case InputEvent::Type::KeyDown: return "InputEvent.key_down(" + std::to_string(e.key) + ")";
            case InputEvent::Type::KeyUp: return "InputEvent.key_up(" + std::to_string(e.key) + ")";
            }
            return std::string("InputEvent(?)");
        });
}

void bindShadertoy(py::module_& m) {
    // dynamic_attr: from_code keeps the arrays given as channels on the object (_arrays), for the
    // sessions made from it.
    py::class_<Shadertoy>(m, "Shadertoy", "A shadertoy, loaded and validated (toyhost.load).", py::dynamic_attr())
        .def_property_readonly("name", &Shadertoy::name)
        .def_property_readonly("path", &Shadertoy::path)
        .def_property_readonly("passes", &Shadertoy::passes)
        .def_property_readonly("has_sound", &Shadertoy::hasSound)
        .def_property_readonly("notices", &Shadertoy::notices)
        .def("__repr__", [](const Shadertoy& s) { return "<toyhost.Shadertoy '" + s.name() + "'>"; });
    // Loading reads files and checks text, no GL: done on the calling thread without the GIL.
    m.def(
        "load_path",
        [](const std::filesystem::path& path) {
            return valueOrThrow(toyhost::python::withoutGil([&] { return Shadertoy::load(path); }));
        },
        py::arg("path"));
    m.def(
        "load_export_json",
        [](const std::string& json, const std::string& name, const std::filesystem::path& folder) {
            return valueOrThrow(
                toyhost::python::withoutGil([&] { return Shadertoy::fromExportJson(json, name, folder); }));
        },
        py::arg("json"), py::arg("name"), py::arg("folder"));
}

}  // namespace

PYBIND11_MODULE(_toyhost, m) {
    m.doc() = "toyhost's native API (use the `toyhost` package)";
    toyhost::python::registerErrorTranslator();
    bindDiagnostic(m);
    bindInputEvent(m);
    bindShadertoy(m);
    toyhost::python::bindSession(m);
    toyhost::python::bindCompare(m);
    m.def("version_string", [] { return std::string(versionString()); });
    // toyhost.farm.shard_spans' arithmetic: the split of `toyhost run --shard i/n` (toyhost/Shards.h).
    m.def(
        "shard_span",
        [](int frames, int shards, int index) {
            const FrameSpan span = valueOrThrow(shardSpan(frames, shards, index));
            return py::make_tuple(span.first, span.end);
        },
        py::arg("frames"), py::arg("shards"), py::arg("index"));
    // The defaults a session uses for what the caller leaves out (toyhost::runDefaults), by the keys
    // of toyhost/Defaults.h's list; a new dict at every call so that a caller changing it changes
    // nothing else.
    m.def("defaults", [] {
        const Defaults d = runDefaults();
        py::dict out;
#define TOYHOST_DEFAULT_TO_PYTHON(Type, member, key, value, what) out[key] = d.member;
        TOYHOST_DEFAULTS(TOYHOST_DEFAULT_TO_PYTHON)
#undef TOYHOST_DEFAULT_TO_PYTHON
        return out;
    });
}
