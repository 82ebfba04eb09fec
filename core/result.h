#pragma once
/// Failure as a value: every solver and validator in core/ returns either a result or a
/// Failure that names the culprit, so the GUI can show it and the CLI can print it.
/// Nothing in core/ ever hands a NaN to a caller in place of an error.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace pkm {

enum class FailureKind {
    InvalidParameter, ///< a design parameter is outside its domain (a ≤ 0, θ range inverted…)
    UnknownName,      ///< no parameter or variable of that name
    OutOfRange,       ///< a joint variable outside the design's limits
    Unreachable,      ///< the geometry cannot close for the requested value
    Singular,         ///< the requested pose is singular and the quantity is undefined
};

struct Failure {
    FailureKind kind = FailureKind::InvalidParameter;
    std::string culprit; ///< the parameter or variable name the message is about
    std::string message; ///< one sentence naming the culprit and the allowed values (text::translate)
};

template <class T>
class Result
{
public:
    Result(T value) : m_data(std::move(value)) {}
    Result(Failure failure) : m_data(std::move(failure)) {}

    bool ok() const { return std::holds_alternative<T>(m_data); }
    explicit operator bool() const { return ok(); }

    const T &value() const
    {
        assert(ok());
        return std::get<T>(m_data);
    }
    T &value()
    {
        assert(ok());
        return std::get<T>(m_data);
    }
    const T &operator*() const { return value(); }
    const T *operator->() const { return &value(); }
    T &operator*() { return value(); }
    T *operator->() { return &value(); }

    const Failure &failure() const
    {
        assert(!ok());
        return std::get<Failure>(m_data);
    }

private:
    std::variant<T, Failure> m_data;
};

} // namespace pkm
