#pragma once
/// Result<T>: a value or an Error. Expected failures travel as values; nothing throws across a stage.

#include "hs/core/Error.h"

#include <cassert>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

namespace hs {

/// Tag for `return fail(...)`: converts to any Result<T>.
struct Failure {
    Error error;
};

inline Failure fail(ErrorCode code, std::string detail) {
    return Failure{Error{code, std::move(detail)}};
}
inline Failure fail(Error error) {
    return Failure{std::move(error)};
}

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Result(Failure failure) : m_state(std::in_place_index<1>, std::move(failure.error)) {}
    Result(Error error) : m_state(std::in_place_index<1>, std::move(error)) {}

    bool ok() const noexcept { return m_state.index() == 0; }
    explicit operator bool() const noexcept { return ok(); }

    T& value() & {
        assert(ok());
        return std::get<0>(m_state);
    }
    const T& value() const& {
        assert(ok());
        return std::get<0>(m_state);
    }
    T&& value() && {
        assert(ok());
        return std::get<0>(std::move(m_state));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const {
        assert(!ok());
        return std::get<1>(m_state);
    }
    /// Converts the error of this result into a Failure for another Result type.
    Failure failure() const { return Failure{error()}; }

private:
    std::variant<T, Error> m_state;
};

/// Result without a value: success or an Error.
template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Failure failure) : m_error(std::move(failure.error)) {}
    Result(Error error) : m_error(std::move(error)) {}

    bool ok() const noexcept { return !m_error.has_value(); }
    explicit operator bool() const noexcept { return ok(); }
    const Error& error() const {
        assert(!ok());
        return *m_error;
    }
    Failure failure() const { return Failure{error()}; }

private:
    std::optional<Error> m_error;
};

using Status = Result<void>;

} // namespace hs

/// Propagates the failure of a Result-returning expression: `HS_TRY(writeFile(...));`
#define HS_TRY(expr)                                                                                                   \
    do {                                                                                                               \
        auto&& hsTryResult_ = (expr);                                                                                  \
        if (!hsTryResult_.ok())                                                                                        \
            return hsTryResult_.failure();                                                                             \
    } while (false)
