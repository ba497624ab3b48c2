// robowire/navbot/protocol.hpp - NAVBOT-ES02's descriptor: two GATT characteristics.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include "../core/descriptor.hpp"
#include "frame.hpp"

namespace robowire::navbot {

inline constexpr characteristic characteristics[] = {
    {write_uuid, gatt_direction::to_device, "NAVBOT write characteristic"},
    {notify_uuid, gatt_direction::from_device, "NAVBOT notify characteristic"},
};
inline constexpr protocol_descriptor descriptor{"navbot", "BLE; 20-byte frames", characteristics,
                                                stream_kind::reassembler};

}  // namespace robowire::navbot
