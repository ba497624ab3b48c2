// Texts from the tables shared by the command-line tool and the Python
// package: byte spellings, accepted lengths, NAVBOT sign-magnitude notes.
// robowire headers and the standard library only.
#pragma once

#include <robowire/core/fields.hpp>
#include <robowire/navbot.hpp>
#include <robowire/reflect.hpp>

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace robowire::tools {

// "0x5C"
inline std::string hex2(unsigned v) {
    char b[8];
    std::snprintf(b, sizeof b, "0x%02X", v & 0xFFu);
    return b;
}

// Every input length M's decoder accepts: "1, 13 or 17 bytes", "54 or 68..129 bytes"
// (robowire::describe_lengths: the words of describe_error's length errors).
template <class M>
std::string valid_lengths() {
    char buf[96];
    return std::string(robowire::describe_lengths<M>(buf));
}

// NAVBOT maneuver channels with bit 7 set, also read sign-magnitude (as the
// protocol document's samples write them): one note per such channel.
inline std::vector<std::string> sign_magnitude_notes(std::span<const std::uint8_t> in) {
    namespace nb = robowire::navbot;
    std::vector<std::string> notes;
    if (in.size() != nb::frame_size || in[2] != nb::command::maneuver) return notes;
    robowire::for_each_field<nb::maneuver>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if constexpr (F::kind == wire_kind::i8) {
            const std::uint8_t b = in[f.offset];
            if (b < 0x80) return;
            const int twos = static_cast<int>(static_cast<std::int8_t>(b));
            const int sm = -static_cast<int>(b & 0x7F);
            notes.push_back(std::string(f.name) + " at byte " + std::to_string(f.offset) + " is " + hex2(b) + " = " +
                            std::to_string(twos) +
                            " (two's complement, what the robot reads); in the sign-magnitude "
                            "spelling of the protocol document's samples " +
                            hex2(b) + " = " + std::to_string(sm));
        }
    });
    return notes;
}

}  // namespace robowire::tools
