// BuWizz3: every command decoded (as a device or sniffer would) and encoded
// (as a host would), every notification decoded.
#include <robowire/buwizz3.hpp>

#include "harness.hpp"

namespace bw = robowire::buwizz3;

ENTRY void buwizz3_decode_command(const std::uint8_t* p, std::size_t n) {
    const auto c = bw::decode_command({p, n});
    if (c) out(std::span(reinterpret_cast<const std::uint8_t*>(&*c), sizeof *c));  // every field
    else sink = static_cast<std::uint32_t>(c.code());
}
ENTRY void buwizz3_decode_notification(const std::uint8_t* p, std::size_t n) {
    const auto r = bw::decode_notification({p, n});
    if (r) out(std::span(reinterpret_cast<const std::uint8_t*>(&*r), sizeof *r));  // every field
    else sink = static_cast<std::uint32_t>(r.code());
}
ENTRY void buwizz3_encode_command(const std::uint8_t* p, std::size_t n) {
    // a command built from input bytes, then encoded
    const auto c = bw::decode_command({p, n});
    if (!c) return;
    const auto w = robowire::encode(*c);
    if (w) out(*w);
}
ENTRY void buwizz3_encode_drive(const std::uint8_t* b) {
    // every field from the input (an app's values: checked by encode)
    bw::set_motor_data_extended m{};
    for (std::size_t i = 0; i < 4; ++i) m.reference[i] = static_cast<std::int32_t>(b[i] * 1000);
    m.power = {static_cast<std::int8_t>(b[4]), static_cast<std::int8_t>(b[5])};
    m.brake_flags = b[6];
    m.lut_disable_flags = b[7];
    const auto w = robowire::encode(m);
    if (w) out(*w);
}

int main() {
    const auto in = read_input<160>();
    const std::size_t n = size_in(129);
    buwizz3_decode_command(in.data(), n);
    buwizz3_decode_notification(in.data(), n);
    buwizz3_encode_command(in.data(), n);
    buwizz3_encode_drive(in.data());
    return 0;
}
