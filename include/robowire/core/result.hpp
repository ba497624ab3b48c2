// robowire/core/result.hpp - error codes and result<T>: no exceptions, no heap.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>  // std::construct_at
#include <string_view>
#include <type_traits>
#include <utility>  // std::in_place_t, std::move

namespace robowire {

// What went wrong. `error::offset` says where (byte index into the input).
enum class errc : std::uint8_t {
    ok = 0,
    too_short,           // input ends before the message does
    too_long,            // more bytes than the message can have
    bad_length,          // a length no form of the message has (e.g. a truncated optional block)
    bad_header,          // a fixed start / header byte is wrong
    bad_trailer,         // a fixed end byte is wrong
    bad_command,         // command byte does not belong to this message
    bad_device,          // device byte does not belong to this message (OSP)
    unknown_message,     // no message of this protocol has that command
    value_out_of_range,  // field value outside its valid range
    invalid_enum,        // field value is not one of the enumerated codes
    bad_padding,         // a byte after a text terminator is not zero
    reserved_not_zero,   // a reserved byte is not zero (strict modes only)
    missing_field,       // an optional block is present but an earlier one is not
    buffer_too_small,    // caller's output buffer cannot hold the result
    capacity_exceeded,   // a fixed-capacity container is full
    bad_sequence,        // multi-frame: frame out of order
    command_changed,     // multi-frame: continuation frame with another command
};

// Short, stable, lower-case description of an error code.
constexpr std::string_view to_string(errc e) noexcept {
    switch (e) {
    case errc::ok: return "ok";
    case errc::too_short: return "input too short";
    case errc::too_long: return "input too long";
    case errc::bad_length: return "length matches no form of the message";
    case errc::bad_header: return "bad header byte";
    case errc::bad_trailer: return "bad trailer byte";
    case errc::bad_command: return "wrong command byte for this message";
    case errc::bad_device: return "wrong device byte for this message";
    case errc::unknown_message: return "unknown message";
    case errc::value_out_of_range: return "value out of range";
    case errc::invalid_enum: return "value is not a valid code";
    case errc::bad_padding: return "non-zero byte after text terminator";
    case errc::reserved_not_zero: return "reserved byte is not zero";
    case errc::missing_field: return "optional block present without the one before it";
    case errc::buffer_too_small: return "output buffer too small";
    case errc::capacity_exceeded: return "capacity exceeded";
    case errc::bad_sequence: return "frame out of sequence";
    case errc::command_changed: return "command changed inside a multi-frame message";
    }
    return "unknown error";
}

// An error code and the byte offset it refers to.
struct error {
    errc code = errc::ok;
    std::size_t offset = 0;
    friend constexpr bool operator==(const error&, const error&) = default;
};

namespace detail {
// Called when a result is accessed in the wrong state. Not constexpr: such an
// access inside a constant expression is a compile error; at run time it traps.
[[noreturn]] inline void bad_result_access() noexcept { __builtin_trap(); }
// Does nothing; not constexpr, so that compilers do not fold an in-place
// result into a constant that they then write out as a block clear.
inline void run_time_only() noexcept {}
}  // namespace detail

// Either a T or an error; they share storage. T must be trivially copyable
// and trivially destructible (every value type of this library is).
template <class T>
class [[nodiscard]] result {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "result<T>: T must be trivially copyable and trivially destructible");

public:
    using value_type = T;

    constexpr result(const T& val) noexcept : value_(val), ok_(true) {}
    constexpr result(robowire::error e) noexcept : error_(e), ok_(false) {}
    // A value-holding result whose value is default-initialised (member
    // initialisers run; nothing is cleared first): for codecs that then
    // write every member.
    constexpr explicit result(std::in_place_t) noexcept(std::is_nothrow_default_constructible_v<T>)
        : value_(std::in_place), ok_(true) {}
    // Turns this result into an error.
    constexpr result& operator=(robowire::error e) noexcept {
        std::construct_at(&error_, e);  // makes the error the active member
        ok_ = false;
        return *this;
    }

    constexpr bool has_value() const noexcept { return ok_; }
    constexpr explicit operator bool() const noexcept { return ok_; }

    constexpr T& value() & noexcept { check(true); return value_.v; }
    constexpr const T& value() const& noexcept { check(true); return value_.v; }
    // From a temporary: the value itself, so `for (auto& x : make().value())` does not dangle.
    constexpr T value() && noexcept { check(true); return value_.v; }
    constexpr T& operator*() & noexcept { return value(); }
    constexpr const T& operator*() const& noexcept { return value(); }
    constexpr T operator*() && noexcept { return std::move(*this).value(); }
    constexpr T* operator->() noexcept { return &value(); }
    constexpr const T* operator->() const noexcept { return &value(); }

    // The error; only valid when !has_value().
    constexpr robowire::error error() const noexcept { check(false); return error_; }
    constexpr errc code() const noexcept { return ok_ ? errc::ok : error_.code; }

    template <class U>
    constexpr T value_or(U&& fallback) const& { return ok_ ? value_.v : static_cast<T>(std::forward<U>(fallback)); }

private:
    constexpr void check(bool want_value) const noexcept {
        if (ok_ != want_value) detail::bad_result_access();
    }
    struct holder {  // default-initialises its value (value-initialising would clear it first)
        T v;
        constexpr explicit holder(std::in_place_t) noexcept(std::is_nothrow_default_constructible_v<T>) {
            if (!std::is_constant_evaluated()) detail::run_time_only();
        }
        constexpr holder(const T& val) noexcept : v(val) {}
    };
    union {
        holder value_;
        robowire::error error_;
    };
    bool ok_;
};

// Shorthand for returning an error.
constexpr error fail(errc code, std::size_t offset) noexcept { return error{code, offset}; }

}  // namespace robowire
