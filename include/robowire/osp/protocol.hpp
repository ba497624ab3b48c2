// robowire/osp/protocol.hpp - OSP's descriptor: a serial protocol, no GATT.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include "../core/descriptor.hpp"

namespace robowire::osp {

inline constexpr protocol_descriptor descriptor{"osp", "serial; FF AA DEV CMD P1..P4 55 77", {}, stream_kind::scanner};

}  // namespace robowire::osp
