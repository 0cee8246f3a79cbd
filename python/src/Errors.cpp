// The translator from ToyhostError to a Python exception: the classes and the choice among them
// live in toyhost/_errors.py, so that Python code can subclass, catch and document them.
#include "Errors.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace toyhost::python {

void registerErrorTranslator() {
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const ToyhostError& e) {
            const Error& error = e.error();
            py::object errors = py::module_::import("toyhost._errors");
            py::object exception = errors.attr("from_diagnostics")(
                std::string(categoryName(error.category())), error.text(), py::cast(error.diagnostics));
            PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(exception.ptr())), exception.ptr());
        }
    });
}

}  // namespace toyhost::python
