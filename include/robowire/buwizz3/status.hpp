// robowire/buwizz3/status.hpp - the device status report (0x01), sent about
// 20 times a second once notifications are enabled. 54 bytes, or 68 with the
// PID state block (after 0x51 enable_pid_reporting).
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "../core/bits.hpp"
#include "../core/decode.hpp"
#include "../core/encode.hpp"
#include "../core/flag_bits.hpp"
#include "../core/table.hpp"

namespace robowire::buwizz3 {

// Status flag bits (status::flags).
namespace status_flag {
inline constexpr std::uint8_t error = 1u << 0;               // over-current or over-temperature
inline constexpr std::uint8_t motion_wakeup = 1u << 1;       // motion wake-up enabled
inline constexpr std::uint8_t long_range_phy = 1u << 2;      // BLE long-range (coded) PHY in use
inline constexpr std::uint8_t battery_level_mask = 3u << 3;  // bits 3-4: battery_level
inline constexpr std::uint8_t charging = 1u << 5;            // battery is charging
inline constexpr std::uint8_t usb_connected = 1u << 6;       // USB cable connected
}  // namespace status_flag

enum class battery_level : std::uint8_t { empty = 0, low = 1, medium = 2, full = 3 };  // empty: motors disabled

struct bootloader_response {
    std::uint8_t command = 0;
    std::uint8_t code = 0;
    std::array<std::uint8_t, 3> data{};
    friend constexpr bool operator==(const bootloader_response&, const bootloader_response&) = default;
};

// One PoweredUp motor port. Positions are signed (the document says unsigned;
// the vendor's apps read them signed).
struct pu_motor {
    std::uint8_t type = 0;  // PoweredUp motor type id
    std::int8_t velocity = 0;
    std::int16_t absolute_position = 0;  // degrees, -180..179
    std::int32_t position = 0;           // degrees, relative, may be negative
    friend constexpr bool operator==(const pu_motor&, const pu_motor&) = default;
};

struct pid_state {
    float process_value = 0;
    float error = 0;
    float output = 0;
    std::int8_t integrator = 0;
    std::int8_t motor_output = 0;
    friend constexpr bool operator==(const pid_state&, const pid_state&) = default;
};

struct status {
    std::uint8_t flags = 0;                           // status_flag bits
    std::uint8_t battery_voltage_raw = 0;             // 9 V + raw x 0.05 V
    std::array<std::uint8_t, 6> motor_current_raw{};  // raw x 0.015 A, ports 1-6
    std::uint8_t temperature_c = 0;                   // microcontroller, degrees C
    std::array<std::int16_t, 3> accel_raw{};          // x, y, z: 12-bit left-aligned, 0.488 mg per word unit
    buwizz3::bootloader_response bootloader_response{};
    std::uint8_t charge_current_ma = 0;             // battery charge current, mA
    std::array<pu_motor, 4> pu_motors{};            // ports 1-4
    std::optional<buwizz3::pid_state> pid_state{};  // present in the 68-byte form
    std::size_t ignored_trailing_bytes = 0;         // decode: bytes after the known fields (not encoded)

    constexpr bool error() const noexcept { return flags & status_flag::error; }
    constexpr bool motion_wakeup_enabled() const noexcept { return flags & status_flag::motion_wakeup; }
    constexpr bool long_range_phy() const noexcept { return flags & status_flag::long_range_phy; }
    constexpr buwizz3::battery_level battery_level() const noexcept {
        return static_cast<buwizz3::battery_level>(get_bits(flags, 3, 2));
    }
    constexpr bool charging() const noexcept { return flags & status_flag::charging; }
    constexpr bool usb_connected() const noexcept { return flags & status_flag::usb_connected; }

    friend constexpr bool operator==(const status&, const status&) = default;
};

constexpr auto table_of(std::type_identity<bootloader_response>) {
    using M = bootloader_response;
    return make_record<M>("bootloader_response", field{"command", &M::command, 0, wire::u8{}},
                          field{"code", &M::code, 1, wire::u8{}}, field{"data", &M::data, 2, wire::u8{}});
}
constexpr auto table_of(std::type_identity<pu_motor>) {
    using M = pu_motor;
    return make_record<M>("pu_motor", field{"type", &M::type, 0, wire::u8{}},
                          field{"velocity", &M::velocity, 1, wire::i8{}},
                          field{"absolute_position", &M::absolute_position, 2, wire::i16le{}, unit{"deg"}},
                          field{"position", &M::position, 4, wire::i32le{}, unit{"deg"}});
}
constexpr auto table_of(std::type_identity<pid_state>) {
    using M = pid_state;
    return make_record<M>("pid_state", field{"process_value", &M::process_value, 0, wire::f32le{}},
                          field{"error", &M::error, 4, wire::f32le{}}, field{"output", &M::output, 8, wire::f32le{}},
                          field{"integrator", &M::integrator, 12, wire::i8{}},
                          field{"motor_output", &M::motor_output, 13, wire::i8{}});
}
// Byte offsets as in the document (byte 0 is the command 0x01). Longer than
// 68 bytes (up to the 129-byte packet limit) is decoded; the rest is counted
// in ignored_trailing_bytes. 55-67 bytes is a truncated PID block: bad_length.
constexpr auto table_of(std::type_identity<status>) {
    using M = status;
    auto t = make_table<M>("status", {{0, 0x01, errc::bad_command}}, field{"flags", &M::flags, 1, wire::u8{}},
                           field{"battery_voltage_raw", &M::battery_voltage_raw, 2, wire::u8{}, unit{"V", 0.05, 9.0}},
                           field{"motor_current_raw", &M::motor_current_raw, 3, wire::u8{}, unit{"A", 0.015}},
                           field{"temperature_c", &M::temperature_c, 9, wire::u8{}, unit{"degC"}},
                           field{"accel_raw", &M::accel_raw, 10, wire::i16le{}, unit{"mg", 0.488}},
                           field{"bootloader_response", &M::bootloader_response, 16, wire::record{}},
                           field{"charge_current_ma", &M::charge_current_ma, 21, wire::u8{}, unit{"mA"}},
                           field{"pu_motors", &M::pu_motors, 22, wire::record{}},
                           field{"pid_state", &M::pid_state, 54, wire::record{}});
    t.declared_max_input = 129;
    t.members_not_on_wire = 1;  // ignored_trailing_bytes
    return t;
}

// Names of status::flags bits (status_flag), for printing.
constexpr auto flag_bits_of(std::type_identity<status>) {
    return std::array<flag_bit, 6>{{{"flags", 0, 1, "error", {}},
                                    {"flags", 1, 1, "motion_wakeup", {}},
                                    {"flags", 2, 1, "long_range_phy", {}},
                                    {"flags", 3, 2, "battery", {"empty", "low", "medium", "full"}},
                                    {"flags", 5, 1, "charging", {}},
                                    {"flags", 6, 1, "usb_connected", {}}}};
}

// Units.
constexpr double battery_volts(std::uint8_t raw) noexcept { return 9.0 + raw * 0.05; }
constexpr double motor_amps(std::uint8_t raw) noexcept { return raw * 0.015; }
// Accelerometer: the 12-bit count (-2048..2047) and milli-g (word x 0.488; 7.808 mg per count).
constexpr std::int16_t accel_count(std::int16_t word) noexcept { return left12_count(word); }
constexpr double accel_milli_g(std::int16_t word) noexcept { return word * 0.488; }

}  // namespace robowire::buwizz3
