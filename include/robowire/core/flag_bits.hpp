// robowire/core/flag_bits.hpp - names of the bits of flag-byte fields, for
// tools that print messages. A message with flag bytes declares them through
//     constexpr auto flag_bits_of(std::type_identity<Msg>)
// (found by ADL) returning std::array<flag_bit, N>. No codec reads them.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace robowire {

// Bits [lo, lo+width) of the flag byte `field`. width 1: a flag named `name`,
// shown when set. Wider: a small field named `name` whose values are named by
// `values` (up to 4; empty names: shown as numbers), always shown.
struct flag_bit {
    std::string_view field;
    std::uint8_t lo = 0;
    std::uint8_t width = 1;
    std::string_view name;
    std::array<std::string_view, 4> values{};
};

// Does M name the bits of any of its flag bytes?
template <class M>
concept has_flag_bits = requires {
    flag_bits_of(std::type_identity<M>{});
};

// M's flag bit names (an array of flag_bit).
template <has_flag_bits M>
inline constexpr auto flag_bits_v = flag_bits_of(std::type_identity<M>{});

// Port bits 0-5 named port1..port6 (BuWizz3 brake and LUT-disable bytes).
constexpr std::array<flag_bit, 6> port_bits(std::string_view field) noexcept {
    return {{{field, 0, 1, "port1", {}},
             {field, 1, 1, "port2", {}},
             {field, 2, 1, "port3", {}},
             {field, 3, 1, "port4", {}},
             {field, 4, 1, "port5", {}},
             {field, 5, 1, "port6", {}}}};
}

// Joins arrays of flag_bit (for messages with several flag bytes).
template <std::size_t A, std::size_t B>
constexpr std::array<flag_bit, A + B> join_flag_bits(const std::array<flag_bit, A>& a,
                                                     const std::array<flag_bit, B>& b) noexcept {
    std::array<flag_bit, A + B> out{};
    for (std::size_t i = 0; i < A; ++i) out[i] = a[i];
    for (std::size_t i = 0; i < B; ++i) out[A + i] = b[i];
    return out;
}

}  // namespace robowire
