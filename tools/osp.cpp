// OSP: 10-byte serial frames FF AA DEV CMD P1..P4 55 77, from osp::message.
#include "describe.hpp"
#include "emit.hpp"

namespace robowire::cli {
namespace {
namespace osp = robowire::osp;

// The message whose DEV and CMD (bytes 2 and 3) `in` carries: "status (DEV 02 CMD 14)",
// or "DEV 03 CMD 01 (no such message)"; empty when `in` is shorter than 4 bytes.
std::string message_of(std::span<const std::uint8_t> in) {
    if (in.size() < 4) return {};
    std::string name;
    for_each_alternative<osp::message>([&](auto t) {
        using M = typename decltype(t)::type;
        bool dev = false, cmd = false;
        for (const auto& b : robowire::table_v<M>.fixed) {
            if (b.offset == 2) dev = b.value == in[2];
            if (b.offset == 3) cmd = b.value == in[3];
        }
        if (name.empty() && dev && cmd) name = std::string(robowire::table_v<M>.name);
    });
    const std::string where = "DEV " + hex_of(in.subspan(2, 1)) + " CMD " + hex_of(in.subspan(3, 1));
    return name.empty() ? where + " (no such message)" : name + " (" + where + ")";
}

// "bad header byte at byte 1: 0xAB, expected 0xAA (frames are FF AA DEV CMD P1..P4 55 77); message status (DEV 02 CMD
// 14)"
std::string marker_error(std::span<const std::uint8_t> in, const robowire::error& e) {
    std::string s = std::string(robowire::to_string(e.code)) + " at byte " + std::to_string(e.offset);
    for (const auto& b : robowire::table_v<osp::frame>.fixed) {
        if (b.offset != e.offset || e.offset >= in.size()) continue;
        s += ": " + hex2(in[e.offset]) + ", expected " + hex2(b.value) + " (frames are FF AA DEV CMD P1..P4 55 77)";
    }
    if (const std::string m = message_of(in); !m.empty()) s += "; message " + m;
    return s;
}

outcome decode(std::span<const std::uint8_t> in, direction, output& out, const record_meta& meta) {
    const auto r = osp::decode(in);
    if (r) {
        static const std::vector<std::string> no_notes;
        emit::variant_message(out, meta, "osp", *r, no_notes);
        return {};
    }
    if (r.code() == errc::bad_header || r.code() == errc::bad_trailer)
        return failure(exit_bad_input, marker_error(in, r.error()));
    outcome o = failure(exit_bad_input, describe_decode_error<osp::message>(in, r.error()));
    if (const auto& f = r.frame()) {
        o.error += " (DEV " + hex_of(std::span<const std::uint8_t>(&f->device, 1)) + " CMD " +
                   hex_of(std::span<const std::uint8_t>(&f->command, 1)) + " params " + hex_of(f->params) + ")";
    }
    return o;
}

std::string list(bool fields) {
    std::string out = "osp (serial; FF AA DEV CMD P1..P4 55 77)\n";
    list_variant<osp::message>(out, fields);
    return out;
}

outcome encode(std::string_view message, const std::vector<std::pair<std::string, std::string>>& values) {
    if (auto o = encode_in<osp::message>(message, values)) return *o;
    return failure(exit_usage, "unknown message " + shorten(message) + " (robowire list osp)");
}
}  // namespace

const protocol& osp_protocol() {
    static const protocol p{"osp", "serial; FF AA DEV CMD P1..P4 55 77", false, list, decode, encode};
    return p;
}

}  // namespace robowire::cli
