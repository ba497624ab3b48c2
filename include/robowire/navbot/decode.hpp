// robowire/navbot/decode.hpp - decode any NAVBOT frame into a variant.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <variant>

#include "../core/fields.hpp"
#include "frame.hpp"
#include "maneuver.hpp"

namespace robowire::navbot {

// A maneuver (command 0x10, single frame), or any other frame as is (JSON
// and Wi-Fi fragments: feed them to a reassembler). A message added here is
// decoded by decode_frame with no other edit: its table's fixed command byte
// (offset 2) picks it.
using message = std::variant<maneuver, frame>;

namespace impl::inline ROBOWIRE_MODE_NAMESPACE {
// The fixed command byte (offset 2) of M's table; -1: none.
template <class M>
constexpr int command_of() noexcept {
    for (const auto& b : table_v<M>.fixed)
        if (b.offset == 2) return b.value;
    return -1;
}
// Index of the alternative with no fixed command byte: the frame that takes
// every command no other alternative claims. Exactly one.
template <class Message, std::size_t... I>
constexpr std::size_t any_command_index(std::index_sequence<I...>) noexcept {
    constexpr bool keyless[] = {(command_of<std::variant_alternative_t<I, Message>>() < 0)...};
    static_assert((0 + ... + keyless[I]) == 1,
                  "navbot::decode_frame: exactly one alternative (the frame) may have no fixed command byte");
    std::size_t index = 0;
    while (!keyless[index]) ++index;
    return index;
}
template <class Message>
inline constexpr std::size_t any_command_index_v =
    any_command_index<Message>(std::make_index_sequence<std::variant_size_v<Message>>{});

// The frame f (decoded from `in`) as alternative I of Message if its command is
// I's, else as the next alternatives would take it; the frame itself when none
// does. One compare with a constant per alternative. (`in` by reference: a
// span passed on by value is copied through the stack first, 8 more bytes of
// Cortex-M code.)
template <class Message, std::size_t I, class Frame>
ROBOWIRE_ALWAYS_INLINE constexpr result<Message> decode_command(const Frame& f,
                                                                const std::span<const std::uint8_t>& in) noexcept {
    constexpr std::size_t any = any_command_index_v<Message>;
    if constexpr (I == std::variant_size_v<Message>) {
        return result<Message>(std::in_place, f);  // built in place: no Message temporary on the stack
    } else {
        if constexpr (I != any) {
            using alternative = std::variant_alternative_t<I, Message>;
            if (f.command == command_of<alternative>()) {
                const auto m = codec::decode_at<alternative>(in.data(), in.size());
                if (!m) return codec::unchecked_error(m);
                return result<Message>(std::in_place, *m);
            }
        }
        return decode_command<Message, I + 1>(f, in);
    }
}
}  // namespace impl::inline ROBOWIRE_MODE_NAMESPACE

// Decodes one 20-byte frame: as the alternative whose fixed command byte
// matches, else as the frame. Signed maneuver channels: two's complement.
// Length errors: too_short / too_long (length_error_text explains them).
// (A template, so that nothing is instantiated in a translation unit that does not call it.)
inline namespace ROBOWIRE_MODE_NAMESPACE {
template <class Message = message>
[[nodiscard]] constexpr result<Message> decode_frame(std::span<const std::uint8_t> in) noexcept {
    const auto f =
        codec::decode_at<std::variant_alternative_t<impl::any_command_index_v<Message>, Message>>(in.data(), in.size());
    if (!f) return codec::unchecked_error(f);
    return impl::decode_command<Message, 0>(*f, in);
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

// describe_error for a NAVBOT error (decode_frame, reassembler::push of
// frame bytes): the line of the message whose command byte `in` carries, the
// frame's for every command no message claims ("frame.remaining: frame out
// of sequence at byte 3"); the frame's too when `in` does not reach the
// command. Pass the input the error came from; cut to fit `buf`.
template <class Message = message>
constexpr std::string_view describe_error(const error& e, std::span<const std::uint8_t> in,
                                          std::span<char> buf) noexcept {
    if (in.size() < 3) return robowire::describe_error<frame>(e, buf);
    return codec::describe_keyed_error<Message, 2>(e, in, buf);
}

}  // namespace robowire::navbot
