// robowire/buwizz3/decode.hpp - decode any command or notification into a variant.
#pragma once

#include <span>
#include <variant>

#include "../core/dispatch.hpp"
#include "commands.hpp"
#include "status.hpp"

namespace robowire::buwizz3 {

// Every host -> device command (application characteristic).
using command = std::variant<set_device_name, set_motion_wakeup, set_accel_calibration, read_accel_calibration,
                             set_motor_data, set_motor_data_extended, set_data_period, set_ramp_rates,
                             set_motor_timeout, activate_watchdog, set_led_status, set_accel_lpf, set_current_limits,
                             set_uart_baudrate, set_pu_port_function, enable_pid_reporting, set_servo_reference,
                             set_pid_parameters, activate_shelf_mode, check_charger_settings>;

// Every device -> host notification (application characteristic).
using notification = std::variant<status, accel_calibration, charger_settings>;

// Decodes a packet written to the device; unknown_message (offset 0) for an unknown command byte.
// (A template, so that nothing is instantiated in a translation unit that does not call it.)
template <class Command = command>
[[nodiscard]] constexpr result<Command> decode_command(std::span<const std::uint8_t> in) noexcept {
    return decode_variant<Command, 0>(in);
}
// Decodes a notification from the device; unknown_message (offset 0) for an unknown command byte.
template <class Notification = notification>
[[nodiscard]] constexpr result<Notification> decode_notification(std::span<const std::uint8_t> in) noexcept {
    return decode_variant<Notification, 0>(in);
}

}  // namespace robowire::buwizz3
