// robowire/reflect.hpp: the table walks every tool shares. Expected values
// from the protocol documents (docs/buwizz3.md, docs/navbot.md, docs/osp.md).
#include <robowire/reflect.hpp>
#include <robowire/buwizz3/commands.hpp>
#include <robowire/buwizz3/decode.hpp>
#include <robowire/buwizz3/status.hpp>
#include <robowire/navbot/decode.hpp>
#include <robowire/osp/messages.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

using namespace robowire;
namespace bw = robowire::buwizz3;
namespace nb = robowire::navbot;

namespace {
// How many alternatives for_each_alternative visits.
template <class V>
constexpr std::size_t alternatives() {
    std::size_t n = 0;
    for_each_alternative<V>([&](auto) { ++n; });
    return n;
}
template <class V>
constexpr std::string_view name_at(std::size_t i) {
    std::string_view s{};
    with_alternative<V>(i, [&](auto t) { s = table_v<typename decltype(t)::type>.name; });
    return s;
}
constexpr std::size_t key_index(std::initializer_list<std::uint8_t> bytes) {
    std::array<std::uint8_t, 8> b{};
    std::size_t n = 0;
    for (auto x : bytes) b[n++] = x;
    return alternative_by_key<bw::notification, 0>(std::span<const std::uint8_t>(b.data(), n));
}
// How many named bit groups status' byte `field` has.
constexpr std::size_t flag_groups(std::string_view field) {
    std::size_t n = 0;
    for_each_flag_bit<bw::status>(field, [&](const flag_bit&) { ++n; });
    return n;
}
constexpr flag_bit battery_bits() {
    flag_bit out{};
    for_each_flag_bit<bw::status>("flags", [&](const flag_bit& b) {
        if (b.name == "battery") out = b;
    });
    return out;
}
// The raw accel_raw values of a status, summed through elements_of.
constexpr long long accel_sum() {
    bw::status s{};
    s.accel_raw = {1, -2, 300};
    long long sum = 0;
    std::size_t fields = 0;
    for_each_value(s, [&](const auto& f, auto elements) {
        ++fields;
        if constexpr (value_kind_v<std::remove_cvref_t<decltype(f)>> == value_kind::integer)
            if (f.name == "accel_raw")
                for (const auto v : elements) sum += v;
        if (f.name == "pid_state" && !elements.empty()) sum += 1000000;  // absent: no element
    });
    return fields == 9 ? sum : -1;
}
// describe_lengths<M> compared with `want` (at compile time).
template <class M>
struct lengths_text {
    constexpr bool operator==(std::string_view want) const {
        std::array<char, 64> buf{};
        return describe_lengths<M>(buf) == want;
    }
};
}  // namespace

TEST_CASE("for_each_alternative and with_alternative walk a variant in order", "[core][reflect]") {
    // docs/buwizz3.md: three notifications, status, accel_calibration, charger_settings
    STATIC_REQUIRE(alternatives<bw::notification>() == 3);
    STATIC_REQUIRE(name_at<bw::notification>(0) == "status");
    STATIC_REQUIRE(name_at<bw::notification>(2) == "charger_settings");
    STATIC_REQUIRE(name_at<bw::notification>(3).empty());
    STATIC_REQUIRE(alternatives<nb::message>() == 2);
    STATIC_REQUIRE(alternative_named<bw::notification>("charger_settings") == 2);
    STATIC_REQUIRE(alternative_named<bw::notification>("maneuver") == 3);
    STATIC_REQUIRE(alternative_named<nb::message>("frame") == 1);
}

TEST_CASE("alternative_by_key finds the message a key byte names", "[core][reflect]") {
    // docs/buwizz3.md: 0x01 status, 0xAC charger_settings
    STATIC_REQUIRE(key_index({0x01, 0x00}) == 0);
    STATIC_REQUIRE(key_index({0xAC}) == 2);
    STATIC_REQUIRE(key_index({0x7E}) == 3);  // no notification 0x7E
    STATIC_REQUIRE(key_index({}) == 3);      // the input does not reach the key
    // NAVBOT: command 0x10 (CMD_MANEUVER, docs/navbot.md) at byte 2; any other command: frame (no fixed command byte)
    constexpr std::uint8_t maneuver_key[] = {0x00, 0x00, 0x10};
    constexpr std::uint8_t other_key[] = {0x00, 0x00, 0x11};
    STATIC_REQUIRE(alternative_by_key<nb::message, 2>(maneuver_key) == 0);
    STATIC_REQUIRE(alternative_by_key<nb::message, 2>(other_key) == 1);
}

