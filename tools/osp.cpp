// OSP: 10-byte serial frames FF AA DEV CMD P1..P4 55 77, from osp::message.
#include "describe.hpp"

namespace robowire::cli {
namespace {
namespace osp = robowire::osp;

outcome decode(std::span<const std::uint8_t> in, direction) {
    const auto r = osp::decode(in);
    if (r) return outcome_of(*r);
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
    return failure(exit_usage, "unknown message " + std::string(message) + " (robowire list osp)");
}
}  // namespace

const protocol& osp_protocol() {
    static const protocol p{"osp", "serial; FF AA DEV CMD P1..P4 55 77", false, list, decode, encode};
    return p;
}

}  // namespace robowire::cli
