#include <robowire/buwizz3/status.hpp>
#include <robowire/buwizz3/units.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"

using namespace robowire;
using namespace robowire::buwizz3;

namespace {
// Every field non-zero and distinct, worked out by hand:
//  1 flags 0x73 = 0111 0011: error, motion wake-up, battery level 2 (bits 3-4 = 10), charging, USB
//  2 battery 0x50 = 80 -> 9 + 80 x 0.05 = 13.0 V
//  3-8 currents 10 20 30 40 50 200 (200 x 0.015 = 3.0 A)
//  9 temperature 0x23 = 35 C
//  10-15 accel x -16 (F0 FF: count -1, -7.808 mg), y 0x7FF0 (F0 7F: count 2047), z 0x0800 (00 08: count 128)
//  16-20 bootloader response 0B 0C 0D 0E 0F; 21 charge current 0x7D = 125 mA
//  22 motor 1: type 0x30, velocity -20 (EC), abs -180 (4C FF), position -100000 (0xFFFE7960: 60 79 FE FF)
//  30 motor 2: type 0x31, velocity 100 (64), abs 179 (B3 00), position 123456 (0x0001E240: 40 E2 01 00)
//  38 motor 3: type 0x4B, velocity -1 (FF), abs 1, position 1
//  46 motor 4: type 0x4C, velocity 127 (7F), abs -1 (FF FF), position 2147483647 (FF FF FF 7F)
//  54 process value 0.6f (0x3F19999A), 58 error -2.5f (0xC0200000), 62 output 12.75f (0x414C0000)
//  66 integrator -7 (F9), 67 motor output 42 (2A)
constexpr auto full68 = test::hex(
    "01 73 50 0A 14 1E 28 32 C8 23 F0 FF F0 7F 00 08 0B 0C 0D 0E 0F 7D"
    "30 EC 4C FF 60 79 FE FF"
    "31 64 B3 00 40 E2 01 00"
    "4B FF 01 00 01 00 00 00"
    "4C 7F FF FF FF FF FF 7F"
    "9A 99 19 3F 00 00 20 C0 00 00 4C 41 F9 2A");

// (built without ever resetting pid_state: clang 14 cannot copy a reset optional in constant evaluation)
constexpr status twin54() {
    status s;
    s.flags = 0x73;
    s.battery_voltage_raw = 80;
    s.motor_current_raw = {10, 20, 30, 40, 50, 200};
    s.temperature_c = 35;
    s.accel_raw = {-16, 0x7FF0, 0x0800};
    s.bootloader_response = {0x0B, 0x0C, {0x0D, 0x0E, 0x0F}};
    s.charge_current_ma = 125;
    s.pu_motors = {{{0x30, -20, -180, -100000}, {0x31, 100, 179, 123456}, {0x4B, -1, 1, 1}, {0x4C, 127, -1, 2147483647}}};
    return s;
}
constexpr status full_status() {
    status s = twin54();
    s.pid_state = pid_state{0.6f, -2.5f, 12.75f, -7, 42};
    return s;
}
constexpr bytes<256> first(std::size_t n) {
    bytes<256> b;
    for (std::size_t i = 0; i < n; ++i) (void)b.push_back(full68[i]);
    return b;
}
constexpr error decode_error(std::span<const std::uint8_t> b) { return robowire::decode<status>(b).error(); }
}  // namespace

TEST_CASE("buwizz3: 68-byte status golden vector", "[buwizz3][status]") {
    STATIC_REQUIRE(full68.size() == 68);
    STATIC_REQUIRE(robowire::decode<status>(full68).value() == full_status());
    STATIC_REQUIRE(robowire::encode(full_status()).value() == full68);
    const auto s = robowire::decode<status>(full68).value();
    CHECK(s == full_status());
    CHECK(s.pu_motors[0].position == -100000);
    CHECK(s.pid_state->output == 12.75f);
    CHECK(robowire::encode(s).value() == full68);
}

TEST_CASE("buwizz3: 54-byte status twin", "[buwizz3][status]") {
    STATIC_REQUIRE(robowire::decode<status>(first(54)).value() == twin54());
    STATIC_REQUIRE(robowire::encode(twin54()).value() == first(54));
    CHECK_FALSE(robowire::decode<status>(first(54))->pid_state.has_value());
}

TEST_CASE("buwizz3: decode_into a 54-byte status empties a held PID block", "[buwizz3][status]") {
    status s = full_status();
    REQUIRE(s.pid_state.has_value());
    CHECK(robowire::decode_into(s, first(54)).code == errc::ok);
    CHECK_FALSE(s.pid_state.has_value());
    CHECK(s == twin54());
}

TEST_CASE("buwizz3: status flags and units", "[buwizz3][status]") {
    constexpr auto s = full_status();
    STATIC_REQUIRE(s.error());
    STATIC_REQUIRE(s.motion_wakeup_enabled());
    STATIC_REQUIRE(!s.long_range_phy());
    STATIC_REQUIRE(s.battery_level() == battery_level::medium);
    STATIC_REQUIRE(s.charging());
    STATIC_REQUIRE(s.usb_connected());
    STATIC_REQUIRE(battery_volts(s) == 13.0);
    STATIC_REQUIRE(motor_amps(s, 5) == 3.0);
    STATIC_REQUIRE(accel_count(s.accel_raw[0]) == -1);
    STATIC_REQUIRE(accel_count(s.accel_raw[1]) == 2047);
    STATIC_REQUIRE(accel_count(s.accel_raw[2]) == 128);
    CHECK(battery_volts(std::uint8_t{127}) == Approx(15.35));
    CHECK(accel_milli_g(s.accel_raw[0]) == Approx(-7.808));
    CHECK(accel_milli_g(s.accel_raw[2]) == Approx(999.424));
    status flags_only;
    flags_only.flags = 0x1C;  // 0001 1100: long range, battery level 3
    CHECK(flags_only.long_range_phy());
    CHECK(flags_only.battery_level() == battery_level::full);
    CHECK_FALSE(flags_only.error());
}

TEST_CASE("buwizz3: status lengths", "[buwizz3][status]") {
    STATIC_REQUIRE(decode_error(first(53)) == error{errc::too_short, 53});
    STATIC_REQUIRE(decode_error(first(55)) == error{errc::bad_length, 54});  // truncated PID block
    STATIC_REQUIRE(decode_error(first(67)) == error{errc::bad_length, 54});
    STATIC_REQUIRE(decode_error(first(0)) == error{errc::too_short, 0});
    constexpr auto wrong = [] { auto b = first(54); b[0] = 0x02; return b; }();
    STATIC_REQUIRE(decode_error(wrong) == error{errc::bad_command, 0});
    // Longer than 68, up to 129 bytes: known fields decoded, the rest counted.
    auto longer = first(68);
    for (int i = 0; i < 5; ++i) REQUIRE(longer.push_back(0xEE));
    const auto s = robowire::decode<status>(longer).value();
    CHECK(s.ignored_trailing_bytes == 5);
    CHECK(s.pid_state == full_status().pid_state);
    CHECK(robowire::encode(s).value() == first(68));
    auto max = first(68);
    while (max.size() < 129) REQUIRE(max.push_back(0));
    CHECK(robowire::decode<status>(max)->ignored_trailing_bytes == 61);
    REQUIRE(max.push_back(0));
    CHECK(decode_error(max) == error{errc::too_long, 129});
}
