// robowire/core/descriptor.hpp - what a protocol is, in one constexpr table:
// name, summary, GATT characteristics, stream kind; and its message variants
// per direction (types, beside it). Tools iterate these.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstddef>
#include <string_view>
#include <type_traits>

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

// A protocol's message variants by direction (types cannot sit in the
// constexpr descriptor): `messages` beside each `descriptor`. The same
// variant both ways (the default) means one message set, no directions.
template <class ToDevice, class FromDevice = ToDevice>
struct message_variants {
    using to_device = ToDevice;      // app -> device (BuWizz3: command)
    using from_device = FromDevice;  // device -> app (BuWizz3: notification)
    static constexpr bool has_directions = !std::is_same_v<ToDevice, FromDevice>;
};

// A protocol's GATT characteristics: a view of a constant array (begin, end,
// size, empty, [i]); `std::span(list.begin(), list.size())` makes a span.
class characteristic_list {
public:
    constexpr characteristic_list() noexcept = default;
    template <std::size_t N>
    constexpr characteristic_list(const characteristic (&list)[N]) noexcept : first_(list), count_(N) {}
    constexpr const characteristic* begin() const noexcept { return first_; }
    constexpr const characteristic* end() const noexcept { return first_ + count_; }
    constexpr std::size_t size() const noexcept { return count_; }
    constexpr bool empty() const noexcept { return count_ == 0; }
    constexpr const characteristic& operator[](std::size_t i) const noexcept { return first_[i]; }

private:
    const characteristic* first_ = nullptr;
    std::size_t count_ = 0;
};

// One protocol: what the command-line tool, the log reader, the schema and
// the Python module know of it. Including it computes nothing from the
// tables (the fuzz dictionary is fuzz_dictionary_v<messages>, reflect.hpp).
struct protocol_descriptor {
    std::string_view name;                // lower case, e.g. "osp"
    std::string_view summary;             // one line
    characteristic_list characteristics;  // empty: no GATT (serial)
    stream_kind stream;
    bool has_directions;  // the messages differ by direction (message_variants)

    // The characteristic with this UUID, or nullptr.
    constexpr const characteristic* find(const uuid128& u) const noexcept {
        for (const auto& c : characteristics)
            if (c.uuid == u) return &c;
        return nullptr;
    }
};

}  // namespace robowire
