// robowire/core/table.hpp - field tables: the single description of a message.
//
// A message is a plain struct of raw wire values plus one constexpr table,
// found by ADL:   constexpr auto table_of(std::type_identity<Msg>);
// The table lists fixed bytes (command, markers) and fields (name, member,
// offset, wire type, valid range, unit). robowire::encode / decode (encode.hpp,
// decode.hpp) are driven by it, so codec and table cannot disagree; tools read the same table.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "detail/check.hpp"
#include "detail/field_list.hpp"
#include "detail/traits.hpp"
#include "result.hpp"
#include "wire.hpp"

namespace robowire {

// Physical unit: physical = raw * scale + offset. Empty name: no unit.
struct unit {
    std::string_view name{};
    double scale = 1.0;
    double offset = 0.0;
    // Raw values are already in this unit; worked out here, so that describe_error
    // needs no floating point at run time.
    bool raw_is_physical = scale == 1.0 && offset == 0.0;
};

// A byte every instance of a message has (command, marker); `code` is the
// error reported when it differs.
struct fixed_byte {
    std::size_t offset;
    std::uint8_t value;
    errc code;
};

// Enumerations: tables found by ADL, constexpr auto enum_table_of(std::type_identity<E>)
// returning std::array<enum_entry<E>, K>.
template <class E>
struct enum_entry {
    E value;
    std::string_view name;
};
template <class E>
inline constexpr auto enum_table_v = enum_table_of(std::type_identity<E>{});

namespace detail {
// Valid codes as a bit set when every code is below 32 (else 0: use the table).
template <class E>
inline constexpr std::uint32_t enum_code_mask_v = [] {
    std::uint32_t mask = 0;
    for (const auto& entry : enum_table_v<E>) {
        const auto code = static_cast<std::uint64_t>(static_cast<std::underlying_type_t<E>>(entry.value));
        if (code >= 32) return std::uint32_t{0};
        mask |= std::uint32_t{1} << code;
    }
    return mask;
}();

// Codes that form one run lo..hi, without gaps (else found == false).
template <class E>
inline constexpr auto enum_code_run_v = [] {
    struct run {
        bool found;
        std::int64_t lo, hi;
    };
    run r{!enum_table_v<E>.empty(), 0, 0};
    bool first = true;
    for (const auto& entry : enum_table_v<E>) {
        const auto code = static_cast<std::int64_t>(static_cast<std::underlying_type_t<E>>(entry.value));
        if (first || code < r.lo) r.lo = code;
        if (first || code > r.hi) r.hi = code;
        first = false;
    }
    if (r.found && static_cast<std::uint64_t>(r.hi - r.lo) + 1 != enum_table_v<E>.size()) r.found = false;
    return r;  // (codes are distinct: a table entry per code)
}();
}  // namespace detail

template <class E>
[[nodiscard]] constexpr bool is_valid_enum(E e) noexcept {
    if constexpr (detail::enum_code_run_v<E>.found) {  // one range compare, no table in flash
        const auto code = static_cast<std::int64_t>(static_cast<std::underlying_type_t<E>>(e));
        return code >= detail::enum_code_run_v<E>.lo && code <= detail::enum_code_run_v<E>.hi;
    } else if constexpr (detail::enum_code_mask_v<E> != 0) {  // one bit test, no table in flash
        const auto code = static_cast<std::uint64_t>(static_cast<std::underlying_type_t<E>>(e));
        return code < 32 && (detail::enum_code_mask_v<E> >> code & 1) != 0;
    } else {
        for (const auto& entry : enum_table_v<E>)
            if (entry.value == e) return true;
        return false;
    }
}
// Name of an enumerator ("" if not a valid code).
template <class E>
[[nodiscard]] constexpr std::string_view enum_name(E e) noexcept {
    for (const auto& entry : enum_table_v<E>)
        if (entry.value == e) return entry.name;
    return {};
}
template <class E>
[[nodiscard]] constexpr std::optional<E> enum_from_name(std::string_view name) noexcept {
    for (const auto& entry : enum_table_v<E>)
        if (entry.name == name) return entry.value;
    return std::nullopt;
}

// A type with a field table (found by ADL: table_of(std::type_identity<M>)).
template <class M>
concept described = requires {
    table_of(std::type_identity<M>{});
};

namespace detail {
template <class M>
constexpr bool members_match() noexcept {
    constexpr auto t = table_of(std::type_identity<M>{});
    return aggregate_has_members<M, decltype(t)::field_count + t.members_not_on_wire>();
}
}  // namespace detail

// The table of a message or record type, checked once, at compile time.
template <described M>
inline constexpr auto table_v = detail::checked_table(table_of(std::type_identity<M>{}),
                                                      std::bool_constant<detail::members_match<M>()>{});

namespace detail {
// What coding a field depends on besides its offset and range: the member
// type T and the wire type W (shared by fields of different messages).
template <class T, class W>
struct field_shape {
    using member_type = T;
    using wire_type = W;
    using element_type = element_t<T>;
    static_assert(wire_fits<W, element_type>(), "field: member type does not fit the wire type");
    static constexpr wire_kind kind = W::kind;
    static constexpr bool is_optional = optional_traits<T>::value;
    static constexpr bool is_array = array_traits<value_t<T>>::value;
    static constexpr bool is_enum = std::is_enum_v<element_type>;
    static constexpr std::size_t count = array_traits<value_t<T>>::count;
    static constexpr std::size_t element_size = detail::element_size<W, element_type>();
    // Bytes the field occupies (a tail: its capacity).
    static constexpr std::size_t size =
        W::kind == wire_kind::tail ? bytes_traits<element_type>::size : count * element_size;
};
}  // namespace detail

// One field: name, member, byte offset, wire type, valid raw range, unit.
// The member may be a scalar, an enum, bool, text<N>, bytes<N> (tail), a
// record struct, a std::array of those, or a std::optional of any of them
// (an optional block: present when the input is long enough).
template <class M, class T, class W>
struct field : detail::field_shape<T, W> {
    using message_type = M;
    using shape = detail::field_shape<T, W>;
    using typename shape::element_type;

