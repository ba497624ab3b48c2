#include <robowire/navbot/decode.hpp>
#include <robowire/navbot/maneuver.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"
#include "round_trips.hpp"

using namespace robowire;
using namespace robowire::navbot;

namespace {
// Every field non-zero: roll -100 (0x9C), height 100 (0x64), pitch 55 (0x37), yaw -1 (0xFF),
// A start + touch panel (2), B mark (1), C lock (1), D ball poise (2), ball x -5 (0xFB), ball y 5.
constexpr maneuver all_fields{-100, 100, 55, -1, switch_a::start_touch_panel, switch_b::mark,
                              switch_c::lock, switch_d::ball_poise, -5, 5};
constexpr auto all_fields_twos = test::hex("55 AA 10 00 00 9C 64 37 FF 02 01 01 02 FB 05 00 00 00 00 00");
// Sign-magnitude: -100 -> 0x80|0x64 = E4, -1 -> 81, -5 -> 85.
constexpr auto all_fields_sm = test::hex("55 AA 10 00 00 E4 64 37 81 02 01 01 02 85 05 00 00 00 00 00");

constexpr error decode_error(std::string_view hex) { return robowire::decode<maneuver>(test::hex(hex)).error(); }
constexpr error encode_error(const maneuver& m) { return robowire::encode(m).error(); }
constexpr maneuver with(auto change) {
    maneuver m{};
    change(m);
    return m;
}

// The document's samples are 22 bytes with every field one byte late: an extra
// 00 at index 5 and one at the end. Dropping those two gives the 20-byte frame.
constexpr bytes<20> corrected(std::string_view sample22) {
    const auto s = test::hex(sample22);
    bytes<20> out;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (i != 5 && i != 21) (void)out.push_back(s[i]);
    return out;
}
}  // namespace

TEST_CASE("navbot: maneuver golden vector", "[navbot]") {
    STATIC_REQUIRE(robowire::encode(all_fields).value() == all_fields_twos);
    STATIC_REQUIRE(robowire::decode<maneuver>(all_fields_twos).value() == all_fields);
    STATIC_REQUIRE(navbot::encode(all_fields, sign_encoding::sign_magnitude).value() == all_fields_sm);
    STATIC_REQUIRE(decode_maneuver(all_fields_sm, sign_encoding::sign_magnitude).value() == all_fields);
    CHECK(robowire::encode(all_fields).value() == all_fields_twos);
    CHECK(navbot::encode(all_fields).value() == all_fields_twos);
    CHECK(decode_maneuver(all_fields_twos).value() == all_fields);
}

