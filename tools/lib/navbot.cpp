// NAVBOT-ES02: 20-byte frames, from navbot::message.
#include <robowire/navbot/protocol.hpp>

#include "describe.hpp"
#include "emit.hpp"

namespace robowire::tools {
namespace {
namespace nb = robowire::navbot;

outcome decode(std::span<const std::uint8_t> in, direction, output& out, const record_meta& meta) {
    const auto r = nb::decode_frame(in);
    if (!r) {
        char buf[160];
        outcome o = decode_failure<nb::message>(nb::describe_error(r.error(), in, buf), in, r.error());
        if (r.code() == errc::too_long || r.code() == errc::too_short)
            o.hints.back() += " (" + std::string(nb::length_error_text(in.size())) + ")";
        for (auto& n : sign_magnitude_notes(in)) o.hints.push_back(std::move(n));
        return o;
    }
    emit::variant_message(out, meta, "navbot", *r, sign_magnitude_notes(in));
    return {};
}

std::string list(bool fields) {
    std::string out = "navbot (BLE; 20-byte frames: 55 AA command remaining 00, 15 payload bytes)\n";
    list_variant<nb::messages::to_device>(out, fields);
    return out;
}

outcome encode(std::string_view message, const std::vector<std::pair<std::string, std::string>>& values) {
    if (auto o = encode_in<nb::messages::to_device>(message, values)) return *o;
    return failure(exit_usage, "unknown message " + shorten(message) + " (robowire list navbot)");
}
}  // namespace

const protocol& navbot_protocol() {
    static const protocol p{robowire::navbot::descriptor.name,
                            robowire::navbot::descriptor.summary,
                            robowire::navbot::descriptor.has_directions,
                            list,
                            decode,
                            encode};
    return p;
}

}  // namespace robowire::tools
