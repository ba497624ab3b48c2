// robowire/core/bits.hpp - bit ranges inside a byte, left-aligned 12-bit values,
// sign-magnitude int8.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstdint>

#include "result.hpp"

namespace robowire {

// Mask of `width` low bits (width 1..8).
[[nodiscard]] constexpr std::uint8_t low_mask(unsigned width) noexcept {
    return static_cast<std::uint8_t>((1u << width) - 1u);
}

// Bits [lo, lo+width) of `byte`, shifted down. lo + width <= 8.
[[nodiscard]] constexpr std::uint8_t get_bits(std::uint8_t byte, unsigned lo, unsigned width) noexcept {
    return static_cast<std::uint8_t>((byte >> lo) & low_mask(width));
}

// `byte` with bits [lo, lo+width) replaced by `value`; value_out_of_range if
// value does not fit in `width` bits.
[[nodiscard]] constexpr result<std::uint8_t> set_bits(std::uint8_t byte, unsigned lo, unsigned width,
                                                      unsigned value) noexcept {
    if (value > low_mask(width)) return fail(errc::value_out_of_range, 0);
    const auto mask = static_cast<std::uint8_t>(low_mask(width) << lo);
    return static_cast<std::uint8_t>((byte & ~mask) | ((value << lo) & mask));
}

// Left-aligned 12-bit signed value in a 16-bit word (low 4 bits unused).
inline constexpr int left12_min = -2048;
inline constexpr int left12_max = 2047;

// The 12-bit count held in `word` (arithmetic shift right by 4): -2048..2047.
[[nodiscard]] constexpr std::int16_t left12_count(std::int16_t word) noexcept {
    return static_cast<std::int16_t>(word >> 4);
}

// The word that holds `count` (-2048..2047) left-aligned, low 4 bits zero.
[[nodiscard]] constexpr result<std::int16_t> left12_word(int count) noexcept {
    if (count < left12_min || count > left12_max) return fail(errc::value_out_of_range, 0);
    return static_cast<std::int16_t>(count * 16);
}

// Sign-magnitude int8: bit 7 is the sign, bits 0-6 the magnitude (0x8A = -10).
// 0x80 ("minus zero") reads as 0.
[[nodiscard]] constexpr std::int8_t from_sign_magnitude(std::uint8_t byte) noexcept {
    const auto magnitude = static_cast<std::int8_t>(byte & 0x7F);
    return (byte & 0x80) ? static_cast<std::int8_t>(-magnitude) : magnitude;
}

// Sign-magnitude byte for v; -128 has no sign-magnitude form (value_out_of_range).
[[nodiscard]] constexpr result<std::uint8_t> to_sign_magnitude(std::int8_t v) noexcept {
    if (v == -128) return fail(errc::value_out_of_range, 0);
    if (v < 0) return static_cast<std::uint8_t>(0x80 | -v);
    return static_cast<std::uint8_t>(v);
}

}  // namespace robowire
