// Status to units with the double helpers: a BuWizz3 status report and the
// OSP battery's voltage, current and SOC answers (either scale).
#include <robowire/buwizz3/status.hpp>
#include <robowire/buwizz3/units.hpp>
#include <robowire/osp/units.hpp>

#include <cstring>

#include "harness.hpp"

namespace bw = robowire::buwizz3;
namespace osp = robowire::osp;

// The value's bits to the sink (no conversion routine).
inline void out_double(double d) {
    std::uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    sink = static_cast<std::uint32_t>(u);
    sink = static_cast<std::uint32_t>(u >> 32);
}

ENTRY void units_buwizz3(std::span<const std::uint8_t> b) {
    const auto s = robowire::decode<bw::status>(b);
    if (!s) return;
    out_double(bw::battery_volts(*s));
    out_double(bw::motor_amps(*s, 0));
    out_double(bw::accel_milli_g(s->accel_raw[2]));
}
ENTRY void units_osp(std::span<const std::uint8_t> b, osp::scale sc) {
    if (const auto v = robowire::decode<osp::obp1::voltage>(b)) out_double(osp::obp1::volts(*v, sc));
    if (const auto c = robowire::decode<osp::obp1::current>(b)) out_double(osp::obp1::amps(*c, sc));
    if (const auto s = robowire::decode<osp::obp1::soc>(b)) out_double(osp::obp1::soc_percent(*s, sc));
}

int main() {
    const auto in = read_input<160>();
    units_buwizz3(std::span(in).first(size_in(129)));
    units_osp(std::span(in).first(size_in(10)), (in[0] & 1) ? osp::scale::published_firmware : osp::scale::document);
    return 0;
}
