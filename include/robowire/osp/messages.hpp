// robowire/osp/messages.hpp - every OSP message, one table each (unit helpers: osp/units.hpp).
// Reserved parameter bytes are sent as 0 and ignored on receive;
// robowire::check_reserved<M>(bytes) reports them for a strict receiver.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <cstdint>
#include <numbers>
#include <variant>

#include "../core/flag_bits.hpp"
#include "frame.hpp"

namespace robowire::osp {

// DEV_TYPE values (INFO_DEV_TYPE P1). OBP-1 is spelled OPB-1 in places in the document.
enum class device_type : std::uint8_t { invalid = 0x00, arm1 = 0x01, obp1 = 0x02, o2d1 = 0x03 };
constexpr auto enum_table_of(std::type_identity<device_type>) {
    return std::array<enum_entry<device_type>, 4>{{{device_type::invalid, "invalid"},
                                                   {device_type::arm1, "arm1"},
                                                   {device_type::obp1, "obp1"},
                                                   {device_type::o2d1, "o2d1"}}};
}

namespace generic {
// CMD_REQ_DEV_TYPE, DEV 0x00 CMD 0x01: any device answers with device_type.
struct request_device_type {
    friend constexpr bool operator==(const request_device_type&, const request_device_type&) = default;
};
constexpr auto table_of(std::type_identity<request_device_type>) {
    return make_table<request_device_type>("request_device_type", impl::fixed(0x00, 0x01));
}

// INFO_DEV_TYPE, DEV 0x00 CMD 0x11. P1: the device's type.
struct device_type {
    osp::device_type type = osp::device_type::invalid;
    friend constexpr bool operator==(const device_type&, const device_type&) = default;
};
constexpr auto table_of(std::type_identity<device_type>) {
    return make_table<device_type>("device_type", impl::fixed(0x00, 0x11),
                                   field{"type", &device_type::type, 4, wire::u8{}});
}
}  // namespace generic

namespace arm1 {
// ARM1_CMD_SET_ANGLE, DEV 0x01 CMD 0x02. P1: joint; P2-P3: angle (u16le, raw; the published
// ORM arm firmware reads it as signed 16-bit; see units.hpp).
struct set_angle {
    std::uint8_t joint = 0;
    std::uint16_t angle = 0;
    friend constexpr bool operator==(const set_angle&, const set_angle&) = default;
};
constexpr auto table_of(std::type_identity<set_angle>) {
    return make_table<set_angle>(
        "set_angle", impl::fixed(0x01, 0x02), field{"joint", &set_angle::joint, 4, wire::u8{}},
        field{"angle", &set_angle::angle, 5, wire::u16le{}, unit{"rad", std::numbers::pi / 16384.0}});
}

}  // namespace arm1

namespace obp1 {
// Requests, DEV 0x02, no parameters. The battery answers with the message named in each.
struct request_soc {  // OBP_CMD_REQ_SOC, CMD 0x01 -> soc
    friend constexpr bool operator==(const request_soc&, const request_soc&) = default;
};
struct request_voltage {  // OBP_CMD_REQ_VOLTAGE, CMD 0x02 -> voltage
    friend constexpr bool operator==(const request_voltage&, const request_voltage&) = default;
};
struct request_current {  // OBP_CMD_REQ_CURRENT, CMD 0x03 -> current
    friend constexpr bool operator==(const request_current&, const request_current&) = default;
};
struct request_status {  // OBP_CMD_REQ_STATUS, CMD 0x04 -> status
    friend constexpr bool operator==(const request_status&, const request_status&) = default;
};
constexpr auto table_of(std::type_identity<request_soc>) {
    return make_table<request_soc>("request_soc", impl::fixed(0x02, 0x01));
}
constexpr auto table_of(std::type_identity<request_voltage>) {
    return make_table<request_voltage>("request_voltage", impl::fixed(0x02, 0x02));
}
constexpr auto table_of(std::type_identity<request_current>) {
    return make_table<request_current>("request_current", impl::fixed(0x02, 0x03));
}
constexpr auto table_of(std::type_identity<request_status>) {
    return make_table<request_status>("request_status", impl::fixed(0x02, 0x04));
}

// OBP_INFO_SOC, CMD 0x11. State of charge, 0 = 0 %, 65535 = 100 % (the published
// OBP-1 firmware sends 10000 = 100 %: units.hpp, scale::published_firmware).
struct soc {
    std::uint16_t soc_raw = 0;
    friend constexpr bool operator==(const soc&, const soc&) = default;
};
// OBP_INFO_VOLTAGE, CMD 0x12. Volts x 100 (-32768 = -327.68 V, 32767 = 327.67 V); the
// published OBP-1 firmware sends millivolts (units.hpp, scale::published_firmware).
struct voltage {
    std::int16_t centivolts = 0;
    friend constexpr bool operator==(const voltage&, const voltage&) = default;
};
// OBP_INFO_CURRENT, CMD 0x13. Milliamps (-32.768 A .. 32.767 A).
struct current {
    std::int16_t milliamps = 0;
    friend constexpr bool operator==(const current&, const current&) = default;
};

enum class state : std::uint8_t { unknown = 0, idle = 1, discharging = 2, charging = 3, fully_charged = 4 };
constexpr auto enum_table_of(std::type_identity<state>) {
    return std::array<enum_entry<state>, 5>{{{state::unknown, "unknown"},
                                             {state::idle, "idle"},
                                             {state::discharging, "discharging"},
                                             {state::charging, "charging"},
                                             {state::fully_charged, "fully_charged"}}};
}
// Status flag bits (bits 4-7 reserved; kept raw).
namespace flag {
inline constexpr std::uint8_t low_voltage = 1u << 0;
inline constexpr std::uint8_t high_voltage = 1u << 1;
inline constexpr std::uint8_t overheat = 1u << 2;
inline constexpr std::uint8_t short_circuit = 1u << 3;
}  // namespace flag

// OBP_INFO_STATUS, CMD 0x14 (the document prints 0x13, OBP_INFO_CURRENT's code).
struct status {
    obp1::state state = obp1::state::unknown;
    std::uint8_t flags = 0;  // flag:: bits
    constexpr bool low_voltage() const noexcept { return flags & flag::low_voltage; }
    constexpr bool high_voltage() const noexcept { return flags & flag::high_voltage; }
    constexpr bool overheat() const noexcept { return flags & flag::overheat; }
    constexpr bool short_circuit() const noexcept { return flags & flag::short_circuit; }
    friend constexpr bool operator==(const status&, const status&) = default;
};

constexpr auto table_of(std::type_identity<soc>) {
    return make_table<soc>("soc", impl::fixed(0x02, 0x11),
                           field{"soc_raw", &soc::soc_raw, 4, wire::u16le{}, unit{"%", 100.0 / 65535.0}});
}
constexpr auto table_of(std::type_identity<voltage>) {
    return make_table<voltage>("voltage", impl::fixed(0x02, 0x12),
                               field{"centivolts", &voltage::centivolts, 4, wire::i16le{}, unit{"V", 0.01}});
}
constexpr auto table_of(std::type_identity<current>) {
    return make_table<current>("current", impl::fixed(0x02, 0x13),
                               field{"milliamps", &current::milliamps, 4, wire::i16le{}, unit{"A", 0.001}});
}
constexpr auto table_of(std::type_identity<status>) {
    return make_table<status>("status", impl::fixed(0x02, 0x14), field{"state", &status::state, 4, wire::u8{}},
                              field{"flags", &status::flags, 5, wire::u8{}});
}

// Names of status::flags bits (flag::), for printing.
constexpr auto flag_bits_of(std::type_identity<status>) {
    return std::array<flag_bit, 4>{{{"flags", 0, 1, "low_voltage", {}},
                                    {"flags", 1, 1, "high_voltage", {}},
                                    {"flags", 2, 1, "overheat", {}},
                                    {"flags", 3, 1, "short_circuit", {}}}};
}
}  // namespace obp1

// Every OSP message (one list: osp::decode, the tools, tests and fuzzers use it;
// a new message is added here).
using message = std::variant<generic::request_device_type, generic::device_type, arm1::set_angle, obp1::request_soc,
                             obp1::request_voltage, obp1::request_current, obp1::request_status, obp1::soc,
                             obp1::voltage, obp1::current, obp1::status>;

}  // namespace robowire::osp
