// OSP: decode of any frame (dispatch), every encoder, the stream scanner, serve().
#include <robowire/osp.hpp>

#include "harness.hpp"

namespace osp = robowire::osp;

ENTRY void osp_decode(std::span<const std::uint8_t> b) {
    const auto m = osp::decode(b);
    sink = m ? static_cast<std::uint32_t>(m->index()) : static_cast<std::uint32_t>(m.code());
}
ENTRY void osp_encode(std::size_t which, std::uint16_t value) {
    osp::message m;
    switch (which % 11) {
    case 0: m = osp::generic::request_device_type{}; break;
    case 1: m = osp::generic::device_type{static_cast<osp::device_type>(value & 3)}; break;
    case 2: m = osp::arm1::set_angle{static_cast<std::uint8_t>(value), value}; break;
    case 3: m = osp::obp1::request_soc{}; break;
    case 4: m = osp::obp1::request_voltage{}; break;
    case 5: m = osp::obp1::request_current{}; break;
    case 6: m = osp::obp1::request_status{}; break;
    case 7: m = osp::obp1::soc{value}; break;
    case 8: m = osp::obp1::voltage{static_cast<std::int16_t>(value)}; break;
    case 9: m = osp::obp1::current{static_cast<std::int16_t>(value)}; break;
    default: m = osp::obp1::status{static_cast<osp::obp1::state>(value % 5), static_cast<std::uint8_t>(value)}; break;
    }
    const auto r = osp::encode(m);
    if (r) out(*r);
}
osp::scanner scanner_state;
ENTRY void osp_scan(std::span<const std::uint8_t> chunk) {
    scanner_state.feed(chunk, [](osp::scanner::frame_bytes f) { osp_decode(f); });
}
struct battery {
    osp::obp1::soc operator()(const osp::obp1::request_soc&) const { return {static_cast<std::uint16_t>(sink)}; }
    osp::obp1::voltage operator()(const osp::obp1::request_voltage&) const { return {static_cast<std::int16_t>(sink)}; }
};
ENTRY void osp_serve(std::span<const std::uint8_t> request) {
    const auto a = osp::serve(request, battery{});
    if (a && *a) out(**a);
}

int main() {
    const auto in = read_input<160>();
    const auto b = std::span(in).first(size_in(160));
    osp_decode(b);
    osp_encode(in[0], static_cast<std::uint16_t>(in[1] | in[2] << 8));
    osp_scan(b);
    osp_serve(b);
    return 0;
}
