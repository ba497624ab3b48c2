// Structure-aware: NAVBOT maneuvers and frames built from the input, encoded, decoded back.
#include <robowire/navbot.hpp>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace nb = robowire::navbot;
    fuzz::reader r{{data, size}};
    const std::size_t which = r.byte();
    auto m = fuzz::pick<nb::message>(which % std::variant_size_v<nb::message>, r);
    if (auto* f = std::get_if<nb::frame>(&m); f && f->command == nb::command::maneuver) f->command = 0x11;
    fuzz::round_trip(m, [](auto in) { return nb::decode_frame(in); });
    if (const auto* man = std::get_if<nb::maneuver>(&m)) {
        const auto sm = nb::encode(*man, nb::sign_encoding::sign_magnitude);
        if (sm) FUZZ_CHECK(nb::decode_maneuver(*sm, nb::sign_encoding::sign_magnitude).value() == *man);
    }
    return 0;
}
