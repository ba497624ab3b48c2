// robowire/osp/units.hpp - OSP values in physical units, in the document's
// scale or the published firmware's. Integer forms (millivolts, milliamps,
// basis points) for cores without an FPU; double forms beside them.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <cstdint>
#include <numbers>

#include "../core/divide.hpp"
#include "messages.hpp"

namespace robowire::osp {

// Whose reading of a raw value to use.
//  - document: the OSP document v0.1.0. Voltage V x 100, current mA, SOC
//    65535 = 100 %, set_angle's angle unsigned 16-bit.
//  - published_firmware: the published device firmware. OBP-1 battery:
//    voltage in mV (12600 = 12.6 V), current mA, SOC 10000 = 100 %. ORM arm:
//    set_angle's angle signed 16-bit.
enum class scale : std::uint8_t { document, published_firmware };

namespace arm1 {
// The angle as the device reads it: 0..65535 (document) or -32768..32767
// (published firmware: raw 0xC000 is -16384).
constexpr std::int32_t angle_count(std::uint16_t raw, scale s = scale::document) noexcept {
    return s == scale::document ? std::int32_t{raw} : std::int32_t{static_cast<std::int16_t>(raw)};
}
// Radians for a raw angle, 16384 = pi (the unit of the published firmware; the
// document gives none): 0 .. ~4 pi (document), -2 pi .. ~2 pi (published firmware).
constexpr double angle_to_radians(std::uint16_t raw, scale s = scale::document) noexcept {
    return angle_count(raw, s) * (std::numbers::pi / 16384.0);
}
// Raw angle for `radians`, rounded; value_out_of_range (offset 5) outside
// 0 .. 65535 counts (document) or -32768 .. 32767 counts (published firmware).
constexpr result<std::uint16_t> angle_from_radians(double radians, scale s = scale::document) noexcept {
    const double count = radians * (16384.0 / std::numbers::pi);
    const double lo = s == scale::document ? 0.0 : -32768.0, hi = s == scale::document ? 65535.0 : 32767.0;
    if (!(count >= lo - 0.5 && count < hi + 0.5)) return fail(errc::value_out_of_range, 5);
    const auto n = static_cast<std::int32_t>(count < 0 ? count - 0.5 : count + 0.5);
    return static_cast<std::uint16_t>(static_cast<std::uint32_t>(n) & 0xFFFFu);
}
}  // namespace arm1

namespace obp1 {
namespace units_detail {
// The divisions of the integer forms below (see robowire/core/divide.hpp).
using millivolts_by_10 = robowire::codec::divider<10, 327689, 6554, 16, 2>;            // (|mv| + 5) / 10
using sixteenths_by_625 = robowire::codec::divider<625, (55355000 >> 4), 839, 19, 1>;  // (bp x 5535 + 5000) / 16 / 625
}  // namespace units_detail
// ---- integer forms (no floating point)
// Battery voltage in millivolts: raw x 10 (document, -327680..327670) or raw (published firmware).
constexpr std::int32_t millivolts(std::int16_t raw, scale s = scale::document) noexcept {
    return s == scale::document ? std::int32_t{raw} * 10 : std::int32_t{raw};
}
// Current in milliamps: the raw value in both scales (-32768..32767).
constexpr std::int32_t milliamps(std::int16_t raw, scale = scale::document) noexcept { return raw; }
// State of charge in basis points (hundredths of a percent, 10000 = 100 %):
// raw x 10000 / 65535 rounded to nearest (document), or raw (published firmware,
// passed through unchanged even above 10000). No division: x / 65535 is
// (x + (x >> 16)) >> 16, exact for every raw.
constexpr std::uint16_t soc_basis_points(std::uint16_t raw, scale s = scale::document) noexcept {
    if (s == scale::published_firmware) return raw;
    const std::uint32_t x = std::uint32_t{raw} * 10000u + 32767u;  // at most 655382767
    return static_cast<std::uint16_t>((x + (x >> 16)) >> 16);
}
constexpr std::int32_t millivolts(const voltage& m, scale s = scale::document) noexcept {
    return millivolts(m.centivolts, s);
}
constexpr std::int32_t milliamps(const current& m, scale s = scale::document) noexcept {
    return milliamps(m.milliamps, s);
}
constexpr std::uint16_t soc_basis_points(const soc& m, scale s = scale::document) noexcept {
    return soc_basis_points(m.soc_raw, s);
}
// Raw voltage for `mv` millivolts (document: mv / 10 rounded half away from
// zero; published firmware: mv); value_out_of_range (offset 4) if it does not
// fit the i16 field (document: mv outside -327684..327674). No library
// division on a core without a divide instruction.
constexpr result<std::int16_t> voltage_from_millivolts(std::int32_t mv, scale s = scale::document) noexcept {
    if (s == scale::published_firmware) {
        if (mv < -32768 || mv > 32767) return fail(errc::value_out_of_range, 4);
        return static_cast<std::int16_t>(mv);
    }
    if (mv < -327684 || mv > 327674) return fail(errc::value_out_of_range, 4);
    const std::uint32_t n = (mv < 0 ? 0u - static_cast<std::uint32_t>(mv) : static_cast<std::uint32_t>(mv)) + 5u;
    const std::uint32_t q = units_detail::millivolts_by_10{}(n);
    return static_cast<std::int16_t>(mv < 0 ? -static_cast<std::int32_t>(q) : static_cast<std::int32_t>(q));
}
// Raw SOC for `bp` basis points (0..10000; document: bp x 65535 / 10000
// rounded half up, published firmware: bp); value_out_of_range (offset 4)
// above 10000. No library division on a core without a divide instruction.
constexpr result<std::uint16_t> soc_from_basis_points(std::uint16_t bp, scale s = scale::document) noexcept {
    if (bp > 10000) return fail(errc::value_out_of_range, 4);
    if (s == scale::published_firmware) return bp;
    // bp x 65535 + 5000 = bp x 60000 + (bp x 5535 + 5000), and floor(w / 10000) = floor(floor(w / 16) / 625)
    const std::uint32_t w = std::uint32_t{bp} * 5535u + 5000u;  // at most 55355000
    return static_cast<std::uint16_t>(std::uint32_t{bp} * 6u + units_detail::sixteenths_by_625{}(w >> 4));
}

// ---- double forms
constexpr double volts(std::int16_t raw, scale s = scale::document) noexcept {
    return s == scale::document ? raw / 100.0 : raw / 1000.0;
}
constexpr double amps(std::int16_t raw, scale = scale::document) noexcept { return raw / 1000.0; }
// 0..100 % (document); raw / 100 (published firmware).
constexpr double soc_percent(std::uint16_t raw, scale s = scale::document) noexcept {
    return s == scale::document ? raw * (100.0 / 65535.0) : raw / 100.0;
}
constexpr double volts(const voltage& m, scale s = scale::document) noexcept { return volts(m.centivolts, s); }
constexpr double amps(const current& m, scale s = scale::document) noexcept { return amps(m.milliamps, s); }
constexpr double soc_percent(const soc& m, scale s = scale::document) noexcept { return soc_percent(m.soc_raw, s); }
// Raw SOC for a percentage 0..100 (rounded); value_out_of_range (offset 4) outside.
constexpr result<std::uint16_t> soc_from_percent(double percent, scale s = scale::document) noexcept {
    if (!(percent >= 0.0 && percent <= 100.0)) return fail(errc::value_out_of_range, 4);
    return static_cast<std::uint16_t>(percent * (s == scale::document ? 655.35 : 100.0) + 0.5);
}
}  // namespace obp1

}  // namespace robowire::osp
