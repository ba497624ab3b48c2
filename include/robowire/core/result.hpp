// robowire/core/result.hpp - error codes and result<T>: no heap. Accessing
// the wrong state throws robowire::bad_result_access when exceptions are
// enabled; without exceptions it calls ROBOWIRE_BAD_RESULT_ACCESS_HANDLER
// if defined, then traps.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstddef>
#include <cstdint>
#include <cstring>  // std::memmove
#if defined(__cpp_exceptions)
#include <exception>  // std::exception
#endif
#include <new>  // placement new
#include <string_view>
#include <type_traits>
#include <utility>  // std::in_place_t, std::move, std::index_sequence

namespace robowire {

// What went wrong. `error::offset` says where (byte index into the input).
enum class errc : std::uint16_t {
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
    bad_json,            // text is not one complete JSON object (unbalanced braces, open string)
    not_handled,         // device role: a valid message that the handler takes no overload for
};

// One row per error code, in the enum's order: the code, its name as the
// tools, the JSON schema and the Python package spell it, and its text
// (short, stable, lower case). Every list of the codes reads this table.
struct errc_info {
    errc code;
    std::string_view name;
    std::string_view text;
};
inline constexpr errc_info errc_table[] = {
    {errc::ok, "ok", "ok"},
    {errc::too_short, "too_short", "input too short"},
    {errc::too_long, "too_long", "input too long"},
    {errc::bad_length, "bad_length", "length matches no form of the message"},
    {errc::bad_header, "bad_header", "bad header byte"},
    {errc::bad_trailer, "bad_trailer", "bad trailer byte"},
    {errc::bad_command, "bad_command", "wrong command byte for this message"},
    {errc::bad_device, "bad_device", "wrong device byte for this message"},
    {errc::unknown_message, "unknown_message", "unknown message"},
    {errc::value_out_of_range, "value_out_of_range", "value out of range"},
    {errc::invalid_enum, "invalid_enum", "value is not a valid code"},
    {errc::bad_padding, "bad_padding", "non-zero byte after text terminator"},
    {errc::reserved_not_zero, "reserved_not_zero", "reserved byte is not zero"},
    {errc::missing_field, "missing_field", "optional block present without the one before it"},
    {errc::buffer_too_small, "buffer_too_small", "output buffer too small"},
    {errc::capacity_exceeded, "capacity_exceeded", "capacity exceeded"},
    {errc::bad_sequence, "bad_sequence", "frame out of sequence"},
    {errc::command_changed, "command_changed", "command changed inside a multi-frame message"},
    {errc::bad_json, "bad_json", "not one complete JSON object"},
    {errc::not_handled, "not_handled", "message not handled"},
};
// Number of error codes, ok included.
inline constexpr std::size_t errc_count = sizeof errc_table / sizeof errc_table[0];

// Short, stable, lower-case description of an error code ("unknown error"
// for a value that is no code).
constexpr std::string_view to_string(errc e) noexcept {
    const auto i = static_cast<std::size_t>(e);
    return i < errc_count ? errc_table[i].text : "unknown error";
}
// The code's name ("value_out_of_range"; "unknown_error" for a value that is no code).
constexpr std::string_view name_of(errc e) noexcept {
    const auto i = static_cast<std::size_t>(e);
    return i < errc_count ? errc_table[i].name : "unknown_error";
}

// An error code and the byte offset it refers to (0..65535: offsets past that
// read 65535). Four bytes, so that functions return it in a register.
// Converts to true when it is an error (like std::error_code):
// `if (auto e = decode_into(m, bytes)) ...`.
struct alignas(4) error {  // no padding, aligned: built in a register, not through memory
    errc code = errc::ok;
    std::uint16_t offset = 0;
    constexpr explicit operator bool() const noexcept { return code != errc::ok; }
    friend constexpr bool operator==(const error&, const error&) = default;
};

}  // namespace robowire

// Without exceptions, value(), operator* and operator-> of a result holding
// an error (and error() of one holding a value, with errc::ok) call the
// function named by ROBOWIRE_BAD_RESULT_ACCESS_HANDLER (config.hpp), if
// defined, then trap. A macro, not a settable pointer, so that the library
// has no static data.

