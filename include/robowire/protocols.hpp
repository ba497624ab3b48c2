// robowire/protocols.hpp - every protocol, in `list` order: its umbrella and
// its descriptor (name, GATT characteristics, stream kind, fuzz dictionary).
// A new protocol adds its umbrella's #include and its descriptor here.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "buwizz3.hpp"
#include "core/descriptor.hpp"
#include "navbot.hpp"
#include "osp.hpp"

namespace robowire {

// What tools iterate (the command-line tool, the log reader, fuzz/dict/).
inline constexpr const protocol_descriptor* all_protocols[] = {&buwizz3::descriptor, &navbot::descriptor,
                                                               &osp::descriptor};

// The descriptor named `name`, or nullptr.
constexpr const protocol_descriptor* find_descriptor(std::string_view name) noexcept {
    for (const auto* d : all_protocols)
        if (d->name == name) return d;
    return nullptr;
}

}  // namespace robowire
