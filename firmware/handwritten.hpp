// Shared by the hand-written baselines (hw_*.cpp): what a careful C/C++
// firmware developer writes without a library. Plain structs, a switch on the
// command, shifts for multi-byte fields, and the same checks and error
// reporting as robowire (an error code and the byte offset it is about).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "harness.hpp"

namespace hw {

// A codec function of the baseline: a plain function of the program's file,
// which the compiler may inline into its callers, as it may robowire's
// header-only codecs (the same freedom on both sides).
#define HW_CODEC

// Same codes as robowire::errc, so both report the same thing.
enum err : std::uint8_t {
    ok = 0, too_short, too_long, bad_length, bad_header, bad_trailer, bad_command, bad_device,
    unknown_message, value_out_of_range, invalid_enum, bad_padding, reserved_not_zero, missing_field,
    buffer_too_small, capacity_exceeded, bad_sequence, command_changed
};
struct error {
    std::uint8_t code;
    std::uint8_t offset;
};
constexpr error good{ok, 0};
inline error fail(err e, std::size_t at) { return {e, static_cast<std::uint8_t>(at)}; }
// Length check in robowire's order: too short, then too long.
inline error length(std::size_t n, std::size_t want) {
    if (n < want) return fail(too_short, n);
    if (n > want) return fail(too_long, want);
    return good;
}

inline std::uint16_t rd16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | p[1] << 8); }
inline std::uint32_t rd32(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
inline float rdf(const std::uint8_t* p) {
    float f;
    std::memcpy(&f, p, 4);
    return f;
}
inline void wr16(std::uint8_t* p, std::uint16_t v) {
    p[0] = static_cast<std::uint8_t>(v);
    p[1] = static_cast<std::uint8_t>(v >> 8);
}
inline void wr32(std::uint8_t* p, std::uint32_t v) {
    p[0] = static_cast<std::uint8_t>(v);
    p[1] = static_cast<std::uint8_t>(v >> 8);
    p[2] = static_cast<std::uint8_t>(v >> 16);
    p[3] = static_cast<std::uint8_t>(v >> 24);
}
inline void wrf(std::uint8_t* p, float f) { std::memcpy(p, &f, 4); }
inline void report(error e) { sink = static_cast<std::uint32_t>(e.code | e.offset << 8); }
[[gnu::always_inline]] inline void out(const std::uint8_t* p, std::size_t n) { out_bytes(p, n); }

}  // namespace hw