namespace robowire {

#if defined(__cpp_exceptions)
// Thrown by value(), operator* and operator-> of a result holding an error
// (and by error() of one holding a value: code() is errc::ok). what() names
// the error code and the byte offset; the text lives in the exception (no heap).
class bad_result_access : public std::exception {
public:
    explicit bad_result_access(robowire::error e) noexcept : error_(e) {
        std::size_t n = 0;
        const auto put = [&](std::string_view s) {
            for (char c : s)
                if (n + 1 < sizeof what_) what_[n++] = c;
        };
        if (e.code == errc::ok) {
            put("robowire: error() of a result that holds a value");
        } else {
            put("robowire: value() of a result that holds an error: ");
            put(to_string(e.code));
            put(" at byte ");
            char digits[5] = {};
            std::size_t d = 0;
            std::size_t v = e.offset;
            do {
                digits[d++] = static_cast<char>('0' + v % 10);
                v /= 10;
            } while (v != 0 && d < sizeof digits);
            while (d > 0) put({&digits[--d], 1});
        }
        what_[n] = '\0';
    }
    const char* what() const noexcept override { return what_; }
    robowire::error error() const noexcept { return error_; }
    errc code() const noexcept { return error_.code; }

private:
    robowire::error error_;
    char what_[120] = {};  // longest text: 51 + 48 + 9 + 5 digits
};
#endif

namespace detail {
#if defined(__cpp_exceptions)
inline constexpr bool access_noexcept = false;
#else
inline constexpr bool access_noexcept = true;
#endif

// Not constexpr: a wrong access inside a constant expression (e.g. .value()
// of a constexpr encode given an out-of-range value) stops the compiler at
// the call of this function, whose template argument names the error
// ("result_holds_error<robowire::errc::value_out_of_range>").
template <errc Code>
inline void result_holds_error() noexcept {}
inline void result_holds_value_not_error() noexcept {}
template <std::size_t... I>
constexpr void compile_time_bad_access(errc code, std::index_sequence<I...>) noexcept {
    (void)((code == errc_table[I].code ? (result_holds_error<errc_table[I].code>(), true) : false) || ...);
}
template <int = 0>  // instantiated with the first constant expression that needs it
constexpr void compile_time_bad_access(errc code) noexcept {
    if (code == errc::ok) result_holds_value_not_error();
    else compile_time_bad_access(code, std::make_index_sequence<errc_count>{});
}

// Run-time reaction to a wrong access: throw, or the handler, or trap.
[[noreturn]] inline void bad_result_access(error e) noexcept(access_noexcept) {
#if defined(__cpp_exceptions)
    throw robowire::bad_result_access(e);
#else
#if defined(ROBOWIRE_BAD_RESULT_ACCESS_HANDLER)
    ::ROBOWIRE_BAD_RESULT_ACCESS_HANDLER(e);
#else
    (void)e;
#endif
    __builtin_trap();
#endif
}
// Does nothing; not constexpr, so that compilers do not fold an in-place
// result into a constant that they then write out as a block clear.
inline void run_time_only() noexcept {}
}  // namespace detail

template <class T>
class result;
namespace detail {
// A type whose own state can also mark "no value" (bytes<N>: a size past N):
// result<T> keeps its error inside the value and needs no flag of its own.
// A specialisation provides engaged(v), make_error(e), set_error(v, e), get_error(v).
template <class T>
struct niche {
    static constexpr bool used = false;
};
// Tag of result's value-initialising constructor.
struct value_init_t {
    explicit value_init_t() = default;
};
}  // namespace detail
// Building blocks for protocol headers (docs/extending.md): what the generic
// codec does, for a protocol's own dispatchers and encoders.
namespace codec {
// Tag of the constructors that set nothing: result's (neither value nor error
// yet) and bytes' (bytes and size unset), for codecs that then set everything.
struct unset_t {};
// The value of a result known to hold one (the caller has just built it so):
// no access check (at -Os the check is a call that is not folded away).
template <class T>
constexpr T& unchecked_value(result<T>& r) noexcept;
// The error of a result known to hold one (the caller has just tested it): no access check.
template <class T>
constexpr error unchecked_error(const result<T>& r) noexcept;
}  // namespace codec
namespace detail {
// Makes r hold T(arg), whatever it held, and returns the value.
template <class T, class A>
constexpr T& build_value(result<T>& r, const A& arg) noexcept;
// As build_value, but at run time leaves r's flag as it is: for a codec
// that has stored it already (as true) together with other bytes.
template <class T, class A>
constexpr T& build_value_keep_flag(result<T>& r, const A& arg) noexcept;
// Makes r hold a default-initialised T (member initialisers run), whatever it held.
template <class T>
constexpr T& build_default(result<T>& r) noexcept;
// Makes r hold a T whose members are not initialised (at run time; in a
// constant expression, default-initialised), for a codec that then writes
// every member. T: trivially copyable (an implicit-lifetime type).
template <class T>
constexpr T& build_unset(result<T>& r) noexcept;
}  // namespace detail

// Either a T or an error; they share storage. T must be trivially copyable
// and trivially destructible (every value type of this library is).
template <class T>
class [[nodiscard]] result {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "result<T>: T must be trivially copyable and trivially destructible");
    static constexpr bool in_value_ = detail::niche<T>::used;  // the error lives inside the value

public:
    using value_type = T;

