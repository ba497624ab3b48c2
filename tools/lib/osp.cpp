// OSP: 10-byte serial frames FF AA DEV CMD P1..P4 55 77, from osp::message.
#include <robowire/osp/protocol.hpp>

#include "describe.hpp"
#include "emit.hpp"

namespace robowire::tools {
namespace {
namespace osp = robowire::osp;

// A decode error: osp::describe_error's line ("voltage: bad trailer byte at
// byte 9"), with hints: a marker byte given and expected, the length given
// when it is not a frame's, the value at the offset, the frame's DEV, CMD
// and parameters.
outcome decode(std::span<const std::uint8_t> in, direction, output& out, const record_meta& meta) {
    const auto r = osp::decode(in);
    if (r) {
        static const std::vector<std::string> no_notes;
        emit::variant_message(out, meta, "osp", *r, no_notes);
        return {};
    }
    const robowire::error e = r.error();
    char buf[160];
    // the length wrong, and a start marker too or bytes 2 and 3 naming no message: no frame, and
    // no DEV and CMD to name; the result's line is osp::frame's ("frame: bad header byte at byte 0")
    const bool no_frame = in.size() != osp::frame_size &&
                          (e.code == errc::bad_header ||
                           robowire::alternative_by_key<osp::message, 2, 3>(in) == std::variant_size_v<osp::message>);
    outcome o =
        decode_failure<osp::message>(no_frame ? osp::describe_error(r, buf) : osp::describe_error(e, in, buf), in, e);
    if (e.code == errc::bad_header || e.code == errc::bad_trailer) {
        o.hints.clear();
        for (const auto& b : robowire::table_v<osp::frame>.fixed)
            if (b.offset == e.offset && e.offset < in.size())
                o.hints.push_back("byte " + std::to_string(e.offset) + " is " + hex2(in[e.offset]) + ", expected " +
                                  hex2(b.value) + " (frames are FF AA DEV CMD P1..P4 55 77)");
        if (in.size() != osp::frame_size)
            o.hints.push_back(plural(in.size(), "byte", "bytes") + " given (a frame is " + valid_lengths<osp::frame>() +
                              ")");
    }
    if (const auto& f = r.frame())
        o.hints.push_back("DEV " + hex_of(std::span<const std::uint8_t>(&f->device, 1)) + " CMD " +
                          hex_of(std::span<const std::uint8_t>(&f->command, 1)) + " params " + hex_of(f->params));
    return o;
}

std::string list(bool fields) {
    std::string out = "osp (serial; FF AA DEV CMD P1..P4 55 77)\n";
    list_variant<osp::messages::to_device>(out, fields);
    return out;
}

outcome encode(std::string_view message, const std::vector<std::pair<std::string, std::string>>& values) {
    if (auto o = encode_in<osp::messages::to_device>(message, values)) return *o;
    return failure(exit_usage, "unknown message " + shorten(message) + " (robowire list osp)");
}
}  // namespace

const protocol& osp_protocol() {
    static const protocol p{robowire::osp::descriptor.name,
                            robowire::osp::descriptor.summary,
                            robowire::osp::descriptor.has_directions,
                            list,
                            decode,
                            encode};
    return p;
}

}  // namespace robowire::tools
