// robowire/buwizz3/protocol.hpp - BuWizz3's descriptor: one GATT
// characteristic both ways; commands to the device, notifications from it.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include "../core/descriptor.hpp"
#include "decode.hpp"
#include "uuids.hpp"

namespace robowire::buwizz3 {

inline constexpr characteristic characteristics[] = {
    {application_uuid, gatt_direction::both, "BuWizz3 application characteristic"},
};
using messages = message_variants<command, notification>;
inline constexpr protocol_descriptor descriptor{"buwizz3", "BLE; byte 0 = command", characteristics, stream_kind::none,
                                                messages::has_directions};

}  // namespace robowire::buwizz3
