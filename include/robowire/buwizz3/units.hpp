// robowire/buwizz3/units.hpp - conversions between physical units and raw
// command values, and the document's PID presets.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <cstdint>
#include <numbers>
#include <type_traits>
#include <utility>

#include "../core/divide.hpp"
#include "commands.hpp"
#include "status.hpp"

namespace robowire::buwizz3 {

// 0x37: filter cut-off frequency in Hz.
constexpr double lpf_hz(lpf_setting s) noexcept {
    switch (s) {
    case lpf_setting::hz_0_781: return 0.781;
    case lpf_setting::hz_1_563: return 1.563;
    case lpf_setting::hz_3_125: return 3.125;
    case lpf_setting::hz_6_25: return 6.25;
    case lpf_setting::hz_12_5: return 12.5;
    case lpf_setting::hz_25: return 25.0;
    case lpf_setting::hz_50: return 50.0;
    case lpf_setting::hz_100: return 100.0;
    }
    return 0.0;
}
// The setting for one of the eight frequencies (within 1 %); invalid_enum otherwise.
constexpr result<lpf_setting> lpf_from_hz(double hz) noexcept {
    for (const auto& e : enum_table_v<lpf_setting>) {
        const double f = lpf_hz(e.value);
        if (hz >= f * 0.99 && hz <= f * 1.01) return e.value;
    }
    return fail(errc::invalid_enum, 1);
}

// 0x30 / 0x31 motor power: raw -127..127, 127 (0x7F) full forwards, -127
// (0x81) full backwards, as the document gives them; so a positive percentage
// is forwards. raw = percent x 127 / 100, rounded half away from zero:
// 100 % -> 127, 50 % -> 63.5 -> 64, -50 % -> -64, 1 % -> 1.27 -> 1.
// Outside -100..100 (or NaN): value_out_of_range (offset 1, the first power byte).
constexpr result<std::int8_t> power_from_percent(double percent) noexcept {
    if (!(percent >= -100.0 && percent <= 100.0)) return fail(errc::value_out_of_range, 1);
    const double raw = percent * 127.0 / 100.0;
    return static_cast<std::int8_t>(raw < 0.0 ? raw - 0.5 : raw + 0.5);
}
// The same for whole percentages, in integers (no floating point is linked).
template <class Int>
requires std::is_integral_v<Int>
constexpr result<std::int8_t> power_from_percent(Int percent) noexcept {
    if (std::cmp_less(percent, -100) || std::cmp_greater(percent, 100)) return fail(errc::value_out_of_range, 1);
    const int p = static_cast<int>(percent);
    const int magnitude = ((p < 0 ? -p : p) * 127 + 50) / 100;
    return static_cast<std::int8_t>(p < 0 ? -magnitude : magnitude);
}
// The inverse: percent of full power, raw x 100 / 127 (127 -> 100 %, 64 -> 50.39 %,
// -127 -> -100 %). -128 is no valid power (-100.79 %).
constexpr double percent_from_power(std::int8_t raw) noexcept { return raw * 100.0 / 127.0; }

// 0x33: rate (% per 128 ms) for a full 0-100 % ramp in `seconds`:
// 100 / (seconds x 7.8125), rounded, clamped to 1..255. seconds <= 0: value_out_of_range.
constexpr result<std::uint8_t> ramp_rate_from_seconds(double seconds) noexcept {
    if (!(seconds > 0.0)) return fail(errc::value_out_of_range, 1);
    const double r = 100.0 / (seconds * 7.8125);
    if (r >= 254.5) return std::uint8_t{255};
    if (r < 1.5) return std::uint8_t{1};
    return static_cast<std::uint8_t>(r + 0.5);
}
// Seconds for a full 0-100 % ramp at `rate` (0: no ramp, returns 0).
constexpr double ramp_seconds(std::uint8_t rate) noexcept { return rate == 0 ? 0.0 : 100.0 / (rate * 7.8125); }

// 0x38: raw current limit for `milliamps` in steps of `step_ma` (30 mA per the
// document; some apps use 35), rounded; value_out_of_range above 255 steps.
inline constexpr double default_current_step_ma = 30.0;
constexpr result<std::uint8_t> current_limit_raw(double milliamps, double step_ma = default_current_step_ma) noexcept {
    if (!(milliamps >= 0.0) || !(step_ma > 0.0)) return fail(errc::value_out_of_range, 1);
    const double raw = milliamps / step_ma + 0.5;
    if (raw >= 256.0) return fail(errc::value_out_of_range, 1);
    return static_cast<std::uint8_t>(raw);
}
constexpr double current_limit_ma(std::uint8_t raw, double step_ma = default_current_step_ma) noexcept {
    return raw * step_ma;
}
// The limits the device sets on every connection: 1.5 A ports 1-4, 3.0 A ports 5-6 (30 mA steps).
inline constexpr set_current_limits default_current_limits{{50, 50, 50, 50, 100, 100}};

// 0x53: K_LP for a low-pass cut-off frequency f (Hz): 1 - Ts / (Ts + 1 / (2 pi f)), Ts = 0.01 s.
// f <= 0: value_out_of_range.
inline constexpr double pid_sample_time_s = 0.01;
constexpr result<float> k_lp_from_cutoff(double f_hz) noexcept {
    if (!(f_hz > 0.0)) return fail(errc::value_out_of_range, 2);
    const double ts = pid_sample_time_s;
    return static_cast<float>(1.0 - ts / (ts + 1.0 / (2.0 * std::numbers::pi * f_hz)));
}

// The document's default PID parameters. Entries the document leaves empty
// ("/" or N/A) are 0. `port` is 0-based (0..3).
constexpr set_pid_parameters position_servo_preset(std::uint8_t port) noexcept {
    return {port, 0.0f, 0.9f, 0.0f, 0.4f, 0.01f, -0.8f, 20.0f, 0.0f, 100, 2, 2, port_function::pu_position_servo};
}
constexpr set_pid_parameters speed_servo_preset(std::uint8_t port) noexcept {
    return {port, 0.5f, 0.5f, 0.9f, 0.8f, 0.06f, -3.0f, 127.0f, 0.0f, 127, 2, 2, port_function::pu_speed_servo};
}
// "Generic PID" column: gains are yours to set (0 here), filters off, limits 127.
constexpr set_pid_parameters generic_pid_preset(std::uint8_t port, port_function mode) noexcept {
    return {port, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 127.0f, 0.0f, 127, 0, 0, mode};
}

// Status report units (double; battery_volts(raw) etc. are in status.hpp).
constexpr double battery_volts(const status& s) noexcept { return battery_volts(s.battery_voltage_raw); }
constexpr double motor_amps(const status& s, std::size_t port_index) noexcept {
    return motor_amps(s.motor_current_raw[port_index]);
}

// Status report units in integers, for cores without an FPU (no floating
// point is used, so no soft-float routine is linked).
// Battery voltage in millivolts: 9000 + raw x 50 (9000..21750; the device reports up to 15350).
constexpr std::uint16_t battery_millivolts(std::uint8_t raw) noexcept {
    return static_cast<std::uint16_t>(9000u + raw * 50u);
}
// Motor current in milliamps: raw x 15 (0..3825).
constexpr std::uint16_t motor_milliamps(std::uint8_t raw) noexcept { return static_cast<std::uint16_t>(raw * 15u); }
// Acceleration in micro-g: word x 488 (the 16-bit word, not the 12-bit count;
// -15990784..15990296).
constexpr std::int32_t accel_micro_g(std::int16_t word) noexcept { return std::int32_t{word} * 488; }
namespace units_detail {
// The division of accel_milli_g_rounded (see robowire/core/divide.hpp).
using milli_g_by_125 = robowire::codec::divider<125, ((32768u * 488u + 500u) >> 3), 2097, 18, 2>;
}  // namespace units_detail
// Acceleration in whole milli-g: word x 0.488 rounded half away from zero
// (-15991..15990). No library division on a core without a divide
// instruction: (|word| x 488 + 500) / 1000 as / 8, then / 125 by a multiply.
constexpr std::int16_t accel_milli_g_rounded(std::int16_t word) noexcept {
    const std::uint32_t mag = word < 0 ? 0u - static_cast<std::uint32_t>(word) : static_cast<std::uint32_t>(word);
    const std::uint32_t q = units_detail::milli_g_by_125{}((mag * 488u + 500u) >> 3);
    return static_cast<std::int16_t>(word < 0 ? -static_cast<std::int32_t>(q) : static_cast<std::int32_t>(q));
}
constexpr std::uint16_t battery_millivolts(const status& s) noexcept {
    return battery_millivolts(s.battery_voltage_raw);
}
// port_index: 0..5 (ports 1-6).
constexpr std::uint16_t motor_milliamps(const status& s, std::size_t port_index) noexcept {
    return motor_milliamps(s.motor_current_raw[port_index]);
}

}  // namespace robowire::buwizz3