TEST_CASE("navbot: the document's samples, sign-magnitude, once the 22-byte error is undone", "[navbot]") {
    constexpr maneuver stand{0, 0, 0, 0, switch_a::start};
    constexpr maneuver forward{0, 0, 10, 0, switch_a::start};
    constexpr maneuver back{0, 0, -10, 0, switch_a::start};
    constexpr maneuver clockwise{0, 0, 0, 8, switch_a::start};
    constexpr maneuver counterclockwise{0, 0, 0, -8, switch_a::start};
    constexpr auto sm = sign_encoding::sign_magnitude;
    STATIC_REQUIRE(navbot::encode(stand, sm).value() == corrected("55 AA 10 00 00 00 00 00 00 00 01 00 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(navbot::encode(forward, sm).value() == corrected("55 AA 10 00 00 00 00 00 0A 00 01 00 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(navbot::encode(back, sm).value() == corrected("55 AA 10 00 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(navbot::encode(clockwise, sm).value() == corrected("55 AA 10 00 00 00 00 00 00 08 01 00 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(navbot::encode(counterclockwise, sm).value() == corrected("55 AA 10 00 00 00 00 00 00 88 01 00 00 00 00 00 00 00 00 00 00 00"));
    // The same movements as the robot reads them (two's complement), by hand.
    STATIC_REQUIRE(robowire::encode(back).value() == test::hex("55 AA 10 00 00 00 00 F6 00 01 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(robowire::encode(counterclockwise).value() == test::hex("55 AA 10 00 00 00 00 00 F8 01 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(robowire::encode(forward).value() == test::hex("55 AA 10 00 00 00 00 0A 00 01 00 00 00 00 00 00 00 00 00 00"));
    CHECK(navbot::encode(back, sm).value() == corrected("55 AA 10 00 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00 00"));
}

TEST_CASE("navbot: why the default is two's complement", "[navbot]") {
    // The document's "back at speed 10" byte, read the way the robot reads it, is -118:
    // outside -100..100, so robowire refuses it instead of passing it on.
    constexpr auto doc_back = test::hex("55 AA 10 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00");
    STATIC_REQUIRE(static_cast<std::int8_t>(0x8A) == -118);
    STATIC_REQUIRE(decode_maneuver(doc_back).error() == error{errc::value_out_of_range, 7});
    STATIC_REQUIRE(decode_maneuver(doc_back, sign_encoding::sign_magnitude)->pitch == -10);
}

TEST_CASE("navbot: the document's 22-byte samples are a length error that says why", "[navbot]") {
    constexpr auto sample = test::hex("55 AA 10 00 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00 00");
    STATIC_REQUIRE(sample.size() == 22);
    STATIC_REQUIRE(robowire::decode<maneuver>(sample).error() == error{errc::too_long, 20});
    STATIC_REQUIRE(decode_frame(sample).error() == error{errc::too_long, 20});
    CHECK(length_error_text(sample.size()).find("transcription error") != std::string_view::npos);
    CHECK(length_error_text(21) == "NAVBOT frames are 20 bytes");
}

TEST_CASE("navbot: maneuver ranges on decode", "[navbot]") {
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 65 00 00 00 00 00 00 00 00 00 00 00 00 00 00") == error{errc::value_out_of_range, 5});  // roll 101
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 9B 00 00 00 00 00 00 00 00 00 00 00 00 00 00") == error{errc::value_out_of_range, 5});  // roll -101
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 65 00 00 00 00 00 00 00 00 00 00 00 00 00") == error{errc::value_out_of_range, 6});  // height 101
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 80 00 00 00 00 00 00 00 00 00 00 00") == error{errc::value_out_of_range, 8});  // yaw -128
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 00 03 00 00 00 00 00 00 00 00 00 00") == error{errc::invalid_enum, 9});
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 00 00 02 00 00 00 00 00 00 00 00 00") == error{errc::invalid_enum, 10});
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 00 00 00 02 00 00 00 00 00 00 00 00") == error{errc::invalid_enum, 11});
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 00 00 00 00 03 00 00 00 00 00 00 00") == error{errc::invalid_enum, 12});
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 00 00 00 00 00 06 00 00 00 00 00 00") == error{errc::value_out_of_range, 13});
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 00 00 00 00 00 00 FA 00 00 00 00 00") == error{errc::value_out_of_range, 14});
    STATIC_REQUIRE(decode_error("55 AB 10 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00") == error{errc::bad_header, 1});
    STATIC_REQUIRE(decode_error("55 AA 11 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00") == error{errc::bad_command, 2});
    STATIC_REQUIRE(decode_error("55 AA 10 01 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00") == error{errc::bad_sequence, 3});
    STATIC_REQUIRE(decode_error("55 AA 10 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00") == error{errc::too_short, 19});
    CHECK(decode_error("55 AA 10 00 00 00 00 00 00 00 00 00 00 00 FA 00 00 00 00 00") == error{errc::value_out_of_range, 14});
    // reserved bytes are ignored, and reported by the strict check
    constexpr auto junk = test::hex("55 AA 10 00 07 00 00 00 00 00 00 00 00 00 00 00 00 00 00 09");
    STATIC_REQUIRE(robowire::decode<maneuver>(junk).has_value());
    STATIC_REQUIRE(check_reserved<maneuver>(junk).error() == error{errc::reserved_not_zero, 4});
}

TEST_CASE("navbot: maneuver ranges on encode", "[navbot]") {
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.roll = 101; })) == error{errc::value_out_of_range, 5});
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.height = 101; })) == error{errc::value_out_of_range, 6});
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.pitch = -101; })) == error{errc::value_out_of_range, 7});
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.yaw = 127; })) == error{errc::value_out_of_range, 8});
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.switch_a = switch_a{3}; })) == error{errc::invalid_enum, 9});
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.switch_d = switch_d{7}; })) == error{errc::invalid_enum, 12});
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.ball_x = -6; })) == error{errc::value_out_of_range, 13});
    STATIC_REQUIRE(encode_error(with([](maneuver& m) { m.ball_y = 6; })) == error{errc::value_out_of_range, 14});
    CHECK(navbot::encode(with([](maneuver& m) { m.pitch = -101; }), sign_encoding::sign_magnitude).error() ==
          error{errc::value_out_of_range, 7});
}

