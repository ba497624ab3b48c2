// robowire/navbot/maneuver.hpp - CMD_MANEUVER (0x10): drive the robot.
//
// Signed channels are two's complement int8 (what the robot's firmware
// reads). The protocol document's samples write them sign-magnitude (0x8A
// for -10); sent to the robot, 0x8A means -118: "back slowly" becomes "back
// at 118 %". sign_encoding::sign_magnitude exists only to reproduce those
// samples.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "../core/bits.hpp"
#include "frame.hpp"

namespace robowire::navbot {

enum class switch_a : std::uint8_t { stop = 0, start = 1, start_touch_panel = 2 };  // SWA_en
enum class switch_b : std::uint8_t { posture = 0, mark = 1 };                       // SWB_posture
enum class switch_c : std::uint8_t { unlock = 0, lock = 1 };                        // SWC_roll_lock
enum class switch_d : std::uint8_t {
    standard = 0,
    pitch_adjust = 1,
    ball_poise = 2
};  // SWD_posture_option ("default" = standard)

constexpr auto enum_table_of(std::type_identity<switch_a>) {
    return std::array<enum_entry<switch_a>, 3>{
        {{switch_a::stop, "stop"}, {switch_a::start, "start"}, {switch_a::start_touch_panel, "start_touch_panel"}}};
}
constexpr auto enum_table_of(std::type_identity<switch_b>) {
    return std::array<enum_entry<switch_b>, 2>{{{switch_b::posture, "posture"}, {switch_b::mark, "mark"}}};
}
constexpr auto enum_table_of(std::type_identity<switch_c>) {
    return std::array<enum_entry<switch_c>, 2>{{{switch_c::unlock, "unlock"}, {switch_c::lock, "lock"}}};
}
constexpr auto enum_table_of(std::type_identity<switch_d>) {
    return std::array<enum_entry<switch_d>, 3>{{{switch_d::standard, "standard"},
                                                {switch_d::pitch_adjust, "pitch_adjust"},
                                                {switch_d::ball_poise, "ball_poise"}}};
}

// Maneuver command. Ranges: roll, pitch, yaw -100..100; height 0..100; ball_x, ball_y -5..5.
struct maneuver {
    std::int8_t roll = 0;     // lean left/right
    std::uint8_t height = 0;  // body height
    std::int8_t pitch = 0;    // forward (+) / backward (-)
    std::int8_t yaw = 0;      // spin: clockwise (+) / counterclockwise (-)
    navbot::switch_a switch_a = navbot::switch_a::stop;
    navbot::switch_b switch_b = navbot::switch_b::posture;
    navbot::switch_c switch_c = navbot::switch_c::unlock;
    navbot::switch_d switch_d = navbot::switch_d::standard;
    std::int8_t ball_x = 0;
    std::int8_t ball_y = 0;
    friend constexpr bool operator==(const maneuver&, const maneuver&) = default;
};

// Frame offsets (0-based): 5 roll, 6 height, 7 pitch, 8 yaw, 9-12 switches A-D,
// 13 ball x, 14 ball y, 15-19 reserved. `remaining` must be 0.
constexpr auto table_of(std::type_identity<maneuver>) {
    auto t = make_table<maneuver>(
        "maneuver",
        {{0, header1, errc::bad_header},
         {1, header2, errc::bad_header},
         {2, command::maneuver, errc::bad_command},
         {3, 0x00, errc::bad_sequence}},
        field{"roll", &maneuver::roll, 5, wire::i8{}, range{-100, 100}, unit{"%"}},
        field{"height", &maneuver::height, 6, wire::u8{}, range{0, 100}, unit{"%"}},
        field{"pitch", &maneuver::pitch, 7, wire::i8{}, range{-100, 100}, unit{"%"}},
        field{"yaw", &maneuver::yaw, 8, wire::i8{}, range{-100, 100}, unit{"%"}},
        field{"switch_a", &maneuver::switch_a, 9, wire::u8{}}, field{"switch_b", &maneuver::switch_b, 10, wire::u8{}},
        field{"switch_c", &maneuver::switch_c, 11, wire::u8{}}, field{"switch_d", &maneuver::switch_d, 12, wire::u8{}},
        field{"ball_x", &maneuver::ball_x, 13, wire::i8{}, range{-5, 5}},
        field{"ball_y", &maneuver::ball_y, 14, wire::i8{}, range{-5, 5}});
    t.declared_size = frame_size;
    return t;
}

// How signed channels are written.
enum class sign_encoding : std::uint8_t {
    twos_complement,  // default: what the robot reads
    sign_magnitude,   // the protocol document's samples (0x8A = -10); not for the real robot
};

namespace impl {
// Byte offsets of maneuver's i8 fields (the signed channels), from its table.
template <class Deferred = void>
constexpr auto make_signed_offsets() noexcept {
    // one pass over the fields as a pack (one function to compile, not one per field)
    constexpr auto all = table_v<maneuver>.fields.apply([](const auto&... f) {
        struct list {
            std::uint8_t offset[sizeof...(f) + 1];
            std::size_t size;
        } r{};
        ((f.kind == wire_kind::i8 ? (void)(r.offset[r.size++] = static_cast<std::uint8_t>(f.offset)) : void()), ...);
        return r;
    });
    std::array<std::uint8_t, all.size> offsets{};
    for (std::size_t k = 0; k < all.size; ++k) offsets[k] = all.offset[k];
    return offsets;
}
// In flash: one loop over them, not a copy of the conversion per channel.
template <class Deferred = void>
inline constexpr auto signed_offsets_v = make_signed_offsets<Deferred>();
// Rewrites every i8 field of maneuver's table between the two encodings.
template <bool ToSignMagnitude, class Deferred = void>
constexpr void convert_signed(std::uint8_t* b) noexcept {  // a frame's frame_size bytes
    for (const std::uint8_t off : signed_offsets_v<Deferred>) {
        if constexpr (ToSignMagnitude) {  // to_sign_magnitude; -128 (in no channel's range) as 0x80
            const auto v = static_cast<std::int8_t>(b[off]);
            b[off] = static_cast<std::uint8_t>(v < 0 ? 0x80 | -v : v);
        } else {
            b[off] = static_cast<std::uint8_t>(from_sign_magnitude(b[off]));
        }
    }
}
}  // namespace impl

inline namespace ROBOWIRE_MODE_NAMESPACE {
// Encodes with the chosen sign encoding (robowire::encode(m) is two's complement).
// (A template only so that nothing is instantiated in a translation unit that does not call it.)
template <class Deferred = void>
[[nodiscard]] constexpr result<bytes<frame_size>> encode(const maneuver& m,
                                                         sign_encoding enc = sign_encoding::twos_complement) noexcept {
    auto r = robowire::encode(codec::deferred<Deferred>(m));
    if (r && enc == sign_encoding::sign_magnitude) impl::convert_signed<true>(r->data());
    return r;
}

// Decodes with the chosen sign encoding (robowire::decode<maneuver> is two's complement).
// (A template only so that nothing is instantiated in a translation unit that does not call it.)
template <class Deferred = void>
[[nodiscard]] constexpr result<maneuver> decode_maneuver(std::span<const std::uint8_t> in,
                                                         sign_encoding enc = sign_encoding::twos_complement) noexcept {
    if (enc == sign_encoding::twos_complement || in.size() != frame_size)
        return codec::decode_at<maneuver>(codec::deferred<Deferred>(in).data(), in.size());
    std::array<std::uint8_t, frame_size> copy{};
    for (std::size_t i = 0; i < frame_size; ++i) copy[i] = in[i];
    impl::convert_signed<false, Deferred>(copy.data());
    return codec::decode_at<maneuver>(codec::deferred<Deferred>(copy).data(), copy.size());
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire::navbot