    constexpr result(const T& val) noexcept : value_(val), ok_(true) {}
    constexpr result(robowire::error e) noexcept requires(!in_value_) : error_(e), ok_(false) {}
    constexpr result(robowire::error e) noexcept requires(in_value_) : value_(detail::niche<T>::make_error(e)) {}
    // A value-holding result whose value is default-initialised (member
    // initialisers run; nothing is cleared first): for codecs that then write every member.
    constexpr explicit result(std::in_place_t) noexcept(std::is_nothrow_default_constructible_v<T>)
        : value_(std::in_place), ok_(true) {}
    // The same, value-initialised: cleared in one block, then member initialisers
    // (less code than member by member for a large T, see detail::in_place_result).
    constexpr explicit result(detail::value_init_t) noexcept(std::is_nothrow_default_constructible_v<T>)
        : value_(cleared{}), ok_(true) {}
    // Neither a value nor an error yet: for a codec that makes it one or the
    // other on every path before it is read (no store before the branch).
    constexpr explicit result(codec::unset_t) noexcept {}
    // A value-holding result whose value is T(arg).
    template <class A>
    constexpr result(std::in_place_t, const A& arg) noexcept(std::is_nothrow_constructible_v<T, const A&>)
        : value_(std::in_place, arg), ok_(true) {}
    // Turns this result into an error.
    constexpr result& operator=(robowire::error e) noexcept {
        if constexpr (in_value_) {
            if (ROBOWIRE_CONSTANT_EVALUATED()) *this = result(e);  // every byte set in a constant expression
            else detail::niche<T>::set_error(value_.v, e);
        } else {
            if (ROBOWIRE_CONSTANT_EVALUATED())
                *this = result(e);  // a whole-object copy switches the active member in a constant expression
            else ::new (static_cast<void*>(&error_)) robowire::error(e);  // makes the error the active member
            ok_ = false;
        }
        return *this;
    }

    constexpr bool has_value() const noexcept {
        if constexpr (in_value_) return detail::niche<T>::engaged(value_.v);
        else return ok_;
    }
    constexpr explicit operator bool() const noexcept { return has_value(); }

    // The value. On an error: bad_result_access (exceptions enabled), else
    // ROBOWIRE_BAD_RESULT_ACCESS_HANDLER and a trap; in a constant expression, a compile error.
    constexpr T& value() & noexcept(detail::access_noexcept) {
        check(true);
        return value_.v;
    }
    constexpr const T& value() const& noexcept(detail::access_noexcept) {
        check(true);
        return value_.v;
    }
    // From a temporary: the value itself, so `for (auto& x : make().value())` does not dangle.
    constexpr T value() && noexcept(detail::access_noexcept) {
        check(true);
        return value_.v;
    }
    constexpr T& operator*() & noexcept(detail::access_noexcept) { return value(); }
    constexpr const T& operator*() const& noexcept(detail::access_noexcept) { return value(); }
    constexpr T operator*() && noexcept(detail::access_noexcept) { return std::move(*this).value(); }
    constexpr T* operator->() noexcept(detail::access_noexcept) { return &value(); }
    constexpr const T* operator->() const noexcept(detail::access_noexcept) { return &value(); }

    // The error; only valid when !has_value() (else as value() on an error, with errc::ok).
    constexpr robowire::error error() const noexcept(detail::access_noexcept) {
        check(false);
        return stored_error();
    }
    constexpr errc code() const noexcept { return has_value() ? errc::ok : stored_error().code; }

