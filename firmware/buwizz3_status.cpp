// BuWizz3: the status report decode alone (what an app reading telemetry links).
#include <robowire/buwizz3/status.hpp>

#include "harness.hpp"

namespace bw = robowire::buwizz3;

ENTRY void buwizz3_decode_status(std::span<const std::uint8_t> b) {
    const auto s = robowire::decode<bw::status>(b);
    if (s) sink = static_cast<std::uint32_t>(s->pu_motors[0].position + s->accel_raw[2] + s->battery_voltage_raw);
    else sink = static_cast<std::uint32_t>(s.code());
}

int main() {
    const auto in = read_input<160>();
    buwizz3_decode_status(std::span(in).first(size_in(129)));
    return 0;
}