TEST_CASE("navbot: decode_frame dispatches", "[navbot]") {
    STATIC_REQUIRE(std::get<maneuver>(decode_frame(all_fields_twos).value()) == all_fields);
    constexpr auto json = test::hex("55 AA 02 01 00 7B 22 74 79 70 65 22 3A 22 67 65 74 5F 64 65");
    STATIC_REQUIRE(std::get<frame>(decode_frame(json).value()).command == command::json);
    STATIC_REQUIRE(std::get<frame>(decode_frame(json).value()).remaining == 1);
    STATIC_REQUIRE(std::get<frame>(decode_frame(json).value()).payload[0] == '{');
    CHECK(decode_frame(test::hex("55 AA 10 00 00 00 00 00 00 09 00 00 00 00 00 00 00 00 00 00")).error() ==
          error{errc::invalid_enum, 9});
}

namespace {
// A message of another command (0x03), single frame, one byte: what a new
// NAVBOT message looks like to decode_frame.
struct lamp {
    std::uint8_t level = 0;
    friend constexpr bool operator==(const lamp&, const lamp&) = default;
};
constexpr auto table_of(std::type_identity<lamp>) {
    auto t = make_table<lamp>("lamp",
                              {{0, header1, errc::bad_header}, {1, header2, errc::bad_header}, {2, 0x03, errc::bad_command},
                               {3, 0x00, errc::bad_sequence}},
                              field{"level", &lamp::level, 5, wire::u8{}});
    t.declared_size = frame_size;
    return t;
}
// The frame first: decode_frame finds the frame alternative by its table (no fixed command byte), not its place.
using with_lamp = std::variant<frame, lamp, maneuver>;
}  // namespace

TEST_CASE("navbot: decode_frame is driven by the variant's tables", "[navbot]") {
    constexpr auto lamp_frame = test::hex("55 AA 03 00 00 2A 00 00 00 00 00 00 00 00 00 00 00 00 00 00");
    STATIC_REQUIRE(std::get<lamp>(decode_frame<with_lamp>(lamp_frame).value()) == lamp{42});
    STATIC_REQUIRE(std::get<maneuver>(decode_frame<with_lamp>(all_fields_twos).value()) == all_fields);
    constexpr auto json = test::hex("55 AA 02 00 00 7B 7D 00 00 00 00 00 00 00 00 00 00 00 00 00");
    STATIC_REQUIRE(std::get<frame>(decode_frame<with_lamp>(json).value()).command == command::json);
    // the default variant has no lamp: a 0x03 frame stays a frame
    STATIC_REQUIRE(std::get<frame>(decode_frame(lamp_frame).value()).command == 0x03);
    // the alternative's own checks apply: `remaining` must be 0
    CHECK(decode_frame<with_lamp>(test::hex("55 AA 03 01 00 2A 00 00 00 00 00 00 00 00 00 00 00 00 00 00")).error() ==
          error{errc::bad_sequence, 3});
    test::check_each_round_trips<with_lamp>([](const with_lamp& m) { return robowire::encode(m); },
                                            [](std::span<const std::uint8_t> in) { return decode_frame<with_lamp>(in); });
}

TEST_CASE("navbot: every message round trips through the variant", "[navbot]") {
    STATIC_REQUIRE(std::variant_size_v<message> >= 2);
    test::check_each_round_trips<message>([](const message& m) { return robowire::encode(m); },
                                          [](std::span<const std::uint8_t> in) { return decode_frame(in); });
}

TEST_CASE("navbot: BLE constants and name matching", "[navbot]") {
    STATIC_REQUIRE(service_uuid.on_air()[0] == 0x9E);  // ...dcca9e, least significant first
    STATIC_REQUIRE((service_uuid.value[0] == 0x6E && service_uuid.value[3] == 0x11));
    STATIC_REQUIRE(write_uuid.short_value() == 0x0012);
    STATIC_REQUIRE(notify_uuid.short_value() == 0x0013);
    STATIC_REQUIRE(is_navbot_name("navbot_es02-A1B2"));
    STATIC_REQUIRE(!is_navbot_name("navbot_es02-"));
    STATIC_REQUIRE(!is_navbot_name("navbot_es01-A1B2"));
    // flags, complete local name "navbot_es02-7F" (14 chars -> length 15 = 0x0F)
    constexpr auto adv = test::hex("02 01 06 0F 09 6E 61 76 62 6F 74 5F 65 73 30 32 2D 37 46");
    STATIC_REQUIRE(matches_advertisement(adv));
    constexpr auto other = test::hex("02 01 06 08 09 42 75 57 69 7A 7A 33");  // "BuWizz3"
    STATIC_REQUIRE(!matches_advertisement(other));
    CHECK(matches_advertisement(adv));
}
