// The hand-written NAVBOT codecs a careful user would write, with the same
// checks in robowire's order and the same error report (bench::hw): the
// baselines of bench/navbot.cpp, and the oracle of fuzz/diff_navbot.cpp,
// which shares no table with robowire. bench/verify/navbot.cpp proves that
// they agree with robowire on the benchmarks' inputs.
#pragma once

#include <robowire/navbot.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "hw.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// Internal linkage, as when these functions were part of the benchmark's own
// translation unit (the same code, the same instruction counts).
namespace {
namespace nb = robowire::navbot;
namespace hw = bench::hw;

#if defined(__SSE2__)
inline __m128i vec(const std::uint8_t (&a)[16]) { return _mm_load_si128(reinterpret_cast<const __m128i*>(a)); }
#endif
bool in(int v, int lo, int hi) { return v >= lo && v <= hi; }
hw::error hw_encode(const nb::maneuver& m, std::uint8_t* out) {
    if (!in(m.roll, -100, 100)) return hw::fail(hw::value_out_of_range, 5);
    if (m.height > 100) return hw::fail(hw::value_out_of_range, 6);
    if (!in(m.pitch, -100, 100)) return hw::fail(hw::value_out_of_range, 7);
    if (!in(m.yaw, -100, 100)) return hw::fail(hw::value_out_of_range, 8);
    if (static_cast<std::uint8_t>(m.switch_a) > 2) return hw::fail(hw::invalid_enum, 9);
    if (static_cast<std::uint8_t>(m.switch_b) > 1) return hw::fail(hw::invalid_enum, 10);
    if (static_cast<std::uint8_t>(m.switch_c) > 1) return hw::fail(hw::invalid_enum, 11);
    if (static_cast<std::uint8_t>(m.switch_d) > 2) return hw::fail(hw::invalid_enum, 12);
    if (!in(m.ball_x, -5, 5)) return hw::fail(hw::value_out_of_range, 13);
    if (!in(m.ball_y, -5, 5)) return hw::fail(hw::value_out_of_range, 14);
    out[0] = 0x55; out[1] = 0xAA; out[2] = 0x10; out[3] = 0; out[4] = 0;
    out[5] = static_cast<std::uint8_t>(m.roll);
    out[6] = m.height;
    out[7] = static_cast<std::uint8_t>(m.pitch);
    out[8] = static_cast<std::uint8_t>(m.yaw);
    out[9] = static_cast<std::uint8_t>(m.switch_a);
    out[10] = static_cast<std::uint8_t>(m.switch_b);
    out[11] = static_cast<std::uint8_t>(m.switch_c);
    out[12] = static_cast<std::uint8_t>(m.switch_d);
    out[13] = static_cast<std::uint8_t>(m.ball_x);
    out[14] = static_cast<std::uint8_t>(m.ball_y);
    std::memset(out + 15, 0, 5);  // reserved
    return hw::good;
}
// robowire's order: the fixed bytes that are there (header, command, and
// remaining = 0, a bad_sequence), the length, then the fields.
hw::error hw_decode(const std::uint8_t* p, std::size_t n, nb::maneuver& m) {
    if (n > 0 && p[0] != 0x55) return hw::fail(hw::bad_header, 0);
    if (n > 1 && p[1] != 0xAA) return hw::fail(hw::bad_header, 1);
    if (n > 2 && p[2] != 0x10) return hw::fail(hw::bad_command, 2);
    if (n > 3 && p[3] != 0) return hw::fail(hw::bad_sequence, 3);
    if (auto e = hw::length(n, 20); e != hw::good) return e;
    const auto s8 = [&](int i) { return static_cast<std::int8_t>(p[i]); };
    if (!in(s8(5), -100, 100)) return hw::fail(hw::value_out_of_range, 5);
    if (p[6] > 100) return hw::fail(hw::value_out_of_range, 6);
    if (!in(s8(7), -100, 100)) return hw::fail(hw::value_out_of_range, 7);
    if (!in(s8(8), -100, 100)) return hw::fail(hw::value_out_of_range, 8);
    if (p[9] > 2) return hw::fail(hw::invalid_enum, 9);
    if (p[10] > 1) return hw::fail(hw::invalid_enum, 10);
    if (p[11] > 1) return hw::fail(hw::invalid_enum, 11);
    if (p[12] > 2) return hw::fail(hw::invalid_enum, 12);
    if (!in(s8(13), -5, 5)) return hw::fail(hw::value_out_of_range, 13);
    if (!in(s8(14), -5, 5)) return hw::fail(hw::value_out_of_range, 14);
    m = {s8(5), p[6], s8(7), s8(8), static_cast<nb::switch_a>(p[9]), static_cast<nb::switch_b>(p[10]),
         static_cast<nb::switch_c>(p[11]), static_cast<nb::switch_d>(p[12]), s8(13), s8(14)};
    return hw::good;
}

// The careful decoder: the length, the fixed bytes and the ranges, the exact
// error in a cold function (robowire's order), then the fields copied at
// once into robowire's own struct, whose members are the wire's bytes 5..14
// (layout checked below).
static_assert(std::endian::native == std::endian::little && sizeof(nb::maneuver) == 10 &&
              offsetof(nb::maneuver, switch_a) == 4 && offsetof(nb::maneuver, ball_y) == 9);
[[gnu::cold, gnu::noinline]] hw::error careful_maneuver_error(const std::uint8_t* p, std::size_t n) {
    nb::maneuver unused{};
    return hw_decode(p, n, unused);
}
inline unsigned out8(std::uint8_t b, int lo, int hi) {  // 1: the signed byte b is outside [lo, hi]
    return static_cast<unsigned>(static_cast<std::int8_t>(b) - lo) > static_cast<unsigned>(hi - lo);
}
inline unsigned above(std::uint8_t b, unsigned hi) { return b > hi; }  // 1: b > hi
// Scalar: the fixed bytes as a word compare, each range its own branch
// (fewer instructions than the checks OR-ed into one yes/no, g++ 12).
inline hw::error careful_decode_scalar(const std::uint8_t* p, std::size_t n, nb::maneuver& m) {
    const auto head = [p] {
        std::uint32_t h;
        std::memcpy(&h, p, 4);
        return h;
    };
    if (n != 20 || head() != 0x0010AA55u) [[unlikely]] return hw::never_good(careful_maneuver_error(p, n));  // head() only when n == 20
    if (out8(p[5], -100, 100) || above(p[6], 100) || out8(p[7], -100, 100) || out8(p[8], -100, 100) ||
        above(p[9], 2) || above(p[10], 1) || above(p[11], 1) || above(p[12], 2) || out8(p[13], -5, 5) ||
        out8(p[14], -5, 5)) [[unlikely]]
        return hw::never_good(careful_maneuver_error(p, n));
    std::memcpy(static_cast<void*>(&m), p + 5, 10);
    return hw::good;
}
#if defined(__SSE2__)
// SSE2, as the encoder below: bytes 0..15 plus off[i], as signed bytes,
// above lim[i] are bad. The header bytes must land on 0x80 (the minimum);
// bytes 4 and 15 may hold anything.
alignas(16) inline constexpr std::uint8_t dec_off[16] = {0x2B, 0xD6, 0x70, 0x80, 0x00, 0xE4, 0x80, 0xE4,
                                                        0xE4, 0x80, 0x80, 0x80, 0x80, 0x85, 0x85, 0x00};
alignas(16) inline constexpr std::uint8_t dec_lim[16] = {0x80, 0x80, 0x80, 0x80, 0x7F, 0x48, 0xE4, 0x48,
                                                        0x48, 0x82, 0x81, 0x81, 0x82, 0x8A, 0x8A, 0x7F};
inline hw::error careful_decode(const std::uint8_t* p, std::size_t n, nb::maneuver& m) {
    if (n != 20) [[unlikely]] return hw::never_good(careful_maneuver_error(p, n));
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    if (_mm_movemask_epi8(_mm_cmpgt_epi8(_mm_add_epi8(v, vec(dec_off)), vec(dec_lim))) != 0) [[unlikely]]
        return hw::never_good(careful_maneuver_error(p, n));
    std::memcpy(static_cast<void*>(&m), p + 5, 10);
    return hw::good;
}
#else
inline hw::error careful_decode(const std::uint8_t* p, std::size_t n, nb::maneuver& m) {
    return careful_decode_scalar(p, n, m);
}
#endif

// The careful encoder: the checks, the exact error in a cold function, then
// the frame as whole-register stores (the struct's layout is the wire's bytes 5..14).
[[gnu::cold, gnu::noinline]] hw::error careful_encode_error(const nb::maneuver& m, std::uint8_t* out) {
    return hw_encode(m, out);
}
// Scalar: a branch per check (switch_b and switch_c as one word), the frame as three stores.
inline unsigned outside(int v, int lo, int hi) { return static_cast<unsigned>(v - lo) > static_cast<unsigned>(hi - lo); }
inline hw::error careful_encode_scalar(const nb::maneuver& m, std::uint8_t* out) {
    std::uint16_t bc;  // switch_b, switch_c
    std::memcpy(&bc, &m.switch_b, 2);
    if (outside(m.roll, -100, 100) || m.height > 100 || outside(m.pitch, -100, 100) || outside(m.yaw, -100, 100) ||
        static_cast<unsigned>(m.switch_a) > 2 || (bc & 0xFEFE) != 0 || static_cast<unsigned>(m.switch_d) > 2 ||
        outside(m.ball_x, -5, 5) || outside(m.ball_y, -5, 5)) [[unlikely]]
        return hw::never_good(careful_encode_error(m, out));
    std::uint64_t a, b;  // fields 0..7 and 2..9
    std::memcpy(&a, &m, 8);
    std::memcpy(&b, reinterpret_cast<const unsigned char*>(&m) + 2, 8);
    const std::uint64_t w0 = a << 40 | 0x0010AA55u, w1 = b >> 8;  // 55 AA 10 00 00 f0 f1 f2; f3..f9 00
    const std::uint32_t w2 = 0;
    std::memcpy(out, &w0, 8);
    std::memcpy(out + 8, &w1, 8);
    std::memcpy(out + 16, &w2, 4);
    return hw::good;
}
#if defined(__SSE2__)
// SSE2: the ten range checks as one vector compare: each byte plus off[i], as
// a signed byte, above lim[i] is out of range (off = 0x80 - lo, lim = hi - lo - 0x80).
alignas(16) inline constexpr std::uint8_t enc_off[16] = {0xE4, 0x80, 0xE4, 0xE4, 0x80, 0x80, 0x80, 0x80, 0x85, 0x85};
alignas(16) inline constexpr std::uint8_t enc_lim[16] = {0x48, 0xE4, 0x48, 0x48, 0x82, 0x81, 0x81,
                                                        0x82, 0x8A, 0x8A, 0x7F, 0x7F, 0x7F, 0x7F, 0x7F, 0x7F};
alignas(16) inline constexpr std::uint8_t enc_head[16] = {0x55, 0xAA, 0x10};
inline hw::error careful_encode(const nb::maneuver& m, std::uint8_t* out) {
    std::uint16_t tail;  // ball_x, ball_y
    std::memcpy(&tail, &m.ball_x, 2);
    const __m128i v = _mm_insert_epi16(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&m)), static_cast<std::int16_t>(tail), 4);
    if (_mm_movemask_epi8(_mm_cmpgt_epi8(_mm_add_epi8(v, vec(enc_off)), vec(enc_lim))) != 0) [[unlikely]]
        return hw::never_good(careful_encode_error(m, out));
    // 55 AA 10 00 00, the fields, a zero; then the last four reserved bytes
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_or_si128(_mm_slli_si128(v, 5), vec(enc_head)));
    std::memset(out + 16, 0, 4);
    return hw::good;
}
#else
inline hw::error careful_encode(const nb::maneuver& m, std::uint8_t* out) { return careful_encode_scalar(m, out); }
#endif

}  // namespace