    template <class U>
    constexpr T value_or(U&& fallback) const& {
        return has_value() ? value_.v : static_cast<T>(std::forward<U>(fallback));
    }

private:
    template <class U>
    friend constexpr U& codec::unchecked_value(result<U>& r) noexcept;
    template <class U, class A>
    friend constexpr U& detail::build_value(result<U>& r, const A& arg) noexcept;
    template <class U, class A>
    friend constexpr U& detail::build_value_keep_flag(result<U>& r, const A& arg) noexcept;
    template <class U>
    friend constexpr U& detail::build_default(result<U>& r) noexcept;
    template <class U>
    friend constexpr U& detail::build_unset(result<U>& r) noexcept;
    template <class U>
    friend constexpr robowire::error codec::unchecked_error(const result<U>& r) noexcept;
    constexpr robowire::error stored_error() const noexcept {
        if constexpr (in_value_) return detail::niche<T>::get_error(value_.v);
        else return error_;
    }
    constexpr void set_ok() noexcept {
        if constexpr (!in_value_) ok_ = true;
    }
    constexpr void check(bool want_value) const noexcept(detail::access_noexcept) {
        const bool ok = has_value();
        if (ok == want_value) return;
        const robowire::error e = ok ? robowire::error{} : stored_error();
        if (ROBOWIRE_CONSTANT_EVALUATED()) detail::compile_time_bad_access(e.code);
        detail::bad_result_access(e);
    }
    struct cleared {};  // tag of holder's value-initialising constructor
    struct holder {     // default-initialises its value (value-initialising would clear it first)
        T v;
        constexpr explicit holder(std::in_place_t) noexcept(std::is_nothrow_default_constructible_v<T>) {
            if (!ROBOWIRE_CONSTANT_EVALUATED()) detail::run_time_only();
        }
        // Value-initialised (cleared, then member initialisers): one block clear.
        constexpr explicit holder(cleared) noexcept(std::is_nothrow_default_constructible_v<T>) : v() {}
        constexpr holder(const T& val) noexcept : v(val) {}
        template <class A>
        constexpr holder(std::in_place_t, const A& arg) noexcept(std::is_nothrow_constructible_v<T, const A&>)
            : v(arg) {}
    };
    union {
        holder value_;
        robowire::error error_;
#if UINTPTR_MAX > 0xFFFFFFFFu
        // On 64-bit hosts a result of 16 bytes or less lives in registers, where
        // GCC merges each new one into the last one's register (a dependency from
        // one decode to the next): at least 17 bytes keep it in memory.
        unsigned char host_size_[in_value_ ? 17 : 16];
#endif
    };
    struct no_flag {
        no_flag() = default;
        constexpr no_flag(bool) noexcept {}
    };
    [[no_unique_address]] std::conditional_t<in_value_, no_flag, bool> ok_;
};

template <class T>
constexpr T& codec::unchecked_value(result<T>& r) noexcept {
    return r.value_.v;
}
template <class T, class A>
constexpr T& detail::build_value(result<T>& r, const A& arg) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) {
        r = result<T>(std::in_place, arg);  // a whole-object copy switches the active member
    } else {
        ::new (static_cast<void*>(&r.value_)) typename result<T>::holder(std::in_place, arg);
        r.set_ok();
    }
    return r.value_.v;
}
template <class T, class A>
constexpr T& detail::build_value_keep_flag(result<T>& r, const A& arg) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) return build_value(r, arg);
    ::new (static_cast<void*>(&r.value_)) typename result<T>::holder(std::in_place, arg);
    return r.value_.v;
}
template <class T>
constexpr T& detail::build_default(result<T>& r) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) {
        r = result<T>(std::in_place);  // a whole-object copy switches the active member
    } else {
        ::new (static_cast<void*>(&r.value_)) typename result<T>::holder(std::in_place);
        r.set_ok();
    }
    return r.value_.v;
}
template <class T>
constexpr T& detail::build_unset(result<T>& r) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) return build_default(r);
    // memmove implicitly creates the (implicit-lifetime) holder in the storage; no store
    std::memmove(static_cast<void*>(&r.value_), static_cast<const void*>(&r.value_), sizeof(r.value_));
    r.set_ok();
    return r.value_.v;
}
template <class T>
constexpr error codec::unchecked_error(const result<T>& r) noexcept {
    return r.stored_error();
}
// Shorthand for returning an error (offsets past 65535 become 65535).
constexpr error fail(errc code, std::size_t offset) noexcept {
    return error{code, static_cast<std::uint16_t>(offset < 0xFFFF ? offset : 0xFFFF)};
}
namespace codec {
// An error at an offset inside a message, which its table keeps below 65536
// (checked when the table is built): no clamp, unlike fail().
constexpr error fail_at(errc code, std::size_t offset) noexcept {
    return error{code, static_cast<std::uint16_t>(offset)};
}

// x itself, as an expression that depends on D: a call taking it is resolved
// when the enclosing template is instantiated, not where it is written, so
// that a header's templates instantiate no codec until a program calls them.
template <class D, class T>
constexpr const T& deferred(const T& x) noexcept {
    return x;
}
// The type T, named so that it depends on D: a template that uses it (a
// result<T>, a std::optional<T>) instantiates it only when it is itself
// instantiated.
template <class T, class D>
using deferred_t = std::conditional_t<true, T, D>;
}  // namespace codec

namespace detail::inline ROBOWIRE_MODE_NAMESPACE {
// A value-holding result for a codec that then writes every member; under
// ROBOWIRE_OPTIMIZE_SIZE a T over 32 bytes is cleared in one block first.
template <class T>
constexpr result<T> in_place_result() noexcept {
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE && sizeof(T) > 32) return result<T>(value_init_t{});
    else return result<T>(std::in_place);
}
}  // namespace detail::inline ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire
