// robowire/navbot/protocol.hpp - NAVBOT-ES02's descriptor: two GATT
// characteristics; one message set (navbot::message) both ways.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include "../core/descriptor.hpp"
#include "decode.hpp"
#include "frame.hpp"

namespace robowire::navbot {

inline constexpr characteristic characteristics[] = {
    {write_uuid, gatt_direction::to_device, "NAVBOT write characteristic"},
    {notify_uuid, gatt_direction::from_device, "NAVBOT notify characteristic"},
};
using messages = message_variants<message>;
inline constexpr protocol_descriptor descriptor{"navbot", "BLE; 20-byte frames", characteristics,
                                                stream_kind::reassembler, messages::has_directions};

}  // namespace robowire::navbot
