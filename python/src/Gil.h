// withoutGil(work): runs `work` with the GIL released and takes it back afterwards, in plain code
// rather than in a destructor: when the interpreter is finalizing, taking the GIL back ends a
// daemon thread by pthread_exit (a forced unwind), which pybind11 lets through but a noexcept
// destructor (py::gil_scoped_release's) turns into std::terminate. No GL needed.
#pragma once

#include <Python.h>

#include <exception>
#include <optional>
#include <type_traits>
#include <utility>

namespace toyhost::python {

template <class Work>
auto withoutGil(Work&& work) -> std::invoke_result_t<Work&> {
    using Value = std::invoke_result_t<Work&>;
    std::exception_ptr failure;
    PyThreadState* state = PyEval_SaveThread();
    if constexpr (std::is_void_v<Value>) {
        try {
            work();
        } catch (...) {
            failure = std::current_exception();
        }
        PyEval_RestoreThread(state);  // may end this thread while the interpreter finalizes
        if (failure) std::rethrow_exception(failure);
    } else {
        std::optional<Value> value;
        try {
            value.emplace(work());
        } catch (...) {
            failure = std::current_exception();
        }
        PyEval_RestoreThread(state);
        if (failure) std::rethrow_exception(failure);
        return std::move(*value);
    }
}

}  // namespace toyhost::python
