// NAVBOT frames: decode_frame, maneuver in both sign encodings, re-encode.
#include <robowire/navbot.hpp>

#include "common.hpp"

FUZZ_STRUCTURE_AWARE(robowire::navbot::message)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace nb = robowire::navbot;
    const std::span<const std::uint8_t> in(data, size);
    const auto m = nb::decode_frame(in);
    if (!m) {
        FUZZ_CHECK(m.error().offset <= size);
    } else if (const auto* man = std::get_if<nb::maneuver>(&*m)) {
        const auto wire = robowire::encode(*man);
        FUZZ_CHECK(wire.has_value());
        FUZZ_CHECK(fuzz::same_bytes(*wire, fuzz::without_reserved<nb::maneuver>(in)));
    } else {
        const auto wire = robowire::encode(std::get<nb::frame>(*m));
        FUZZ_CHECK(wire.has_value());
        FUZZ_CHECK(fuzz::same_bytes(*wire, fuzz::without_reserved<nb::frame>(in)));
    }
    // Sign-magnitude: a decoded value re-encodes to a frame that decodes to the same value.
    const auto sm = nb::decode_maneuver(in, nb::sign_encoding::sign_magnitude);
    if (sm) {
        const auto wire = nb::encode(*sm, nb::sign_encoding::sign_magnitude);
        FUZZ_CHECK(wire.has_value());
        const auto back = nb::decode_maneuver(*wire, nb::sign_encoding::sign_magnitude);
        FUZZ_CHECK(back.has_value() && *back == *sm);
    }
    return 0;
}
