// Differential: robowire's OSP decoder against the hand-written ones of
// bench/handwritten/osp.hpp (no table shared). First byte, bit 0: 0 a frame
// (osp::decode against hw_decode_any and careful_decode_any: the same
// outcome, error code and offset, the same frame() and field values), 1 a
// message made from the rest (near-valid: an enumeration out of range now
// and then), encoded by robowire and read back by the hand-written decoder
// (the same key and values; an encode error only for a code the decoder
// refuses too). Both: the unit helpers of every decoded or made message
// against the document's formulas, written out here (osp/units.hpp's scales).
#include <robowire/ext/fuzz.hpp>
#include <robowire/osp.hpp>

#include <cstring>
#include <type_traits>

#include "../bench/handwritten/osp.hpp"
#include "common.hpp"

namespace {
namespace osp = robowire::osp;
bool same_error(robowire::error e, hw::error h) {
    return static_cast<unsigned>(e.code) == (h & 0xFFu) && (e.code == robowire::errc::ok || e.offset == h >> 8);
}
// A message holds what the hand-written decoder read; its key is DEV and CMD.
bool same_message(const osp::message& msg, const hw_msg& h) {
    return std::visit(
        [&](const auto& m) -> bool {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, osp::generic::device_type>) {
                return static_cast<std::uint8_t>(m.type) == h.b;
            } else if constexpr (std::is_same_v<M, osp::arm1::set_angle>) {
                return m.joint == h.b && m.angle == h.a;
            } else if constexpr (std::is_same_v<M, osp::obp1::soc>) {
                return m.soc_raw == h.a;
            } else if constexpr (std::is_same_v<M, osp::obp1::voltage>) {
                return m.centivolts == static_cast<std::int16_t>(h.a);
            } else if constexpr (std::is_same_v<M, osp::obp1::current>) {
                return m.milliamps == static_cast<std::int16_t>(h.a);
            } else if constexpr (std::is_same_v<M, osp::obp1::status>) {
                return static_cast<std::uint8_t>(m.state) == h.b && m.flags == h.a;
            } else {
                return true;  // the requests: no fields
            }
        },
        msg);
}
// DEV and CMD of each alternative, from its encoding.
std::uint16_t key_of(const osp::message& m) {
    const auto f = robowire::encode(m).value();
    return static_cast<std::uint16_t>(f[2] << 8 | f[3]);
}

// The unit helpers, integer and double forms, in both scales, against the
// formulas of the document and of the published firmware.
void check_units(const osp::message& msg) {
    using osp::scale;
    if (const auto* v = std::get_if<osp::obp1::voltage>(&msg)) {
        const int cv = v->centivolts;
        FUZZ_CHECK(osp::obp1::millivolts(*v) == cv * 10 && osp::obp1::millivolts(*v, scale::published_firmware) == cv);
        FUZZ_CHECK(osp::obp1::volts(*v) == cv / 100.0 && osp::obp1::volts(*v, scale::published_firmware) == cv / 1000.0);
    } else if (const auto* c = std::get_if<osp::obp1::current>(&msg)) {
        FUZZ_CHECK(osp::obp1::milliamps(*c) == c->milliamps && osp::obp1::amps(*c) == c->milliamps / 1000.0);
    } else if (const auto* so = std::get_if<osp::obp1::soc>(&msg)) {
        const std::uint32_t raw = so->soc_raw;
        FUZZ_CHECK(osp::obp1::soc_basis_points(*so) == (raw * 10000u + 32767u) / 65535u);  // to nearest
        FUZZ_CHECK(osp::obp1::soc_basis_points(*so, scale::published_firmware) == raw);
    } else if (const auto* a = std::get_if<osp::arm1::set_angle>(&msg)) {
        const std::int32_t doc = a->angle, pub = a->angle >= 0x8000 ? a->angle - 0x10000 : a->angle;
        FUZZ_CHECK(osp::arm1::angle_count(a->angle) == doc && osp::arm1::angle_count(a->angle, scale::published_firmware) == pub);
    }
}

void check_frame(std::span<const std::uint8_t> in) {
    const auto r = osp::decode(in);
    hw_msg h{};
    const auto e = hw_decode_any(in.data(), in.size(), h);
    FUZZ_CHECK(same_error(r ? robowire::error{} : r.error(), e));
    hw_msg c{};
    FUZZ_CHECK(careful_decode_any(in.data(), in.size(), c) == e);
    // frame(): whenever the markers and the length are right (also for an unknown key or a bad field)
    const bool framed = e == hw::good || (e & 0xFF) == hw::unknown_message || (e & 0xFF) == hw::invalid_enum;
    FUZZ_CHECK(r.frame().has_value() == framed);
    if (framed) {
        const auto& f = *r.frame();
        FUZZ_CHECK(f.device == h.dev && f.command == h.cmd && std::memcmp(f.params.data(), h.p, 4) == 0);
        FUZZ_CHECK(c.dev == h.dev && c.cmd == h.cmd && std::memcmp(c.p, h.p, 4) == 0);
    }
    if (r) {
        FUZZ_CHECK(key_of(*r) == (h.dev << 8 | h.cmd));
        FUZZ_CHECK(same_message(*r, h) && same_message(*r, c));
        check_units(*r);
    }
}

void check_message(robowire::fuzz::source& s) {
    const auto m = robowire::fuzz::make<osp::message>(s, robowire::fuzz::out_of_range{32});
    const auto r = osp::encode(m);
    if (!r) {  // only an enumeration out of its range: P1
        FUZZ_CHECK(r.error().code == robowire::errc::invalid_enum && r.error().offset == 4);
        const auto* t = std::get_if<osp::generic::device_type>(&m);
        const auto* st = std::get_if<osp::obp1::status>(&m);
        FUZZ_CHECK((t && static_cast<std::uint8_t>(t->type) > 3) || (st && static_cast<std::uint8_t>(st->state) > 4));
        return;
    }
    hw_msg h{};
    FUZZ_CHECK(hw_decode_any(r->data(), r->size(), h) == hw::good);
    FUZZ_CHECK(std::memcmp(h.p, r->data() + 4, 4) == 0);
    FUZZ_CHECK(same_message(m, h));
    check_units(m);
    // the parameters the message does not use are zero
    const auto used = std::visit(
        [](const auto& x) -> unsigned {
            using M = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<M, osp::generic::device_type>) return 1;
            else if constexpr (std::is_same_v<M, osp::arm1::set_angle>) return 3;
            else if constexpr (std::is_same_v<M, osp::obp1::soc> || std::is_same_v<M, osp::obp1::voltage> ||
                               std::is_same_v<M, osp::obp1::current> || std::is_same_v<M, osp::obp1::status>)
                return 2;
            else return 0;
        },
        m);
    for (unsigned i = used; i < 4; ++i) FUZZ_CHECK(h.p[i] == 0);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    if (data[0] & 1) {
        robowire::fuzz::source s{data + 1, size - 1};
        check_message(s);
    } else {
        check_frame({data + 1, size - 1});
    }
    return 0;
}
