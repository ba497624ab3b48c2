// NAVBOT-ES02: maneuver encode/decode (both sign encodings), frame dispatch,
// fragmenter and reassembler.
#include <robowire/navbot.hpp>

#include "harness.hpp"

namespace nb = robowire::navbot;

ENTRY void navbot_encode_maneuver(const std::uint8_t* b) {
    // every channel from the input (an app's values: checked by encode)
    const nb::maneuver m{static_cast<std::int8_t>(b[0]), b[1], static_cast<std::int8_t>(b[2]),
                         static_cast<std::int8_t>(b[3]), static_cast<nb::switch_a>(b[4]),
                         static_cast<nb::switch_b>(b[5]), static_cast<nb::switch_c>(b[6]),
                         static_cast<nb::switch_d>(b[7]), static_cast<std::int8_t>(b[8]),
                         static_cast<std::int8_t>(b[9])};
    const auto w = nb::encode(m, (b[10] & 1) ? nb::sign_encoding::sign_magnitude : nb::sign_encoding::twos_complement);
    if (w) out(*w);
}
ENTRY void navbot_decode_frame(const std::uint8_t* p, std::size_t n) {
    const std::span b(p, n);
    const auto m = nb::decode_frame(b);
    if (m) out(std::span(reinterpret_cast<const std::uint8_t*>(&*m), sizeof *m));  // every field
    else sink = static_cast<std::uint32_t>(m.code());
    const auto sm = nb::decode_maneuver(b, nb::sign_encoding::sign_magnitude);
    if (sm) out(std::span(reinterpret_cast<const std::uint8_t*>(&*sm), sizeof *sm));
}
nb::reassembler<120> reassembler_state;
ENTRY void navbot_reassemble(const std::uint8_t* p, std::size_t n) {
    const auto st = reassembler_state.push({p, n});
    if (st && *st == nb::reassembly::complete) out(reassembler_state.payload());
}
ENTRY void navbot_fragment(const std::uint8_t* p, std::size_t n) {
    const auto frames = nb::make_frames(nb::command::json, {p, n});
    if (!frames) return;
    for (const auto& f : *frames) out(f);
}

int main() {
    const auto in = read_input<160>();
    const std::size_t n = size_in(40);
    navbot_encode_maneuver(in.data());
    navbot_decode_frame(in.data(), n);
    navbot_reassemble(in.data(), n);
    navbot_fragment(in.data(), size_in(120));
    return 0;
}
