// robowire/buwizz3/commands.hpp - every application command (host -> device)
// and the two command responses (device -> host). Byte 0 is the command;
// offsets below count it, as the document does. Values are raw wire values;
// units.hpp converts.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <cstdint>
#include <optional>
#include <variant>

#include "../core/decode.hpp"
#include "../core/encode.hpp"
#include "../core/flag_bits.hpp"
#include "../core/table.hpp"

namespace robowire::buwizz3 {

// 0x20: device name, up to 12 characters (NUL-padded on the wire).
struct set_device_name {
    text<12> name{};
    friend constexpr bool operator==(const set_device_name&, const set_device_name&) = default;
};

// 0x21: motion wake-up. idle_timeout_s >= 10 (default 300); shallow_sleep_timeout_s 0 disables.
struct set_motion_wakeup {
    bool enabled = false;
    std::uint32_t idle_timeout_s = 300;
    std::uint32_t shallow_sleep_timeout_s = 0;
    friend constexpr bool operator==(const set_motion_wakeup&, const set_motion_wakeup&) = default;
};

// 0x22: store the accelerometer calibration (6 factors).
struct set_accel_calibration {
    std::array<float, 6> factors{};
    friend constexpr bool operator==(const set_accel_calibration&, const set_accel_calibration&) = default;
};
// 0x23 request: read the calibration; the device answers with accel_calibration.
struct read_accel_calibration {
    friend constexpr bool operator==(const read_accel_calibration&, const read_accel_calibration&) = default;
};
// 0x23 response (notification).
struct accel_calibration {
    std::array<float, 6> factors{};
    friend constexpr bool operator==(const accel_calibration&, const accel_calibration&) = default;
};

// 0x30: motor power, ports 1-6: -127 (full backwards) .. 127 (full forwards).
// brake_flags / lut_disable_flags: bit n-1 for port n (bits 0-5).
struct set_motor_data {
    std::array<std::int8_t, 6> power{};
    std::uint8_t brake_flags = 0;
    std::uint8_t lut_disable_flags = 0;
    friend constexpr bool operator==(const set_motor_data&, const set_motor_data&) = default;
};

// 0x31: reference for ports 1-4 (meaning set by the port function: PWM,
// speed or position), power for ports 5-6 (-127..127), flags as in 0x30.
struct set_motor_data_extended {
    std::array<std::int32_t, 4> reference{};
    std::array<std::int8_t, 2> power{};
    std::uint8_t brake_flags = 0;
    std::uint8_t lut_disable_flags = 0;
    friend constexpr bool operator==(const set_motor_data_extended&, const set_motor_data_extended&) = default;
};

// 0x32: status report period, 20..255 ms (the device works in 5 ms steps).
struct set_data_period {
    std::uint8_t period_ms = 50;
    friend constexpr bool operator==(const set_data_period&, const set_data_period&) = default;
};

// 0x33: ramp rates per port, % per 128 ms; 0 disables (units: ramp_rate_from_seconds).
struct set_ramp_rates {
    std::array<std::uint8_t, 6> ramp_up{};
    std::array<std::uint8_t, 6> ramp_down{};
    friend constexpr bool operator==(const set_ramp_rates&, const set_ramp_rates&) = default;
};

// 0x34: what motors do on timeout: 0 brake, 1 coast, 2..254 coast to stop in mode-1 s.
struct set_motor_timeout {
    std::uint8_t mode = 0;
    friend constexpr bool operator==(const set_motor_timeout&, const set_motor_timeout&) = default;
};

// 0x35: connection watchdog, seconds; 0 disables. Each call resets the timer.
struct activate_watchdog {
    std::uint8_t timeout_s = 0;
    friend constexpr bool operator==(const activate_watchdog&, const activate_watchdog&) = default;
};

// 0x36: LED colours and blinking. No colours: back to the default behaviour
// (1 byte). Colours only: 13 bytes. Colours and blink: 17 bytes.
struct rgb {
    std::uint8_t r = 0, g = 0, b = 0;
    friend constexpr bool operator==(const rgb&, const rgb&) = default;
};
struct blink {
    std::uint8_t frequency_hz = 0;  // 0..15, 0 = LED off
    std::uint8_t duty = 0;          // 0..15: (duty + 1) / 16 of the period
    friend constexpr bool operator==(const blink&, const blink&) = default;
};
struct set_led_status {
    std::optional<std::array<rgb, 4>> colors{};            // ports 1-4
    std::optional<std::array<buwizz3::blink, 4>> blink{};  // needs colors
    friend constexpr bool operator==(const set_led_status&, const set_led_status&) = default;
};

// 0x37: accelerometer low-pass filter. Default hz_50.
enum class lpf_setting : std::uint8_t {
    hz_0_781 = 0b1000,
    hz_1_563 = 0b1001,
    hz_3_125 = 0b1010,
    hz_6_25 = 0b1011,
    hz_12_5 = 0b0000,
    hz_25 = 0b0001,
    hz_50 = 0b0010,
    hz_100 = 0b0011,
};
struct set_accel_lpf {
    lpf_setting setting = lpf_setting::hz_50;
    friend constexpr bool operator==(const set_accel_lpf&, const set_accel_lpf&) = default;
};

// 0x38: current limit per port, raw steps (30 mA per the document; units: current_limit_raw).
struct set_current_limits {
    std::array<std::uint8_t, 6> limit_raw{};
    friend constexpr bool operator==(const set_current_limits&, const set_current_limits&) = default;
};

// 0x40 0x10: UART baud rate of a channel.
struct set_uart_baudrate {
    std::uint8_t channel = 0;
    std::uint32_t baudrate = 115200;
    friend constexpr bool operator==(const set_uart_baudrate&, const set_uart_baudrate&) = default;
};

// PoweredUp port functions (0x50, and the mode of 0x53).
enum class port_function : std::uint8_t {
    generic_pwm = 0x00,
    pu_simple_pwm = 0x10,  // default
    pu_speed_servo = 0x14,
    pu_position_servo = 0x15,
    pu_absolute_position_servo = 0x16,
};

// 0x50: function of PU ports 1-4.
struct set_pu_port_function {
    std::array<port_function, 4> function{port_function::pu_simple_pwm, port_function::pu_simple_pwm,
                                          port_function::pu_simple_pwm, port_function::pu_simple_pwm};
    friend constexpr bool operator==(const set_pu_port_function&, const set_pu_port_function&) = default;
};

// 0x51: report the PID state of port 1..4 in the status; 0 disables.
struct enable_pid_reporting {
    std::uint8_t port = 0;
    friend constexpr bool operator==(const enable_pid_reporting&, const enable_pid_reporting&) = default;
};

// 0x52: servo reference (speed or position, by port mode), ports 1-4.
struct set_servo_reference {
    std::array<std::int32_t, 4> reference{};
    friend constexpr bool operator==(const set_servo_reference&, const set_servo_reference&) = default;
};

// 0x53: PID parameters of one PU port (port index 0..3, 0-based as the
// vendor's apps send it). Filter constants are K_LP values (units:
// k_lp_from_cutoff); presets in units.hpp.
struct set_pid_parameters {
    std::uint8_t port = 0;
    float out_lp = 0;
    float d_lp = 0;
    float speed_lp = 0;
    float kp = 0;
    float ki = 0;
    float kd = 0;
    float lim_i = 0;
    float reference_rate_limit = 0;                      // reference change per 10 ms step
    std::int8_t lim_out = 127;                           // 1..127
    std::int8_t deadband_out = 0;                        // 0..127
    std::int8_t deadband_out_boost = 0;                  // 0..127
    port_function mode = port_function::pu_speed_servo;  // must equal the port's function
    friend constexpr bool operator==(const set_pid_parameters&, const set_pid_parameters&) = default;
};

// 0xA1: shelf mode: disconnects the battery until a charger is connected.
struct activate_shelf_mode {
    friend constexpr bool operator==(const activate_shelf_mode&, const activate_shelf_mode&) = default;
};

// 0xAC request: check charger settings; the device answers with charger_settings.
struct check_charger_settings {
    friend constexpr bool operator==(const check_charger_settings&, const check_charger_settings&) = default;
};
// 0xAC response (notification): the layout after byte 0 is not documented: raw bytes.
struct charger_settings {
    bytes<128> data{};
    friend constexpr bool operator==(const charger_settings&, const charger_settings&) = default;
};

// ---- enum tables ----
constexpr auto enum_table_of(std::type_identity<lpf_setting>) {
    using E = lpf_setting;
    return std::array<enum_entry<E>, 8>{{{E::hz_0_781, "hz_0_781"},
                                         {E::hz_1_563, "hz_1_563"},
                                         {E::hz_3_125, "hz_3_125"},
                                         {E::hz_6_25, "hz_6_25"},
                                         {E::hz_12_5, "hz_12_5"},
                                         {E::hz_25, "hz_25"},
                                         {E::hz_50, "hz_50"},
                                         {E::hz_100, "hz_100"}}};
}
constexpr auto enum_table_of(std::type_identity<port_function>) {
    using E = port_function;
    return std::array<enum_entry<E>, 5>{{{E::generic_pwm, "generic_pwm"},
                                         {E::pu_simple_pwm, "pu_simple_pwm"},
                                         {E::pu_speed_servo, "pu_speed_servo"},
                                         {E::pu_position_servo, "pu_position_servo"},
                                         {E::pu_absolute_position_servo, "pu_absolute_position_servo"}}};
}

// ---- tables ----
namespace impl {
constexpr fixed_byte cmd(std::uint8_t c) noexcept { return {0, c, errc::bad_command}; }
inline constexpr range motor_power{-127, 127};
inline constexpr range port_flags{0, 0x3F};
}  // namespace impl

constexpr auto table_of(std::type_identity<set_device_name>) {
    using M = set_device_name;
    return make_table<M>("set_device_name", {impl::cmd(0x20)}, field{"name", &M::name, 1, wire::text{}});
}
constexpr auto table_of(std::type_identity<set_motion_wakeup>) {
    using M = set_motion_wakeup;
    return make_table<M>(
        "set_motion_wakeup", {impl::cmd(0x21)}, field{"enabled", &M::enabled, 1, wire::u8{}},
        field{"idle_timeout_s", &M::idle_timeout_s, 2, wire::u32le{}, range{10, 0xFFFFFFFF}, unit{"s"}},
        field{"shallow_sleep_timeout_s", &M::shallow_sleep_timeout_s, 6, wire::u32le{}, unit{"s"}});
}
constexpr auto table_of(std::type_identity<set_accel_calibration>) {
    using M = set_accel_calibration;
    return make_table<M>("set_accel_calibration", {impl::cmd(0x22)}, field{"factors", &M::factors, 1, wire::f32le{}});
}
constexpr auto table_of(std::type_identity<read_accel_calibration>) {
    return make_table<read_accel_calibration>("read_accel_calibration", {impl::cmd(0x23)});
}
constexpr auto table_of(std::type_identity<accel_calibration>) {
    using M = accel_calibration;
    return make_table<M>("accel_calibration", {impl::cmd(0x23)}, field{"factors", &M::factors, 1, wire::f32le{}});
}
constexpr auto table_of(std::type_identity<set_motor_data>) {
    using M = set_motor_data;
    return make_table<M>("set_motor_data", {impl::cmd(0x30)},
                         field{"power", &M::power, 1, wire::i8{}, impl::motor_power, unit{"%", 100.0 / 127.0}},
                         field{"brake_flags", &M::brake_flags, 7, wire::u8{}, impl::port_flags},
                         field{"lut_disable_flags", &M::lut_disable_flags, 8, wire::u8{}, impl::port_flags});
}
constexpr auto table_of(std::type_identity<set_motor_data_extended>) {
    using M = set_motor_data_extended;
    return make_table<M>("set_motor_data_extended", {impl::cmd(0x31)},
                         field{"reference", &M::reference, 1, wire::i32le{}},
                         field{"power", &M::power, 17, wire::i8{}, impl::motor_power, unit{"%", 100.0 / 127.0}},
                         field{"brake_flags", &M::brake_flags, 19, wire::u8{}, impl::port_flags},
                         field{"lut_disable_flags", &M::lut_disable_flags, 20, wire::u8{}, impl::port_flags});
}
constexpr auto table_of(std::type_identity<set_data_period>) {
    using M = set_data_period;
    return make_table<M>("set_data_period", {impl::cmd(0x32)},
                         field{"period_ms", &M::period_ms, 1, wire::u8{}, range{20, 255}, unit{"ms"}});
}
constexpr auto table_of(std::type_identity<set_ramp_rates>) {
    using M = set_ramp_rates;
    return make_table<M>("set_ramp_rates", {impl::cmd(0x33)},
                         field{"ramp_up", &M::ramp_up, 1, wire::u8{}, unit{"%/128ms"}},
                         field{"ramp_down", &M::ramp_down, 7, wire::u8{}, unit{"%/128ms"}});
}
constexpr auto table_of(std::type_identity<set_motor_timeout>) {
    using M = set_motor_timeout;
    return make_table<M>("set_motor_timeout", {impl::cmd(0x34)}, field{"mode", &M::mode, 1, wire::u8{}, range{0, 254}});
}
constexpr auto table_of(std::type_identity<activate_watchdog>) {
    using M = activate_watchdog;
    return make_table<M>("activate_watchdog", {impl::cmd(0x35)},
                         field{"timeout_s", &M::timeout_s, 1, wire::u8{}, unit{"s"}});
}
constexpr auto table_of(std::type_identity<rgb>) {
    return make_record<rgb>("rgb", field{"r", &rgb::r, 0, wire::u8{}}, field{"g", &rgb::g, 1, wire::u8{}},
                            field{"b", &rgb::b, 2, wire::u8{}});
}
constexpr auto table_of(std::type_identity<blink>) {
    return make_record<blink>("blink", field{"frequency_hz", &blink::frequency_hz, 0, wire::bits<4, 4>{}, unit{"Hz"}},
                              field{"duty", &blink::duty, 0, wire::bits<0, 4>{}, unit{"/16", 1.0, 1.0}});
}
constexpr auto table_of(std::type_identity<set_led_status>) {
    using M = set_led_status;
    return make_table<M>("set_led_status", {impl::cmd(0x36)}, field{"colors", &M::colors, 1, wire::record{}},
                         field{"blink", &M::blink, 13, wire::record{}});
}
constexpr auto table_of(std::type_identity<set_accel_lpf>) {
    using M = set_accel_lpf;
    return make_table<M>("set_accel_lpf", {impl::cmd(0x37)}, field{"setting", &M::setting, 1, wire::u8{}});
}
constexpr auto table_of(std::type_identity<set_current_limits>) {
    using M = set_current_limits;
    return make_table<M>("set_current_limits", {impl::cmd(0x38)},
                         field{"limit_raw", &M::limit_raw, 1, wire::u8{}, unit{"mA", 30.0}});
}
constexpr auto table_of(std::type_identity<set_uart_baudrate>) {
    using M = set_uart_baudrate;
    return make_table<M>("set_uart_baudrate", {impl::cmd(0x40), {1, 0x10, errc::bad_command}},
                         field{"channel", &M::channel, 2, wire::u8{}},
                         field{"baudrate", &M::baudrate, 3, wire::u32le{}, unit{"baud"}});
}
constexpr auto table_of(std::type_identity<set_pu_port_function>) {
    using M = set_pu_port_function;
    return make_table<M>("set_pu_port_function", {impl::cmd(0x50)}, field{"function", &M::function, 1, wire::u8{}});
}
constexpr auto table_of(std::type_identity<enable_pid_reporting>) {
    using M = enable_pid_reporting;
    return make_table<M>("enable_pid_reporting", {impl::cmd(0x51)},
                         field{"port", &M::port, 1, wire::u8{}, range{0, 4}});
}
constexpr auto table_of(std::type_identity<set_servo_reference>) {
    using M = set_servo_reference;
    return make_table<M>("set_servo_reference", {impl::cmd(0x52)}, field{"reference", &M::reference, 1, wire::i32le{}});
}
constexpr auto table_of(std::type_identity<set_pid_parameters>) {
    using M = set_pid_parameters;
    return make_table<M>("set_pid_parameters", {impl::cmd(0x53)}, field{"port", &M::port, 1, wire::u8{}, range{0, 3}},
                         field{"out_lp", &M::out_lp, 2, wire::f32le{}}, field{"d_lp", &M::d_lp, 6, wire::f32le{}},
                         field{"speed_lp", &M::speed_lp, 10, wire::f32le{}}, field{"kp", &M::kp, 14, wire::f32le{}},
                         field{"ki", &M::ki, 18, wire::f32le{}}, field{"kd", &M::kd, 22, wire::f32le{}},
                         field{"lim_i", &M::lim_i, 26, wire::f32le{}},
                         field{"reference_rate_limit", &M::reference_rate_limit, 30, wire::f32le{}},
                         field{"lim_out", &M::lim_out, 34, wire::i8{}, range{1, 127}},
                         field{"deadband_out", &M::deadband_out, 35, wire::i8{}, range{0, 127}},
                         field{"deadband_out_boost", &M::deadband_out_boost, 36, wire::i8{}, range{0, 127}},
                         field{"mode", &M::mode, 37, wire::u8{}});
}
constexpr auto table_of(std::type_identity<activate_shelf_mode>) {
    return make_table<activate_shelf_mode>("activate_shelf_mode", {impl::cmd(0xA1)});
}
constexpr auto table_of(std::type_identity<check_charger_settings>) {
    return make_table<check_charger_settings>("check_charger_settings", {impl::cmd(0xAC)});
}
constexpr auto table_of(std::type_identity<charger_settings>) {
    using M = charger_settings;
    return make_table<M>("charger_settings", {impl::cmd(0xAC)}, field{"data", &M::data, 1, wire::tail{}});
}

// Names of the port bits of brake_flags and lut_disable_flags, for printing.
constexpr auto flag_bits_of(std::type_identity<set_motor_data>) {
    return join_flag_bits(port_bits("brake_flags"), port_bits("lut_disable_flags"));
}
constexpr auto flag_bits_of(std::type_identity<set_motor_data_extended>) {
    return join_flag_bits(port_bits("brake_flags"), port_bits("lut_disable_flags"));
}

// Every host -> device command (application characteristic); one list: the
// dispatcher, tools, tests and fuzzers use it; a new command is added here.
using command = std::variant<set_device_name, set_motion_wakeup, set_accel_calibration, read_accel_calibration,
                             set_motor_data, set_motor_data_extended, set_data_period, set_ramp_rates,
                             set_motor_timeout, activate_watchdog, set_led_status, set_accel_lpf, set_current_limits,
                             set_uart_baudrate, set_pu_port_function, enable_pid_reporting, set_servo_reference,
                             set_pid_parameters, activate_shelf_mode, check_charger_settings>;

}  // namespace robowire::buwizz3