TEST_CASE("matches_fixed_bytes tells which message an input was meant as", "[core][reflect]") {
    constexpr std::uint8_t status_start[] = {0x01, 0x00, 0x00};
    constexpr std::uint8_t charger[] = {0xAC};
    STATIC_REQUIRE(matches_fixed_bytes<bw::status>(status_start));
    STATIC_REQUIRE(!matches_fixed_bytes<bw::status>(charger));
    STATIC_REQUIRE(matches_fixed_bytes<bw::charger_settings>(charger));
    STATIC_REQUIRE(matches_fixed_bytes<bw::status>(std::span<const std::uint8_t>{}));  // reaches no fixed byte
    STATIC_REQUIRE(!matches_fixed_bytes<bw::pu_motor>(status_start));  // a record has no fixed byte: never
}

TEST_CASE("accepted_lengths_v: the lengths a decoder takes", "[core][reflect]") {
    // docs/buwizz3.md: status is 54 bytes, or 68 with the PID block, up to the 129-byte packet
    constexpr auto& runs = accepted_lengths_v<bw::status>;
    STATIC_REQUIRE(runs.count == 2);
    STATIC_REQUIRE(runs.run[0][0] == 54);
    STATIC_REQUIRE(runs.run[0][1] == 54);
    STATIC_REQUIRE(runs.run[1][0] == 68);
    STATIC_REQUIRE(runs.run[1][1] == 129);
    STATIC_REQUIRE(accepted_lengths_v<nb::maneuver>.count == 1);
    STATIC_REQUIRE(accepted_lengths_v<nb::maneuver>.run[0][0] == 20);  // docs/navbot.md: 20-byte frame
    // describe_lengths: the words of describe_error's length errors (docs/buwizz3.md's example line)
    STATIC_REQUIRE(lengths_text<bw::status>() == "54 or 68..129 bytes");
    STATIC_REQUIRE(lengths_text<bw::charger_settings>() == "1..129 bytes");
    STATIC_REQUIRE(lengths_text<bw::check_charger_settings>() == "1 byte");
}

TEST_CASE("value kinds, elements and physical values", "[core][reflect]") {
    using status_table = std::remove_cvref_t<decltype(table_v<bw::status>)>;
    constexpr auto& t = table_v<bw::status>;
    using flags_f = std::remove_cvref_t<decltype(t.fields.template get<0>())>;
    using battery_f = std::remove_cvref_t<decltype(t.fields.template get<1>())>;
    using record_f = std::remove_cvref_t<decltype(t.fields.template get<5>())>;
    (void)sizeof(status_table);
    STATIC_REQUIRE(value_kind_v<flags_f> == value_kind::integer);
    STATIC_REQUIRE(value_kind_v<record_f> == value_kind::record);
    using tail_f = std::remove_cvref_t<decltype(table_v<bw::charger_settings>.fields.template get<0>())>;
    STATIC_REQUIRE(value_kind_v<tail_f> == value_kind::bytes);
    // battery_voltage_raw: 9 V + raw x 0.05 V (docs/buwizz3.md): raw 20 is 10 V
    STATIC_REQUIRE(has_physical(t.fields.template get<1>()));
    STATIC_REQUIRE(!has_physical(t.fields.template get<0>()));
    STATIC_REQUIRE(physical_of(t.fields.template get<1>(), 20) == 10.0);
    (void)sizeof(battery_f);
    STATIC_REQUIRE(accel_sum() == 299);
}

TEST_CASE("flag bits of a flag byte", "[core][reflect]") {
    // docs/buwizz3.md: status flags: error, motion_wakeup, long_range_phy, battery (bits 3-4), charging, usb_connected
    STATIC_REQUIRE(flag_groups("flags") == 6);
    STATIC_REQUIRE(flag_groups("temperature_c") == 0);
    STATIC_REQUIRE(has_flag_bits_in<bw::status>("flags"));
    STATIC_REQUIRE(!has_flag_bits_in<bw::status>("battery_voltage_raw"));
    STATIC_REQUIRE(!has_flag_bits_in<nb::maneuver>("pitch"));  // names no bits at all
    constexpr flag_bit b = battery_bits();
    STATIC_REQUIRE(flag_mask(b) == 0x18);
    STATIC_REQUIRE(flag_value(b, 0x10) == 2);  // bits 3-4 = 10b: medium
    STATIC_REQUIRE(flag_value_name(b, 2) == "medium");
    STATIC_REQUIRE(flag_value_count(b) == 4);
    STATIC_REQUIRE(flag_value_count(port_bits("brake_flags")[0]) == 0);
    STATIC_REQUIRE(flag_value_name(port_bits("brake_flags")[0], 0).empty());
}
