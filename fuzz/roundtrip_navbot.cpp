// Structure-aware: NAVBOT maneuvers and frames made from the input
// (robowire::fuzz::make), encoded, decoded back. First byte: bit 6 the
// near-valid form (a field out of range now and then), and modulo 2 the message.
#include <robowire/ext/fuzz.hpp>
#include <robowire/navbot.hpp>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace nb = robowire::navbot;
    const bool near_valid = size > 0 && (data[0] & 0x40) != 0;
    robowire::fuzz::source s{data, size};
    auto m = near_valid ? robowire::fuzz::make<nb::message>(s, robowire::fuzz::out_of_range{})
                        : robowire::fuzz::make<nb::message>(s);
    if (!near_valid) FUZZ_CHECK(robowire::encode(m).has_value());  // make draws inside every range
    // A frame with the maneuver command decodes as a maneuver: another command keeps it a frame.
    if (auto* f = std::get_if<nb::frame>(&m); f && f->command == nb::command::maneuver) f->command = 0x11;
    fuzz::round_trip<fuzz::floats::none>(m, [](auto in) { return nb::decode_frame(in); });
    if (const auto* man = std::get_if<nb::maneuver>(&m)) {
        const auto sm = nb::encode(*man, nb::sign_encoding::sign_magnitude);
        if (sm) FUZZ_CHECK(nb::decode_maneuver(*sm, nb::sign_encoding::sign_magnitude).value() == *man);
    }
    return 0;
}
