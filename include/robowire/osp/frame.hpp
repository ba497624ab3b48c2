// robowire/osp/frame.hpp - the OSP frame: FF AA DEV CMD P1 P2 P3 P4 55 77.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>

#include "../core/decode.hpp"
#include "../core/encode.hpp"
#include "../core/table.hpp"

namespace robowire::osp {

inline constexpr std::size_t frame_size = 10;
inline constexpr std::uint8_t start1 = 0xFF, start2 = 0xAA;  // ST1 ST2
inline constexpr std::uint8_t end1 = 0x55, end2 = 0x77;      // EN1 EN2

// Any OSP frame, whatever its device and command.
struct frame {
    std::uint8_t device = 0;               // DEV
    std::uint8_t command = 0;              // CMD
    std::array<std::uint8_t, 4> params{};  // P1..P4
    friend constexpr bool operator==(const frame&, const frame&) = default;
};

constexpr auto table_of(std::type_identity<frame>) {
    return make_table<frame>("frame",
                             {{0, start1, errc::bad_header},
                              {1, start2, errc::bad_header},
                              {8, end1, errc::bad_trailer},
                              {9, end2, errc::bad_trailer}},
                             field{"device", &frame::device, 2, wire::u8{}},
                             field{"command", &frame::command, 3, wire::u8{}},
                             field{"params", &frame::params, 4, wire::u8{}});
}

namespace impl {
// Fixed bytes of a message with device `dev` and command `cmd`.
constexpr std::array<fixed_byte, 6> fixed(std::uint8_t dev, std::uint8_t cmd) noexcept {
    return {{{0, start1, errc::bad_header},
             {1, start2, errc::bad_header},
             {2, dev, errc::bad_device},
             {3, cmd, errc::bad_command},
             {8, end1, errc::bad_trailer},
             {9, end2, errc::bad_trailer}}};
}
}  // namespace impl

// Device byte (DEV) values.
namespace device_id {
inline constexpr std::uint8_t generic = 0x00;
inline constexpr std::uint8_t arm1 = 0x01;
inline constexpr std::uint8_t obp1 = 0x02;
inline constexpr std::uint8_t o2d1 = 0x03;
}  // namespace device_id

}  // namespace robowire::osp
