// robowire/core/dispatch.hpp - decode into a std::variant of messages,
// choosing the alternative by the fixed byte at a key offset (the command).
#pragma once

#include <cstddef>
#include <span>
#include <variant>

#include "table.hpp"

namespace robowire {

namespace detail {
template <class M>
constexpr bool has_key(std::size_t key_offset, std::uint8_t key) noexcept {
    for (const auto& b : table_v<M>.fixed)
        if (b.offset == key_offset) return b.value == key;
    return false;
}
template <class Variant, std::size_t I = 0>
constexpr result<Variant> decode_alternative(std::span<const std::uint8_t> in, std::size_t key_offset) noexcept {
    if constexpr (I == std::variant_size_v<Variant>) {
        return fail(errc::unknown_message, key_offset);
    } else {
        using M = std::variant_alternative_t<I, Variant>;
        if (has_key<M>(key_offset, in[key_offset])) {
            auto r = robowire::decode<M>(in);
            if (!r) return r.error();
            return Variant{std::in_place_index<I>, std::move(*r)};
        }
        return decode_alternative<Variant, I + 1>(in, key_offset);
    }
}
}  // namespace detail

// Decodes `in` as the alternative of Variant whose fixed byte at key_offset
// matches; unknown_message (at key_offset) if none does, too_short if the
// input does not reach the key.
template <class Variant>
[[nodiscard]] constexpr result<Variant> decode_variant(std::span<const std::uint8_t> in,
                                                       std::size_t key_offset = 0) noexcept {
    if (in.size() <= key_offset) return fail(errc::too_short, in.size());
    return detail::decode_alternative<Variant>(in, key_offset);
}

// Encodes whichever message the variant holds, into the largest buffer any needs.
namespace detail {
template <class Variant> struct max_size_of;
template <class... M> struct max_size_of<std::variant<M...>> {
    static constexpr std::size_t value = [] {
        std::size_t n = 0;
        ((n = max_size_v<M> > n ? max_size_v<M> : n), ...);
        return n;
    }();
};
}  // namespace detail
template <class Variant>
inline constexpr std::size_t variant_max_size_v = detail::max_size_of<Variant>::value;

template <class... M>
[[nodiscard]] constexpr result<bytes<variant_max_size_v<std::variant<M...>>>> encode(const std::variant<M...>& v) noexcept {
    using out_t = bytes<variant_max_size_v<std::variant<M...>>>;
    return std::visit(
        [](const auto& m) -> result<out_t> {
            const auto r = robowire::encode(m);
            if (!r) return r.error();
            return out_t::from(*r).value();
        },
        v);
}

}  // namespace robowire
