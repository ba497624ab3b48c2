// robowire/protocols.hpp - every protocol, in `list` order: its umbrella,
// its descriptor (name, GATT characteristics, stream kind) and its messages.
// A new protocol adds its umbrella's #include and its entry here.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include <array>
#include <string_view>

#include "buwizz3.hpp"
#include "core/descriptor.hpp"
#include "navbot.hpp"
#include "osp.hpp"

namespace robowire {

// One protocol of the list below: its descriptor, and its `messages` (the
// message variants per direction) as a type.
template <const protocol_descriptor& Descriptor, class Messages>
struct protocol_entry {
    static constexpr const protocol_descriptor& descriptor = Descriptor;
    using messages = Messages;
};
template <class... Entries>
struct protocol_list {
    static constexpr std::array<const protocol_descriptor*, sizeof...(Entries)> descriptors{&Entries::descriptor...};
    // Calls fn(entry) for every entry, in order.
    template <class Fn>
    static constexpr void each(Fn&& fn) {
        (fn(Entries{}), ...);
    }
};

// Every protocol, in `list` order. What tools iterate (the command-line tool,
// the log reader, fuzz/dict/).
using all_protocol_list =
    protocol_list<protocol_entry<buwizz3::descriptor, buwizz3::messages>,
                  protocol_entry<navbot::descriptor, navbot::messages>, protocol_entry<osp::descriptor, osp::messages>>;
inline constexpr const auto& all_protocols = all_protocol_list::descriptors;

// Calls fn(entry) for every protocol, in all_protocols order: entry.descriptor,
// and typename decltype(entry)::messages (e.g. for fuzz_dictionary_v, reflect.hpp).
template <class Fn>
constexpr void for_each_protocol(Fn&& fn) {
    all_protocol_list::each(fn);
}

// The descriptor named `name`, or nullptr.
constexpr const protocol_descriptor* find_descriptor(std::string_view name) noexcept {
    for (const auto* d : all_protocols)
        if (d->name == name) return d;
    return nullptr;
}

}  // namespace robowire
