// robowire/navbot/decode.hpp - decode any NAVBOT frame into a variant.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <span>
#include <variant>

#include "frame.hpp"
#include "maneuver.hpp"

namespace robowire::navbot {

// A maneuver (command 0x10, single frame), or any other frame as is (JSON
// and Wi-Fi fragments: feed them to a reassembler).
using message = std::variant<maneuver, frame>;

// Decodes one 20-byte frame. Signed maneuver channels: two's complement.
// Length errors: too_short / too_long (length_error_text explains them).
// (A template, so that nothing is instantiated in a translation unit that does not call it.)
inline namespace ROBOWIRE_MODE_NAMESPACE {
template <class Message = message>
[[nodiscard]] constexpr result<Message> decode_frame(std::span<const std::uint8_t> in) noexcept {
    using maneuver_t = std::variant_alternative_t<0, Message>;
    using frame_t = std::variant_alternative_t<1, Message>;
    const auto f = robowire::decode<frame_t>(in);
    if (!f) return codec::unchecked_error(f);
    if (f->command == command::maneuver) {
        const auto m = robowire::decode<maneuver_t>(in);
        if (!m) return codec::unchecked_error(m);
        return Message{*m};
    }
    return Message{*f};
}
}  // inline namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire::navbot
