// The hand-written OSP codecs a careful user would write, with the same
// checks in robowire's order and the same error report (bench::hw): the
// baselines of bench/osp.cpp, and the oracle of fuzz/diff_osp.cpp,
// which shares no table with robowire. bench/verify/osp.cpp proves that
// they agree with robowire on the benchmarks' inputs.
#pragma once

#include <robowire/osp.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "hw.hpp"

// Internal linkage, as when these functions were part of the benchmark's own
// translation unit (the same code, the same instruction counts).
namespace {
namespace hw = bench::hw;

// robowire's order: the fixed bytes that are there (markers, DEV, CMD, end
// markers, by offset), then the length.
hw::error hw_voltage(const std::uint8_t* p, std::size_t n, std::int16_t& cv) {
    if (n > 0 && p[0] != 0xFF) return hw::fail(hw::bad_header, 0);
    if (n > 1 && p[1] != 0xAA) return hw::fail(hw::bad_header, 1);
    if (n > 2 && p[2] != 0x02) return hw::fail(hw::bad_device, 2);
    if (n > 3 && p[3] != 0x12) return hw::fail(hw::bad_command, 3);
    if (n > 8 && p[8] != 0x55) return hw::fail(hw::bad_trailer, 8);
    if (n > 9 && p[9] != 0x77) return hw::fail(hw::bad_trailer, 9);
    if (auto e = hw::length(n, 10); e != hw::good) return e;
    cv = static_cast<std::int16_t>(p[4] | p[5] << 8);
    return hw::good;
}
// The message, and the frame's DEV, CMD and P1..P4 as osp::decode keeps
// them (its frame(), also for unknown messages and bad fields).
struct hw_msg { std::uint8_t dev, cmd, p[4]; std::uint16_t a; std::uint8_t b; };
hw::error hw_decode_any(const std::uint8_t* p, std::size_t n, hw_msg& m) {
    if (n > 0 && p[0] != 0xFF) return hw::fail(hw::bad_header, 0);
    if (n > 1 && p[1] != 0xAA) return hw::fail(hw::bad_header, 1);
    if (n > 8 && p[8] != 0x55) return hw::fail(hw::bad_trailer, 8);
    if (n > 9 && p[9] != 0x77) return hw::fail(hw::bad_trailer, 9);
    if (auto e = hw::length(n, 10); e != hw::good) return e;
    m.dev = p[2];
    m.cmd = p[3];
    std::memcpy(m.p, p + 4, 4);
    switch (p[2] << 8 | p[3]) {
    case 0x0001: case 0x0201: case 0x0202: case 0x0203: case 0x0204: return hw::good;
    case 0x0011: m.b = p[4]; return p[4] <= 3 ? hw::good : hw::fail(hw::invalid_enum, 4);
    case 0x0102: m.b = p[4]; m.a = static_cast<std::uint16_t>(p[5] | p[6] << 8); return hw::good;
    case 0x0211: case 0x0212: case 0x0213: m.a = static_cast<std::uint16_t>(p[4] | p[5] << 8); return hw::good;
    case 0x0214: m.b = p[4]; m.a = p[5]; return p[4] <= 4 ? hw::good : hw::fail(hw::invalid_enum, 4);
    default: return hw::fail(hw::unknown_message, 2);
    }
}

// The careful decoders: the length and the markers, DEV and CMD as one
// test (words compared, little-endian host), the exact error in a cold
// function (robowire's order), the parameters copied at once.
static_assert(std::endian::native == std::endian::little, "the careful baselines compare little-endian words");
inline std::uint32_t ld32(const std::uint8_t* p) { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
inline std::uint16_t ld16(const std::uint8_t* p) { std::uint16_t v; std::memcpy(&v, p, 2); return v; }
[[gnu::cold, gnu::noinline]] hw::error careful_voltage_error(const std::uint8_t* p, std::size_t n) {
    std::int16_t unused = 0;
    return hw_voltage(p, n, unused);
}
inline hw::error careful_voltage(const std::uint8_t* p, std::size_t n, std::int16_t& cv) {
    // each word compared with memory (an immediate operand on x86-64)
    if (n != 10 || ld32(p) != 0x1202AAFFu || ld16(p + 8) != 0x7755u) [[unlikely]]
        return hw::never_good(careful_voltage_error(p, n));
    std::memcpy(&cv, p + 4, 2);
    return hw::good;
}
[[gnu::cold, gnu::noinline]] hw::error careful_any_error(const std::uint8_t* p, std::size_t n) {
    hw_msg unused{};
    return hw_decode_any(p, n, unused);
}
[[gnu::cold, gnu::noinline]] hw::error careful_enum_error() { return hw::fail(hw::invalid_enum, 4); }
inline hw::error careful_decode_any(const std::uint8_t* p, std::size_t n, hw_msg& m) {
    if (n != 10 || ld16(p) != 0xAAFFu || ld16(p + 8) != 0x7755u) [[unlikely]]  // compared with memory
        return hw::never_good(careful_any_error(p, n));
    std::memcpy(&m.dev, p + 2, 6);  // dev, cmd, p[4]
    switch (ld16(p + 2)) {  // DEV | CMD << 8
    case 0x0100: case 0x0102: case 0x0202: case 0x0302: case 0x0402: return hw::good;
    case 0x1100: m.b = p[4]; return p[4] <= 3 ? hw::good : hw::never_good(careful_enum_error());
    case 0x0201: m.b = p[4]; m.a = ld16(p + 5); return hw::good;
    case 0x1102: case 0x1202: case 0x1302: m.a = ld16(p + 4); return hw::good;
    case 0x1402: m.b = p[4]; m.a = p[5]; return p[4] <= 4 ? hw::good : hw::never_good(careful_enum_error());
    default: return hw::never_good(careful_any_error(p, n));
    }
}
static_assert(offsetof(hw_msg, cmd) == 1 && offsetof(hw_msg, p) == 2);

}  // namespace
