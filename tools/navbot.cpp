// NAVBOT-ES02: 20-byte frames, from navbot::message.
#include "describe.hpp"

namespace robowire::cli {
namespace {
namespace nb = robowire::navbot;

// Signed channels read sign-magnitude (as the protocol document's samples write them).
std::vector<std::string> sign_magnitude_notes(std::span<const std::uint8_t> in) {
    std::vector<std::string> notes;
    if (in.size() != nb::frame_size || in[2] != nb::command::maneuver) return notes;
    robowire::for_each_field<nb::maneuver>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if constexpr (F::kind == wire_kind::i8) {
            const std::uint8_t b = in[f.offset];
            if (b < 0x80) return;
            const int twos = static_cast<int>(static_cast<std::int8_t>(b));
            const int sm = -static_cast<int>(b & 0x7F);
            notes.push_back(std::string(f.name) + " at byte " + std::to_string(f.offset) + " is " + hex2(b) + " = " +
                            std::to_string(twos) + " (two's complement, what the robot reads); in the sign-magnitude "
                            "spelling of the protocol document's samples " + hex2(b) + " = " + std::to_string(sm));
        }
    });
    return notes;
}

outcome decode(std::span<const std::uint8_t> in, direction) {
    const auto r = nb::decode_frame(in);
    if (!r) {
        outcome o = failure(exit_bad_input, describe_decode_error<nb::message>(in, r.error()));
        if (r.code() == errc::too_long || r.code() == errc::too_short) o.error += " (" + std::string(nb::length_error_text(in.size())) + ")";
        o.hints = sign_magnitude_notes(in);
        return o;
    }
    outcome o = outcome_of(*r);
    o.hints = sign_magnitude_notes(in);
    if (const auto* f = std::get_if<nb::frame>(&*r); f && f->command == nb::command::json) {
        std::string text;
        for (const std::uint8_t b : f->payload) {
            if (b == 0) break;
            text += static_cast<char>(b);
        }
        for (node& c : o.fields.children)
            if (c.key == "payload") c.payload_text = text;
    }
    return o;
}

std::string list(bool fields) {
    std::string out = "navbot (BLE; 20-byte frames: 55 AA command remaining 00, 15 payload bytes)\n";
    list_variant<nb::message>(out, fields);
    return out;
}

outcome encode(std::string_view message, const std::vector<std::pair<std::string, std::string>>& values) {
    if (auto o = encode_in<nb::message>(message, values)) return *o;
    return failure(exit_usage, "unknown message " + std::string(message) + " (robowire list navbot)");
}
}  // namespace

const protocol& navbot_protocol() {
    static const protocol p{"navbot", "BLE; 20-byte frames", false, list, decode, encode};
    return p;
}

}  // namespace robowire::cli
