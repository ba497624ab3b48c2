// NAVBOT frames: decode_frame, maneuver in both sign encodings, re-encode;
// check_reserved agrees with the reserved bytes.
#include <robowire/navbot.hpp>

#include "common.hpp"

FUZZ_STRUCTURE_AWARE(robowire::navbot::message)

namespace {
// A strict receiver: check_reserved<M> names the first byte
// that M reserves and the input has not zero (a byte by byte reference),
// else gives the input's size.
template <class M>
void check_strict(std::span<const std::uint8_t> in) {
    const auto strict = robowire::check_reserved<M>(in);
    fuzz::check_text(strict);
    constexpr auto reserved = robowire::reserved_bytes<M>();
    std::size_t first = in.size();
    for (std::size_t i = 0; i < in.size() && i < reserved.size(); ++i)
        if (reserved[i] && in[i] != 0) {
            first = i;
            break;
        }
    if (first == in.size()) FUZZ_CHECK(strict.has_value() && *strict == in.size());
    else FUZZ_CHECK(!strict && strict.error().code == robowire::errc::reserved_not_zero && strict.error().offset == first);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace nb = robowire::navbot;
    const std::span<const std::uint8_t> in(data, size);
    const auto m = nb::decode_frame(in);
    fuzz::check_text(m);
    fuzz::check_decode_into<nb::message>(in);
    if (!m) {
        FUZZ_CHECK(m.error().offset <= size);
    } else if (const auto* man = std::get_if<nb::maneuver>(&*m)) {
        const auto wire = robowire::encode(*man);
        FUZZ_CHECK(wire.has_value());
        FUZZ_CHECK(fuzz::same_bytes(*wire, fuzz::without_reserved<nb::maneuver>(in)));
        // Two's complement is what decode_maneuver and nb::encode default to: robowire's own codec.
        const auto twos = nb::decode_maneuver(in);
        FUZZ_CHECK(twos.has_value() && *twos == *man);
        const auto twos_wire = nb::encode(*man);
        FUZZ_CHECK(twos_wire.has_value() && fuzz::same_bytes(*twos_wire, *wire));
    } else {
        const auto wire = robowire::encode(std::get<nb::frame>(*m));
        FUZZ_CHECK(wire.has_value());
        FUZZ_CHECK(fuzz::same_bytes(*wire, fuzz::without_reserved<nb::frame>(in)));
    }
    check_strict<nb::frame>(in);
    if (m && std::holds_alternative<nb::maneuver>(*m)) check_strict<nb::maneuver>(in);
    // Sign-magnitude: a decoded value re-encodes to a frame that decodes to the same value.
    const auto sm = nb::decode_maneuver(in, nb::sign_encoding::sign_magnitude);
    fuzz::check_text(sm);
    if (sm) {
        const auto wire = nb::encode(*sm, nb::sign_encoding::sign_magnitude);
        FUZZ_CHECK(wire.has_value());
        const auto back = nb::decode_maneuver(*wire, nb::sign_encoding::sign_magnitude);
        FUZZ_CHECK(back.has_value() && *back == *sm);
    }
    return 0;
}
