// Result<T>: a value or an Error with a human message. Library code returns these instead of
// printing or exiting; the CLI decides what to print. No GL needed.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace toyhost {

struct Error {
    std::string message;
};

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

// Prefixes an error with context ("Buffer A: " + inner message).
inline Error withContext(const std::string& context, const Error& inner) {
    return Error{context + ": " + inner.message};
}

}  // namespace toyhost