    std::string_view name;
    T M::*member;
    std::size_t offset;
    robowire::range valid = detail::default_range<W, element_type>();
    robowire::unit unit{};

    constexpr field(std::string_view n, T M::*m, std::size_t off, W, robowire::range r, robowire::unit u = {}) noexcept
        : name(n), member(m), offset(off), valid(r), unit(u) {}
    constexpr field(std::string_view n, T M::*m, std::size_t off, W, robowire::unit u = {}) noexcept
        : name(n), member(m), offset(off), unit(u) {}

    constexpr std::size_t end() const noexcept { return offset + shape::size; }
};

// A message (or record) table.
template <class M, std::size_t K, class... F>
struct message_table {
    using message_type = M;
    std::string_view name;
    std::array<fixed_byte, K> fixed;
    detail::field_list<F...> fields;     // fields.get<I>(), fields.each(fn)
    std::size_t declared_max_input = 0;  // longest accepted input; 0: max_size(). Longer is decoded, the rest ignored.
    std::size_t declared_size = 0;  // nonzero: the message is at least this long (reserved bytes after the last field)
    std::size_t members_not_on_wire = 0;  // struct members no field covers (e.g. decode statistics); checked

    static constexpr std::size_t field_count = sizeof...(F);

    // Three sizes: min_size() <= max_size() <= max_input().
    // Longest frame: bytes up to the end of the last field (with every optional block).
    constexpr std::size_t max_size() const noexcept {
        std::size_t e = declared_size;
        for (const auto& b : fixed) e = b.offset + 1 > e ? b.offset + 1 : e;
        fields.apply([&](const auto&... f) { ((e = f.end() > e ? f.end() : e), ...); });
        return e;
    }
    // Shortest valid input: fixed bytes and every non-optional field.
    constexpr std::size_t min_size() const noexcept {
        std::size_t e = declared_size;
        for (const auto& b : fixed) e = b.offset + 1 > e ? b.offset + 1 : e;
        const auto req = [&e](bool optional, std::size_t end) {
            if (!optional && end > e) e = end;
        };
        fields.apply(
            [&](const auto&... f) { (req(f.is_optional, f.kind == wire_kind::tail ? f.offset : f.end()), ...); });
        return e;
    }
    // Longest accepted input (longer than max_size(): the rest is ignored).
    constexpr std::size_t max_input() const noexcept { return declared_max_input ? declared_max_input : max_size(); }
};

// Builds a message table: name, fixed bytes, fields in offset order.
template <class M, std::size_t K, class... F>
constexpr auto make_table(std::string_view name, const fixed_byte (&fixed)[K], F... fields) noexcept {
    message_table<M, K, F...> t{name, {}, detail::field_list<F...>{fields...}};
    for (std::size_t i = 0; i < K; ++i) t.fixed[i] = fixed[i];
    return t;
}
template <class M, std::size_t K, class... F>
constexpr auto make_table(std::string_view name, const std::array<fixed_byte, K>& fixed, F... fields) noexcept {
    return message_table<M, K, F...>{name, fixed, detail::field_list<F...>{fields...}};
}
// Builds a record table (a struct nested in messages; no fixed bytes).
template <class M, class... F>
constexpr auto make_record(std::string_view name, F... fields) noexcept {
    return message_table<M, 0, F...>{name, {}, detail::field_list<F...>{fields...}};
}

// Size limits of a message's encoding.
template <described M>
inline constexpr std::size_t min_size_v = table_v<M>.min_size();
template <described M>
inline constexpr std::size_t max_size_v = table_v<M>.max_size();

// Calls fn(field) for each field of M's table, in table order.
template <class M, class Fn>
constexpr void for_each_field(Fn&& fn) {
    table_v<M>.fields.each(fn);
}

namespace codec {
// The value of M's fixed byte at key_offset (its command, for a dispatcher);
// -1: M has no fixed byte there.
template <class M>
constexpr int key_of(std::size_t key_offset) noexcept {
    for (const auto& b : table_v<M>.fixed)
        if (b.offset == key_offset) return b.value;
    return -1;
}
}  // namespace codec

// Bytes of M's encoding that no fixed byte and no field covers (reserved bytes).
template <class M>
constexpr std::array<bool, max_size_v<M>> reserved_bytes() noexcept {
    std::array<bool, max_size_v<M>> reserved{};
    reserved.fill(true);
    for (const auto& b : table_v<M>.fixed) reserved[b.offset] = false;
    // the fields' byte ranges, as a fold (no function per field type)
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        const std::size_t from[] = {table_v<M>.fields.template get<I>().offset..., 0};
        const std::size_t to[] = {table_v<M>.fields.template get<I>().end()..., 0};
        for (std::size_t k = 0; k < sizeof...(I); ++k)
            for (std::size_t i = from[k]; i < to[k]; ++i) reserved[i] = false;
    }
    (std::make_index_sequence<std::remove_cvref_t<decltype(table_v<M>)>::field_count>{});
    return reserved;
}

}  // namespace robowire
