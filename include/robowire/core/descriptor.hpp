// robowire/core/descriptor.hpp - what a protocol is, in one constexpr table:
// name, summary, GATT characteristics, stream kind. Tools iterate these.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstddef>
#include <span>
#include <string_view>

#include "uuid.hpp"

namespace robowire {

// Which way a characteristic carries messages.
enum class gatt_direction : unsigned char {
    to_device,    // app -> device (write)
    from_device,  // device -> app (notify)
    both,         // write and notify on the same characteristic
};

// How a byte stream of the protocol is cut into messages.
enum class stream_kind : unsigned char {
    none,         // one message per packet (GATT write or notification)
    scanner,      // frames found in a serial byte stream (resynchronises)
    reassembler,  // messages split over several fixed-size frames
};

// One GATT characteristic that carries the protocol's messages.
struct characteristic {
    uuid128 uuid;
    gatt_direction carries;
    std::string_view label;  // e.g. "NAVBOT write characteristic"
};

// One protocol: what the command-line tool, the log reader, the schema and
// the Python module know of it. Message variants stay in the protocol's
// decode.hpp (types cannot sit in a constexpr table).
struct protocol_descriptor {
    std::string_view name;                            // lower case, e.g. "osp"
    std::string_view summary;                         // one line
    std::span<const characteristic> characteristics;  // empty: no GATT (serial)
    stream_kind stream;

    // The characteristic with this UUID, or nullptr.
    constexpr const characteristic* find(const uuid128& u) const noexcept {
        for (const auto& c : characteristics)
            if (c.uuid == u) return &c;
        return nullptr;
    }
};

}  // namespace robowire
