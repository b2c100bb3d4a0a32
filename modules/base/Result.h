// Error values that cross module lines instead of exceptions.
// An Error names what went wrong and, where it comes from a file, the file, line and column.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace camwb::base {

struct Error {
    std::string message;
    std::string file;  // empty when the error is not about a file
    int line = 0;      // 1-based, 0 = unknown
    int column = 0;    // 1-based, 0 = unknown

    // "file:line:column: message", leaving out the parts that are unknown.
    std::string toString() const;
};

// Either a value or an Error. Deliberately small: check ok(), then value() or error().
template <class T> class Result {
public:
    Result(T value) : m_value(std::move(value)) {}
    Result(Error error) : m_error(std::move(error)) {}

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    const T& value() const& { return *m_value; }
    T& value() & { return *m_value; }
    T&& value() && { return std::move(*m_value); }
    const T* operator->() const { return &*m_value; }
    T* operator->() { return &*m_value; }
    const Error& error() const { return m_error; }

private:
    std::optional<T> m_value;
    Error m_error;
};

// Success or an Error, for operations without a value.
class Status {
public:
    Status() = default;
    Status(Error error) : m_error(std::move(error)), m_failed(true) {}
    static Status success() { return {}; }

    bool ok() const { return !m_failed; }
    explicit operator bool() const { return ok(); }
    const Error& error() const { return m_error; }

private:
    Error m_error;
    bool m_failed = false;
};

inline Error makeError(std::string message, std::string file = {}, int line = 0, int column = 0)
{
    return Error{std::move(message), std::move(file), line, column};
}

}  // namespace camwb::base
