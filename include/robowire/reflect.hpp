// robowire/reflect.hpp - walking a protocol's tables, for tools that print,
// parse or check messages (the command-line tool, the Python and JavaScript
// packages, test helpers): the alternatives of a protocol's std::variant, the
// one found by name or by key bytes, the input lengths a message takes, the
// elements of a field by kind with their physical values, and flag-bit
// iteration, and the fuzz dictionary of a protocol's variants. The error text is describe_error (core/fields.hpp).
// Everything here is constexpr and allocates nothing; no codec reads it.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "core/bytes.hpp"
#include "core/descriptor.hpp"
#include "core/fields.hpp"
#include "core/flag_bits.hpp"
#include "core/table.hpp"

namespace robowire {

// One fuzz dictionary entry (fuzz_dictionary_v, below): bytes that a
// message's table fixes at consecutive offsets (markers, command bytes), 1..16 of them.
struct fuzz_token {
    std::uint8_t bytes[16];
    std::uint8_t size;

    constexpr std::span<const std::uint8_t> view() const noexcept { return {bytes, size}; }
};

// ---------------------------------------------------------------- alternatives
// Calls fn(std::type_identity<M>{}) for every alternative M of Variant, in order.
template <class Variant, class Fn>
constexpr void for_each_alternative(Fn&& fn) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (fn(std::type_identity<std::variant_alternative_t<I, Variant>>{}), ...);
    }
    (std::make_index_sequence<std::variant_size_v<Variant>>{});
}

// Calls fn(std::type_identity<M>{}) for alternative `index` of Variant;
// false (and no call) for an index past the end.
template <class Variant, class Fn>
constexpr bool with_alternative(std::size_t index, Fn&& fn) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return ((index == I ? (fn(std::type_identity<std::variant_alternative_t<I, Variant>>{}), true) : false) || ...);
    }
    (std::make_index_sequence<std::variant_size_v<Variant>>{});
}

// The index of the alternative of Variant whose table is named `name`;
// variant_size: none.
template <class Variant>
[[nodiscard]] constexpr std::size_t alternative_named(std::string_view name) noexcept {
    std::size_t found = std::variant_size_v<Variant>, i = 0;
    for_each_alternative<Variant>([&](auto t) {
        if (found == std::variant_size_v<Variant> && table_v<typename decltype(t)::type>.name == name) found = i;
        ++i;
    });
    return found;
}

// The index of the alternative of Variant that a dispatcher reading the key
// bytes of `in` at KeyOffset... (increasing) chooses: the one whose fixed
// bytes there are those bytes, else the one with no fixed byte there (it
// takes every other key, as NAVBOT's frame does); variant_size: none, or `in`
// does not reach the last key offset.
template <class Variant, std::size_t... KeyOffset>
requires(sizeof...(KeyOffset) > 0) [[nodiscard]] constexpr std::size_t
    alternative_by_key(std::span<const std::uint8_t> in) noexcept {
    constexpr std::size_t offsets[] = {KeyOffset...};
    if (in.size() <= offsets[sizeof...(KeyOffset) - 1]) return std::variant_size_v<Variant>;
    const std::uint8_t key[] = {in[KeyOffset]...};
    return detail::alternative_by_key<Variant, KeyOffset...>::find(key);
}

// Do the fixed bytes of M that `in` reaches all have M's values, and has M
// any? (Which message an input that failed to decode was meant as.)
template <described M>
[[nodiscard]] constexpr bool matches_fixed_bytes(std::span<const std::uint8_t> in) noexcept {
    for (const auto& b : table_v<M>.fixed)
        if (b.offset < in.size() && in[b.offset] != b.value) return false;
    return !table_v<M>.fixed.empty();
}

// ---------------------------------------------------------------- fuzz dictionary
namespace detail {
template <class... Variants>
constexpr std::size_t fixed_byte_count() noexcept {
    std::size_t n = 0;
    (for_each_alternative<Variants>([&](auto t) { n += table_v<typename decltype(t)::type>.fixed.size(); }), ...);
    return n;
}
template <std::size_t N>
struct fuzz_token_list {
    std::array<fuzz_token, N> tokens{};
    std::size_t size = 0;
    constexpr void add(const fuzz_token& t) noexcept {
        for (std::size_t i = 0; i < size; ++i)
            if (equal_bytes(tokens[i].view(), t.view())) return;
        tokens[size++] = t;
    }
};
// Every run of M's fixed bytes at consecutive offsets (split every 16 bytes) into `out`.
template <class M, std::size_t N>
constexpr void add_fixed_runs(fuzz_token_list<N>& out) noexcept {
    auto fixed = table_v<M>.fixed;  // in offset order
    for (std::size_t i = 1; i < fixed.size(); ++i)
        for (std::size_t j = i; j > 0 && fixed[j].offset < fixed[j - 1].offset; --j) {
            const auto b = fixed[j];
            fixed[j] = fixed[j - 1];
            fixed[j - 1] = b;
        }
    fuzz_token t{};
    for (std::size_t i = 0; i < fixed.size(); ++i) {
        if (t.size == sizeof t.bytes || (t.size > 0 && fixed[i].offset != fixed[i - 1].offset + 1)) {
            out.add(t);
            t = {};
        }
        t.bytes[t.size++] = fixed[i].value;
    }
    if (t.size > 0) out.add(t);
}
template <class... Variants>
constexpr auto fuzz_token_list_of() noexcept {
    fuzz_token_list<fixed_byte_count<Variants...>()> out;
    (for_each_alternative<Variants>([&](auto t) { add_fixed_runs<typename decltype(t)::type>(out); }), ...);
    return out;
}
}  // namespace detail

