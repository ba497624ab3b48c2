// Status to units with the integer helpers (no floating point): a BuWizz3 status report and the
// OSP battery's voltage, current and SOC answers (either scale), and voltage and SOC back to raw.
#include <robowire/buwizz3/status.hpp>
#include <robowire/buwizz3/units.hpp>
#include <robowire/osp/units.hpp>

#include "harness.hpp"

namespace bw = robowire::buwizz3;
namespace osp = robowire::osp;

ENTRY void units_buwizz3(std::span<const std::uint8_t> b) {
    const auto s = robowire::decode<bw::status>(b);
    if (!s) return;
    sink = bw::battery_millivolts(*s);
    sink = bw::motor_milliamps(*s, 0);
    sink = static_cast<std::uint32_t>(bw::accel_micro_g(s->accel_raw[2]));
    sink = static_cast<std::uint32_t>(bw::accel_milli_g_rounded(s->accel_raw[0]));
}
ENTRY void units_osp(std::span<const std::uint8_t> b, osp::scale sc) {
    if (const auto v = robowire::decode<osp::obp1::voltage>(b)) sink = static_cast<std::uint32_t>(osp::obp1::millivolts(*v, sc));
    if (const auto c = robowire::decode<osp::obp1::current>(b)) sink = static_cast<std::uint32_t>(osp::obp1::milliamps(*c, sc));
    if (const auto s = robowire::decode<osp::obp1::soc>(b)) sink = osp::obp1::soc_basis_points(*s, sc);
}
// The other way: a battery's readings to raw values.
ENTRY void units_osp_raw(std::int32_t mv, std::uint16_t bp, osp::scale sc) {
    if (const auto v = osp::obp1::voltage_from_millivolts(mv, sc)) sink = static_cast<std::uint16_t>(*v);
    if (const auto s = osp::obp1::soc_from_basis_points(bp, sc)) sink = *s;
}

int main() {
    const auto in = read_input<160>();
    units_buwizz3(std::span(in).first(size_in(129)));
    const auto sc = (in[0] & 1) ? osp::scale::published_firmware : osp::scale::document;
    units_osp(std::span(in).first(size_in(10)), sc);
    units_osp_raw(static_cast<std::int32_t>(in[1] | in[2] << 8 | in[3] << 16 | in[4] << 24), static_cast<std::uint16_t>(in[5] | in[6] << 8), sc);
    return 0;
}
