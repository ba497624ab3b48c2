// robowire/core/endian.hpp - little-endian loads and stores on byte spans.
// constexpr (byte by byte in constant evaluation), alignment-safe (memcpy at
// run time on little-endian cores; see bytewise_v), usable in static_assert.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

namespace robowire {

namespace detail {
template <class T>
inline constexpr bool is_wire_scalar_v =
    std::is_same_v<T, std::uint8_t> || std::is_same_v<T, std::int8_t> || std::is_same_v<T, std::uint16_t> ||
    std::is_same_v<T, std::int16_t> || std::is_same_v<T, std::uint32_t> || std::is_same_v<T, std::int32_t> ||
    std::is_same_v<T, float>;

// std::bit_cast through the compiler's builtin (g++ >= 11, clang++ >= 9,
// MSVC), so that a standard library without std::bit_cast is enough
// (emscripten 3.1.6's libc++). constexpr; To and From: same size, trivially copyable.
template <class To, class From>
[[nodiscard]] constexpr To builtin_bit_cast(const From& from) noexcept {
    static_assert(sizeof(To) == sizeof(From), "builtin_bit_cast: sizes differ");
    static_assert(std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>,
                  "builtin_bit_cast: not trivially copyable");
#if defined(_MSC_VER)
    return __builtin_bit_cast(To, from);
#elif defined(__has_builtin)
#if __has_builtin(__builtin_bit_cast)
    return __builtin_bit_cast(To, from);
#else
    return std::bit_cast<To>(from);
#endif
#else
    return std::bit_cast<To>(from);
#endif
}

template <std::size_t N>
struct uint_of_size;
template <>
struct uint_of_size<1> {
    using type = std::uint8_t;
};
template <>
struct uint_of_size<2> {
    using type = std::uint16_t;
};
template <>
struct uint_of_size<4> {
    using type = std::uint32_t;
};
template <>
struct uint_of_size<8> {
    using type = std::uint64_t;
};

// At run time: memcpy (one wide load or store where the core allows
// unaligned access), except 16-bit values on cores without unaligned access
// (Cortex-M0/M0+, RV32 without fast unaligned access), where two byte loads and
// a shift are smaller than a memcpy call or a copy through the stack.
template <class T>
inline constexpr bool bytewise_v =
#if defined(__arm__) && !defined(__ARM_FEATURE_UNALIGNED)
    sizeof(T) == 2 ||
#endif
#if defined(__riscv) && !defined(__riscv_misaligned_fast)
    sizeof(T) == 2 ||
#endif
    std::endian::native != std::endian::little;
}  // namespace detail

// GCC's -Warray-bounds (at -O3) reports loads on paths that every caller's
// length check makes unreachable (e.g. decoding a 9-byte buffer through a
// dispatcher that also knows longer messages). The codecs check lengths
// before any load, and the fuzzers run under ASan; silence only that report.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif

// Reads a T (u8, i8, u16, i16, u32, i32, f32) stored little-endian at p[0..sizeof(T)).
template <class T>
[[nodiscard]] constexpr T load_le(const std::uint8_t* p) noexcept {
    static_assert(detail::is_wire_scalar_v<T>, "load_le: unsupported type");
    using U = typename detail::uint_of_size<sizeof(T)>::type;
    if constexpr (!detail::bytewise_v<T>) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {  // one (possibly unaligned) load
            T v;
            std::memcpy(&v, p, sizeof(T));
            return v;
        }
    }
    U u = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) u = static_cast<U>(u | static_cast<U>(static_cast<U>(p[i]) << (8 * i)));
    return detail::builtin_bit_cast<T>(u);
}

// Writes v little-endian to p[0..sizeof(T)).
template <class T>
constexpr void store_le(std::uint8_t* p, T v) noexcept {
    static_assert(detail::is_wire_scalar_v<T>, "store_le: unsupported type");
    if constexpr (!detail::bytewise_v<T>) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            std::memcpy(p, &v, sizeof(T));
            return;
        }
    }
    using U = typename detail::uint_of_size<sizeof(T)>::type;
    const U u = detail::builtin_bit_cast<U>(v);
    for (std::size_t i = 0; i < sizeof(T); ++i) p[i] = static_cast<std::uint8_t>(u >> (8 * i));
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// Span forms. Precondition: offset + sizeof(T) <= bytes.size().
template <class T>
[[nodiscard]] constexpr T load_le(std::span<const std::uint8_t> bytes, std::size_t offset) noexcept {
    return load_le<T>(bytes.data() + offset);
}
template <class T>
constexpr void store_le(std::span<std::uint8_t> bytes, std::size_t offset, T v) noexcept {
    store_le<T>(bytes.data() + offset, v);
}

}  // namespace robowire