// The fuzz dictionary of a protocol's variants: every run of fixed bytes at
// consecutive offsets of every alternative (markers with command bytes, a
// trailer), each once, in variant order.
template <class... Variants>
inline constexpr auto fuzz_tokens_v = [] {
    constexpr auto all = detail::fuzz_token_list_of<Variants...>();
    std::array<fuzz_token, all.size> out{};
    for (std::size_t i = 0; i < all.size; ++i) out[i] = all.tokens[i];
    return out;
}();
// The fuzz dictionary of a protocol, from its `messages` (message_variants):
// fuzz_tokens_v of its variants, e.g. fuzz_dictionary_v<osp::messages>.
template <class Messages>
inline constexpr const auto& fuzz_dictionary_v = []() -> const auto& {
    if constexpr (Messages::has_directions)
        return fuzz_tokens_v<typename Messages::to_device, typename Messages::from_device>;
    else return fuzz_tokens_v<typename Messages::to_device>;
}
();

// ---------------------------------------------------------------- lengths
// The input lengths M's decoder accepts as runs [first, last], increasing
// (BuWizz3 status: {54, 54}, {68, 129}): every length from min_size() to
// max_input() that does not end inside an optional block. describe_error's
// length errors give the same runs.
template <std::size_t N>
using length_runs = detail::length_runs<N>;
template <described M>
inline constexpr const auto& accepted_lengths_v = detail::length_runs_v<M>;

// ---------------------------------------------------------------- values
// What a field's element holds.
enum class value_kind : std::uint8_t { integer, enumeration, boolean, floating, text, bytes, record };

// The kind of field type F's elements (F: a field of a table).
template <class F>
inline constexpr value_kind value_kind_v = [] {
    using E = typename F::element_type;
    if constexpr (F::kind == wire_kind::record) return value_kind::record;
    else if constexpr (F::kind == wire_kind::text) return value_kind::text;
    else if constexpr (F::kind == wire_kind::tail) return value_kind::bytes;
    else if constexpr (std::is_enum_v<E>) return value_kind::enumeration;
    else if constexpr (std::is_same_v<E, bool>) return value_kind::boolean;
    else if constexpr (std::is_floating_point_v<E>) return value_kind::floating;
    else return value_kind::integer;
}();

// The elements of field f in m: one, every element of an array, none for an
// absent optional block.
template <class F, class M>
[[nodiscard]] constexpr std::span<const typename F::element_type> elements_of(const F& f, const M& m) noexcept {
    const auto& member = m.*(f.member);
    if constexpr (F::is_optional) {
        if (!member) return {};
        if constexpr (F::is_array) return std::span<const typename F::element_type>(*member);
        else return std::span<const typename F::element_type>(&*member, 1);
    } else if constexpr (F::is_array) {
        return std::span<const typename F::element_type>(member);
    } else {
        return std::span<const typename F::element_type>(&member, 1);
    }
}

// Calls fn(f, elements_of(f, m)) for each field f of M's table, in order.
template <described M, class Fn>
constexpr void for_each_value(const M& m, Fn&& fn) {
    for_each_field<M>([&](const auto& f) { fn(f, elements_of(f, m)); });
}

// Has field f a physical value (an integer with a unit)?
template <class F>
[[nodiscard]] constexpr bool has_physical(const F& f) noexcept {
    return value_kind_v<F> == value_kind::integer && !f.unit.name.empty();
}
// The physical value of raw value `raw` of field f: raw * scale + offset
// (raw itself when f has no unit), not rounded.
template <class F>
[[nodiscard]] constexpr double physical_of(const F& f, std::int64_t raw) noexcept {
    return static_cast<double>(raw) * f.unit.scale + f.unit.offset;
}

// ---------------------------------------------------------------- flag bits
// Calls fn(flag_bit) for each named bit group of M's flag byte `field`, in
// table order (none when M names no bits).
template <class M, class Fn>
constexpr void for_each_flag_bit([[maybe_unused]] std::string_view field, [[maybe_unused]] Fn&& fn) {
    if constexpr (has_flag_bits<M>)
        for (const flag_bit& b : flag_bits_v<M>)
            if (b.field == field) fn(b);
}
// Does M name bits of its flag byte `field`?
template <class M>
[[nodiscard]] constexpr bool has_flag_bits_in(std::string_view field) noexcept {
    bool any = false;
    for_each_flag_bit<M>(field, [&](const flag_bit&) { any = true; });
    return any;
}
// The bits of b in a flag byte: ((1 << width) - 1) << lo.
[[nodiscard]] constexpr unsigned flag_mask(const flag_bit& b) noexcept { return ((1u << b.width) - 1u) << b.lo; }
// The value of b's bits in flag byte `raw`, shifted down (0..2^width-1).
[[nodiscard]] constexpr unsigned flag_value(const flag_bit& b, unsigned raw) noexcept {
    return (raw & flag_mask(b)) >> b.lo;
}
// How many of b's values may have names: 0 for a one-bit flag, else
// min(2^width, 4).
[[nodiscard]] constexpr std::size_t flag_value_count(const flag_bit& b) noexcept {
    if (b.width <= 1) return 0;
    const std::size_t n = std::size_t{1} << b.width;
    return n < b.values.size() ? n : b.values.size();
}
// The name of value v of a wider bit group ("" when unnamed: show the number).
[[nodiscard]] constexpr std::string_view flag_value_name(const flag_bit& b, unsigned v) noexcept {
    return v < flag_value_count(b) ? b.values[v] : std::string_view{};
}

}  // namespace robowire
