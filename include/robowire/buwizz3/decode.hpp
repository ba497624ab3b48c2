// robowire/buwizz3/decode.hpp - decode any command or notification into a variant.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <span>
#include <variant>

#include "../core/dispatch.hpp"
#include "commands.hpp"
#include "status.hpp"

namespace robowire::buwizz3 {

// Every device -> host notification (application characteristic).
using notification = std::variant<status, accel_calibration, charger_settings>;

inline namespace ROBOWIRE_MODE_NAMESPACE {
// Decodes a packet written to the device; unknown_message (offset 0) for an unknown command byte.
// (A template, so that nothing is instantiated in a translation unit that does not call it.)
template <class Command = command>
[[nodiscard]] ROBOWIRE_SPEED_INLINE constexpr result<Command> decode_command(
    std::span<const std::uint8_t> in) noexcept {
    return decode_variant<Command, 0>(in);
}
// Decodes a notification from the device; unknown_message (offset 0) for an unknown command byte.
template <class Notification = notification>
[[nodiscard]] ROBOWIRE_SPEED_INLINE constexpr result<Notification> decode_notification(
    std::span<const std::uint8_t> in) noexcept {
    return decode_variant<Notification, 0>(in);
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire::buwizz3
