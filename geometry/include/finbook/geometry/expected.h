// A minimal std::expected stand-in (C++23 is not available with GCC 12): either a value or
// a typed error. Numeric code returns these instead of throwing or producing NaN.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace finbook {

template <class E> struct Unexpected {
    E error;
};

template <class E> Unexpected<E> unexpected(E error) { return Unexpected<E>{std::move(error)}; }

template <class T, class E> class Expected {
public:
    Expected(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Expected(Unexpected<E> error) : m_state(std::in_place_index<1>, std::move(error.error)) {}

    bool hasValue() const { return m_state.index() == 0; }
    explicit operator bool() const { return hasValue(); }

    T &value() { return std::get<0>(m_state); }
    const T &value() const { return std::get<0>(m_state); }
    T &operator*() { return value(); }
    const T &operator*() const { return value(); }
    T *operator->() { return &value(); }
    const T *operator->() const { return &value(); }

    const E &error() const { return std::get<1>(m_state); }

private:
    std::variant<T, E> m_state;
};

} // namespace finbook
