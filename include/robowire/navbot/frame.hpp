// robowire/navbot/frame.hpp - NAVBOT-ES02 20-byte frame, commands, BLE constants.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "../core/advertising.hpp"
#include "../core/decode.hpp"
#include "../core/encode.hpp"
#include "../core/table.hpp"
#include "../core/uuid.hpp"

namespace robowire::navbot {

// Frame: 55 AA command remaining 00, then 15 payload bytes (20 bytes).
inline constexpr std::size_t frame_size = 20;
inline constexpr std::size_t payload_size = 15;
inline constexpr std::uint8_t header1 = 0x55, header2 = 0xAA;

// Command byte values.
namespace command {
inline constexpr std::uint8_t wifi = 0x01;      // Wi-Fi settings (payload not documented: raw)
inline constexpr std::uint8_t json = 0x02;      // JSON text, e.g. {"type":"get_device_info"}
inline constexpr std::uint8_t maneuver = 0x10;  // CMD_MANEUVER
}  // namespace command

// Any frame. `remaining`: frames that follow this one in the same message (last frame: 0).
struct frame {
    std::uint8_t command = 0;
    std::uint8_t remaining = 0;
    std::array<std::uint8_t, payload_size> payload{};
    friend constexpr bool operator==(const frame&, const frame&) = default;
};

// Byte 4 (index 4) is reserved: sent as 0, ignored on receive (check_reserved<frame> reports it).
constexpr auto table_of(std::type_identity<frame>) {
    return make_table<frame>("frame", {{0, header1, errc::bad_header}, {1, header2, errc::bad_header}},
                             field{"command", &frame::command, 2, wire::u8{}},
                             field{"remaining", &frame::remaining, 3, wire::u8{}},
                             field{"payload", &frame::payload, 5, wire::u8{}});
}

// Explains a length error: NAVBOT frames are 20 bytes. A 22-byte input is
// what the protocol document's sample frames look like (a transcription
// error: two extra bytes, every field one byte late).
constexpr std::string_view length_error_text(std::size_t input_size) noexcept {
    if (input_size == 22)
        return "22 bytes: NAVBOT frames are 20 bytes; the protocol document's sample frames have 2 extra bytes "
               "(a transcription error, every field one byte late), the robot reads 20";
    return "NAVBOT frames are 20 bytes";
}

// BLE: advertised name prefix, service and characteristics.
inline constexpr std::string_view name_prefix = "navbot_es02-";
inline constexpr uuid128 service_uuid = uuid_literal("6e400011-b5a3-f393-e0a9-e50e24dcca9e");
inline constexpr uuid128 write_uuid = uuid_literal("6e400012-b5a3-f393-e0a9-e50e24dcca9e");   // app -> robot
inline constexpr uuid128 notify_uuid = uuid_literal("6e400013-b5a3-f393-e0a9-e50e24dcca9e");  // robot -> app (echoes)

// Is `name` a NAVBOT-ES02 name ("navbot_es02-" + suffix)?
constexpr bool is_navbot_name(std::string_view name) noexcept {
    return name.size() > name_prefix.size() && name.substr(0, name_prefix.size()) == name_prefix;
}

// Does the advertisement carry a NAVBOT-ES02 local name (complete or shortened)?
template <class Deferred = void>  // a template: including this header instantiates no reader
constexpr bool matches_advertisement(std::span<const std::uint8_t> ad_data) noexcept {
    ad::basic_reader<Deferred> r(ad_data);
    while (auto s = r.next()) {
        if (s->type != ad::complete_local_name && s->type != ad::shortened_local_name) continue;
        std::array<char, 31> chars{};
        const std::size_t n = s->data.size() < chars.size() ? s->data.size() : chars.size();
        for (std::size_t i = 0; i < n; ++i) chars[i] = static_cast<char>(s->data[i]);
        const std::string_view name(chars.data(), n);
        if (is_navbot_name(name)) return true;
        // a shortened name may stop inside the prefix's suffix, not inside the prefix
        if (s->type == ad::shortened_local_name && name == name_prefix) return true;
    }
    return false;
}

}  // namespace robowire::navbot
