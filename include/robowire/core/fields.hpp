// robowire/core/fields.hpp - field helpers driven by a message's table:
// a checked setter from a wider integer, and the field behind an error's
// byte offset (name, bytes, valid range) for messages and logs.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>  // std::cmp_less, std::cmp_greater, std::index_sequence
#include <variant>

#include "result.hpp"
#include "table.hpp"

namespace robowire {

// What a message's table says about one of its fields.
struct field_info {
    std::string_view message{};   // the table's name, e.g. "maneuver"
    std::string_view name{};      // the field's name, e.g. "pitch"; empty: no field there
    std::size_t offset = 0;       // first byte of the field in the encoding
    std::size_t size = 0;         // bytes it occupies (all elements of an array)
    range valid{0, 0};            // valid raw values, inclusive (scalars; enums: see is_enum)
    bool is_enum = false;         // valid values are the enumeration's codes, not a range
    std::string_view unit{};      // physical unit of the field ("" if none)
    bool raw_is_physical = true;  // raw values (valid) are in `unit` (scale 1, offset 0)
    bool has_range = true;        // valid applies: false for text, byte tails, records and floats
    constexpr explicit operator bool() const noexcept { return !name.empty(); }
};

namespace detail {
template <class M, class F>
constexpr field_info info_of(const F& f) noexcept {
    constexpr bool ranged = F::kind != wire_kind::text && F::kind != wire_kind::tail && F::kind != wire_kind::record &&
                            F::kind != wire_kind::f32le;
    field_info out{};
    out.message = table_v<M>.name;
    out.name = f.name;
    out.offset = f.offset;
    out.size = f.size;
    out.valid = f.valid;
    out.is_enum = F::is_enum;
    out.unit = f.unit.name;
    out.raw_is_physical = f.unit.raw_is_physical;
    out.has_range = ranged;
    return out;
}
}  // namespace detail

// The field of M whose bytes include `offset` (an error's offset points
// into the field it is about). No field there (a fixed or reserved byte,
// or past the end): name is empty and the info is false.
template <described M>
[[nodiscard]] constexpr field_info field_at(std::size_t offset) noexcept {
    field_info out{};
    out.message = table_v<M>.name;
    for_each_field<M>([&](const auto& f) {
        const bool inside = f.size == 0 ? offset == f.offset : offset >= f.offset && offset < f.end();
        if (out.name.empty() && inside) out = detail::info_of<M>(f);
    });
    return out;
}
template <described M>
[[nodiscard]] constexpr field_info field_at(const error& e) noexcept {
    return field_at<M>(e.offset);
}

namespace detail {
template <class P>
struct member_pointer_traits;
template <class M, class T>
struct member_pointer_traits<T M::*> {
    using message = M;
    using member = T;
};
}  // namespace detail

// The field of its message's table that stores member `Member`, e.g.
// field_of<&navbot::maneuver::pitch>() (name "pitch", valid -100..100).
template <auto Member>
[[nodiscard]] constexpr field_info field_of() noexcept {
    using M = typename detail::member_pointer_traits<decltype(Member)>::message;
    field_info out{};
    out.message = table_v<M>.name;
    for_each_field<M>([&](const auto& f) {
        if constexpr (std::is_same_v<decltype(f.member), decltype(Member)>)
            if (out.name.empty() && f.member == Member) out = detail::info_of<M>(f);
    });
    return out;
}

// Sets message member `Member` from any integer after checking it against
// the field's valid range in M's table (enums: against the enumeration's
// codes). Out of range: value_out_of_range (enums: invalid_enum) at the
// field's offset, and the message is not changed; field_at<M>(e) names the
// field and its range.
//
//   int speed = 200;
//   if (auto e = robowire::set_field<&navbot::maneuver::pitch>(m, speed)) ...  // -100..100: refused
//
// Scalar and enum members only (not arrays, text or optional blocks).
template <auto Member, class M, class V>
requires std::is_integral_v<V> &&(!std::is_same_v<V, bool>) [[nodiscard]] constexpr error
    set_field(M& m, V value) noexcept {
    using traits = detail::member_pointer_traits<decltype(Member)>;
    using T = typename traits::member;
    static_assert(std::is_same_v<typename traits::message, M>, "set_field: the member belongs to another message");
    static_assert(
        std::is_integral_v<T> || std::is_enum_v<T>,
        "set_field: scalar or enum members only (an array element: check field_of<&M::member>().valid and assign it)");
    error out{errc::unknown_message, 0};  // member not in the table (cannot happen for a described member)
    if constexpr (std::is_integral_v<T> || std::is_enum_v<T>) {  // else only the assertion above is reported
        bool found = false;
        for_each_field<M>([&](const auto& f) {
            if constexpr (std::is_same_v<decltype(f.member), decltype(Member)>) {
                if (found || f.member != Member) return;
                found = true;
                if constexpr (std::is_enum_v<T>) {
                    using U = std::underlying_type_t<T>;
                    if (std::cmp_less(value, std::numeric_limits<U>::min()) ||
                        std::cmp_greater(value, std::numeric_limits<U>::max()) ||
                        !is_valid_enum(static_cast<T>(static_cast<U>(value)))) {
                        out = fail(errc::invalid_enum, f.offset);
                        return;
                    }
                    m.*Member = static_cast<T>(static_cast<U>(value));
                } else {
                    if (std::cmp_less(value, f.valid.min) || std::cmp_greater(value, f.valid.max) ||
                        !std::in_range<T>(value)) {
                        out = fail(errc::value_out_of_range, f.offset);
                        return;
                    }
                    m.*Member = static_cast<T>(value);
                }
                out = error{};
            }
        });
    }
    return out;
}

namespace detail {
// The input lengths M's decoder accepts, as runs [first, last] in increasing
// order (BuWizz3 status: {54, 54}, {68, 129}): every length from min_size()
// to max_input() that does not end inside an optional block.
template <std::size_t N>
struct length_runs {
    std::size_t run[N][2] = {};
    std::size_t count = 0;
};
template <class M>
inline constexpr auto length_runs_v = [] {
    constexpr std::size_t max_runs = [] {  // one more than the optional blocks
        std::size_t k = 1;
        for_each_field<M>([&](const auto& g) { k += std::remove_cvref_t<decltype(g)>::is_optional; });
        return k;
    }();
    length_runs<max_runs> out{};
    for (std::size_t len = table_v<M>.min_size(); len <= table_v<M>.max_input(); ++len) {
        bool ok = true;
        for_each_field<M>([&](const auto& g) {
            if (std::remove_cvref_t<decltype(g)>::is_optional && len > g.offset && len < g.end()) ok = false;
        });
        if (!ok) continue;
        if (out.count > 0 && out.run[out.count - 1][1] + 1 == len) out.run[out.count - 1][1] = len;
        else {
            out.run[out.count][0] = out.run[out.count][1] = len;
            ++out.count;
        }
    }
    return out;
}();
}  // namespace detail

namespace detail {
// Writes text into a caller's buffer, cut to fit (describe_error's lines).
struct line_writer {
    std::span<char> buf;
    std::size_t n = 0;
    constexpr void put(std::string_view s) noexcept {
        for (char c : s)
            if (n < buf.size()) buf[n++] = c;
    }
    constexpr void put_int(std::int64_t v) noexcept {
        if (v < 0) put("-");
        std::uint64_t u = v < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
        char digits[20] = {};
        std::size_t d = 0;
        do {
            digits[d++] = static_cast<char>('0' + u % 10);
            u /= 10;
        } while (u != 0);
        while (d > 0) put({&digits[--d], 1});
    }
    constexpr void put_hex(std::uint8_t b) noexcept {  // "0x3A"
        constexpr char digit[] = "0123456789ABCDEF";
        const char h[4] = {'0', 'x', digit[b >> 4], digit[b & 15]};
        put({h, 4});
    }
    constexpr void put_at(const error& e) noexcept {
        put(" at byte ");
        put_int(static_cast<std::int64_t>(e.offset));
    }
    constexpr std::string_view text() const noexcept { return {buf.data(), n}; }
};
// The lengths M's decoder accepts: "54 or 68..129 bytes", "1 byte".
template <class M>
constexpr void put_lengths(line_writer& w) noexcept {
    constexpr auto& runs = length_runs_v<M>;
    for (std::size_t i = 0; i < runs.count; ++i) {
        if (i > 0) w.put(i + 1 == runs.count ? " or " : ", ");
        w.put_int(static_cast<std::int64_t>(runs.run[i][0]));
        if (runs.run[i][1] != runs.run[i][0]) {
            w.put("..");
            w.put_int(static_cast<std::int64_t>(runs.run[i][1]));
        }
    }
    w.put(runs.count == 1 && runs.run[0][0] == 1 && runs.run[0][1] == 1 ? " byte" : " bytes");
}
}  // namespace detail

// Writes the input lengths M's decoder accepts ("54 or 68..129 bytes",
// "1, 13 or 17 bytes", "1 byte") into `buf`, cut to fit; returns the text:
// the same words describe_error gives for a length error. No heap.
template <described M>
constexpr std::string_view describe_lengths(std::span<char> buf) noexcept {
    detail::line_writer w{buf};
    detail::put_lengths<M>(w);
    return w.text();
}

// Writes "message.field: <error> (valid min..max unit) at byte N" (or
// without the field part when no field is at the offset) into `buf`, cut to
// fit; returns the text written. The range is in raw values: "raw" instead of
// the unit when the unit scales them; none for text, bytes, records, floats. too_short / too_long name no field and
// give the lengths M takes: "status: input too short (54 or 68..129 bytes)
// at byte 4"; bad_length names the optional block cut short and gives them
// too. For logs; no heap.
template <described M>
constexpr std::string_view describe_error(const error& e, std::span<char> buf) noexcept {
    detail::line_writer w{buf};
    const bool length = e.code == errc::too_short || e.code == errc::too_long;  // about the input, not a field
    const field_info f = field_at<M>(e);
    w.put(f.message);
    if (f && !length) {
        w.put(".");
        w.put(f.name);
    }
    w.put(": ");
    w.put(to_string(e.code));
    if (length || e.code == errc::bad_length) {  // the lengths M's decoder accepts, e.g. " (54 or 68..129 bytes)"
        w.put(" (");
        detail::put_lengths<M>(w);
        w.put(")");
    }
    if (f && !f.is_enum && f.has_range && e.code == errc::value_out_of_range) {
        w.put(" (valid ");
        w.put_int(f.valid.min);
        w.put("..");
        w.put_int(f.valid.max);
        if (!f.unit.empty() && f.raw_is_physical) {
            w.put(" ");
            w.put(f.unit);
        } else if (!f.unit.empty()) {
            w.put(" raw");  // e.g. BuWizz3 power: -127..127 raw is -100..100 %
        }
        w.put(")");
    }
    w.put_at(e);
    return w.text();
}

namespace detail {
// The index of the alternative of Variant whose fixed bytes at KeyOffsets...
// are `key`, else of the one with no fixed byte there (it takes every other
// key, as NAVBOT's frame does); variant_size: none.
template <class Variant, std::size_t... KeyOffset>
struct alternative_by_key;
template <class... M, std::size_t... KeyOffset>
struct alternative_by_key<std::variant<M...>, KeyOffset...> {
    template <class T>
    static constexpr std::array<int, sizeof...(KeyOffset)> keys_of() noexcept {
        return {codec::key_of<T>(KeyOffset)...};
    }
    static constexpr std::size_t find(const std::uint8_t (&key)[sizeof...(KeyOffset)]) noexcept {
        constexpr std::array<std::array<int, sizeof...(KeyOffset)>, sizeof...(M)> keys = {keys_of<M>()...};
        std::size_t keyless = sizeof...(M);
        for (std::size_t i = 0; i < sizeof...(M); ++i) {
            bool same = true, none = true;
            for (std::size_t k = 0; k < sizeof...(KeyOffset); ++k) {
                same = same && keys[i][k] == key[k];
                none = none && keys[i][k] < 0;
            }
            if (same) return i;
            if (none) keyless = i;
        }
        return keyless;
    }
};
// describe_error<alternative `index` of Variant>(e, buf); empty for an index past the end.
template <class Variant, std::size_t... I>
constexpr std::string_view describe_alternative(std::size_t index, const error& e, std::span<char> buf,
                                                std::index_sequence<I...>) noexcept {
    std::string_view out{};
    (void)((index == I ? (out = describe_error<std::variant_alternative_t<I, Variant>>(e, buf), true) : false) || ...);
    return out;
}
}  // namespace detail

namespace codec {
// A dispatcher's error (docs/extending.md): the line of the message of
// Variant that the key bytes of `in` (at KeyOffset..., increasing) name;
// "unknown key 0x03 0x01 at byte 2" for a key no message has (another
// error there: "unknown key 0x03 0x01: bad trailer byte at byte 9"); the error
// alone ("input too short at byte 0") when `in` does not reach the key.
template <class Variant, std::size_t... KeyOffset>
constexpr std::string_view describe_keyed_error(const error& e, std::span<const std::uint8_t> in,
                                                std::span<char> buf) noexcept {
    constexpr std::size_t offsets[] = {KeyOffset...};
    detail::line_writer w{buf};
    if (in.size() <= offsets[sizeof offsets / sizeof offsets[0] - 1]) {
        w.put(to_string(e.code));
        w.put_at(e);
        return w.text();
    }
    const std::uint8_t key[] = {in[KeyOffset]...};
    const std::size_t index = detail::alternative_by_key<Variant, KeyOffset...>::find(key);
    if (index < std::variant_size_v<Variant>)
        return detail::describe_alternative<Variant>(index, e, buf,
                                                     std::make_index_sequence<std::variant_size_v<Variant>>{});
    // another error of a frame with an unknown key: "unknown key 0x03 0x01: bad trailer byte at byte 9"
    w.put("unknown key");
    for (const std::uint8_t k : key) {
        w.put(" ");
        w.put_hex(k);
    }
    if (e.code != errc::unknown_message) {
        w.put(": ");
        w.put(to_string(e.code));
    }
    w.put_at(e);
    return w.text();
}
}  // namespace codec

// describe_error for the error of decode_variant<Variant, KeyOffset>(in)
// (also decode_command and decode_notification): the line of the message
// whose key in[KeyOffset] names ("status: input too short (54 or 68..129
// bytes) at byte 4"); "unknown key 0x3A at byte 0" when no message has that
// key; the error alone ("input too short at byte 0") when `in` does not
// reach the key. Pass the input the error came from.
template <class Variant, std::size_t KeyOffset = 0>
requires(std::variant_size_v<Variant> > 0) constexpr std::string_view
    describe_error(const error& e, std::span<const std::uint8_t> in, std::span<char> buf) noexcept {
    return codec::describe_keyed_error<Variant, KeyOffset>(e, in, buf);
}

}  // namespace robowire
