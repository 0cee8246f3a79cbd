// toyhost/Result.h (public API, stable): Result<T>, a value or an Error (a list of Diagnostics).
// toyhost's functions return these instead of printing, throwing or exiting; the caller decides.
// No GL needed.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <toyhost/Diagnostic.h>

namespace toyhost {

struct Error {
    std::vector<Diagnostic> diagnostics;  // at least one

    // A problem with no particular place; `code` says what kind it is.
    explicit Error(std::string message, Code code = Code::Unclassified) {
        Diagnostic d;
        d.code = code;
        d.message = std::move(message);
        diagnostics.push_back(std::move(d));
    }
    Error(Diagnostic diagnostic) { diagnostics.push_back(std::move(diagnostic)); }
    explicit Error(std::vector<Diagnostic> all) : diagnostics(std::move(all)) {}

    // Every diagnostic, one formatted line each (no prefix), source excerpts below their line.
    std::string text() const { return formatDiagnostics(diagnostics); }
    const Diagnostic& first() const { return diagnostics.front(); }
    // The category of the first diagnostic, which decides what happens next (exit codes).
    Category category() const { return categoryOf(first().code); }
};

// A problem with one file (its path as the user named it).
inline Error fileError(const std::string& file, std::string message, Code code) {
    Diagnostic d;
    d.code = code;
    d.file = file;
    d.message = std::move(message);
    return Error(std::move(d));
}

// An Error about a file: `file` is set on every diagnostic that names no file yet.
inline Error inFile(const std::string& file, Error error) {
    for (Diagnostic& d : error.diagnostics)
        if (d.file.empty()) d.file = file;
    return error;
}

// An Error about a pass (and optionally one of its channels), set where not set yet.
inline Error inPass(const std::string& pass, Error error, int channel = -1) {
    for (Diagnostic& d : error.diagnostics)
        if (d.pass.empty()) {
            d.pass = pass;
            if (d.channel < 0) d.channel = channel;
        }
    return error;
}

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : state_(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : state_(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return state_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(state_); }
    const T& value() const& { return std::get<0>(state_); }
    T&& value() && { return std::get<0>(std::move(state_)); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    const Error& error() const { return std::get<1>(state_); }

private:
    std::variant<T, Error> state_;
};

// For operations that produce nothing but can fail.
using Status = Result<std::monostate>;
inline Status okStatus() { return Status(std::monostate{}); }

}  // namespace toyhost
