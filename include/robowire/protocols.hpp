// robowire/protocols.hpp - every protocol's descriptor, in `list` order.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "buwizz3/protocol.hpp"
#include "navbot/protocol.hpp"
#include "osp/protocol.hpp"

namespace robowire {

// What tools iterate: a new protocol adds its descriptor here.
inline constexpr const protocol_descriptor* all_protocols[] = {&buwizz3::descriptor, &navbot::descriptor,
                                                               &osp::descriptor};

// The descriptor named `name`, or nullptr.
constexpr const protocol_descriptor* find_descriptor(std::string_view name) noexcept {
    for (const auto* d : all_protocols)
        if (d->name == name) return d;
    return nullptr;
}

}  // namespace robowire
