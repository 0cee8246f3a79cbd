// toyhost errors on their way to Python: a C++ exception holding toyhost's Error (its
// diagnostics), which the module's translator turns into the matching toyhost.Error subclass
// (toyhost/_errors.py) with the diagnostics as attributes. No GL needed.
#pragma once

#include <exception>
#include <utility>

#include <toyhost/Result.h>

namespace toyhost::python {

class ToyhostError : public std::exception {
public:
    explicit ToyhostError(Error error) : error_(std::move(error)) {}
    const Error& error() const { return error_; }
    const char* what() const noexcept override { return "toyhost error"; }

private:
    Error error_;
};

// The value, or a ToyhostError with the diagnostics.
template <class T>
T valueOrThrow(Result<T> result) {
    if (!result) throw ToyhostError(result.error());
    return std::move(result).value();
}

inline void throwIfFailed(const Status& status) {
    if (!status) throw ToyhostError(status.error());
}

// Registers the translator (ToyhostError -> toyhost.Error subclass). Call once, from the module's
// initialisation, with the GIL held.
void registerErrorTranslator();

}  // namespace toyhost::python
