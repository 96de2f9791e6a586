#pragma once
// Expected<T>: a value or an Error. Expected failures (I/O, compile errors, missing GL features)
// travel as values; exceptions stay at main() and CLI boundaries.

#include <core/KeyedText.h>

#include <cassert>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace sdfwb {

// A failure with a message that names the thing that failed: "module: what failed: detail".
// Where the message names a request's keys ('n'), `keys` says where, so that each front end can
// word them its own way (KeyedText.h).
struct Error {
    Error() = default;
    explicit Error(std::string text, std::vector<KeyMention> mentions = {})
        : message(std::move(text)), keys(std::move(mentions)) {}
    explicit Error(const char* text) : message(text) {}
    explicit Error(const KeyedText& text) : message(text.text()), keys(text.keys()) {}

    KeyedText keyed() const { return {message, keys}; }

    std::string message;
    std::vector<KeyMention> keys;
};

template <class T> class [[nodiscard]] Expected {
public:
    Expected(T value) : m_storage(std::in_place_index<0>, std::move(value)) {}
    Expected(Error error) : m_storage(std::in_place_index<1>, std::move(error)) {}

    bool hasValue() const { return m_storage.index() == 0; }
    explicit operator bool() const { return hasValue(); }

    T& value() & {
        assert(hasValue());
        return std::get<0>(m_storage);
    }
    const T& value() const& {
        assert(hasValue());
        return std::get<0>(m_storage);
    }
    T&& value() && {
        assert(hasValue());
        return std::get<0>(std::move(m_storage));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const {
        assert(!hasValue());
        return std::get<1>(m_storage);
    }

private:
    std::variant<T, Error> m_storage;
};

// Expected<void>: success or an Error.
template <> class [[nodiscard]] Expected<void> {
public:
    Expected() = default;
    Expected(Error error) : m_error(std::move(error)), m_failed(true) {}

    bool hasValue() const { return !m_failed; }
    explicit operator bool() const { return hasValue(); }
    const Error& error() const {
        assert(m_failed);
        return m_error;
    }

private:
    Error m_error;
    bool m_failed = false;
};

inline Error makeError(std::string message) { return Error(std::move(message)); }
inline Error makeError(const char* message) { return Error(message); }
inline Error makeError(const KeyedText& message) { return Error(message); }

} // namespace sdfwb
