// robowire/osp/protocol.hpp - OSP's descriptor: a serial protocol, no GATT;
// one message set (requests and answers) both ways.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include "../core/descriptor.hpp"
#include "messages.hpp"

namespace robowire::osp {

using messages = message_variants<message>;
inline constexpr protocol_descriptor descriptor{
    "osp", "serial; FF AA DEV CMD P1..P4 55 77", {}, stream_kind::scanner, messages::has_directions};

}  // namespace robowire::osp
