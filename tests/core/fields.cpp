#include <robowire/core/fields.hpp>
#include <robowire/buwizz3/commands.hpp>
#include <robowire/buwizz3/decode.hpp>
#include <robowire/buwizz3/status.hpp>
#include <robowire/navbot/decode.hpp>
#include <robowire/navbot/maneuver.hpp>
#include <robowire/navbot/multiframe.hpp>
#include <robowire/osp/messages.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <variant>

using namespace robowire;
namespace nb = robowire::navbot;

namespace {
// set_field at compile time: the error and the pitch afterwards.
constexpr std::pair<error, int> set_pitch(long long v) {
    nb::maneuver m{};
    m.pitch = 5;
    const error e = set_field<&nb::maneuver::pitch>(m, v);
    return {e, m.pitch};
}
constexpr std::string_view describe(const error& e, std::array<char, 96>& buf) {
    return describe_error<nb::maneuver>(e, buf);
}
}  // namespace

TEST_CASE("set_field checks a wider integer against the field's range", "[core][fields]") {
    // pitch: byte index 7, -100..100 (docs/navbot.md's table)
    STATIC_REQUIRE(set_pitch(200) == std::pair<error, int>{error{errc::value_out_of_range, 7}, 5});  // 200 would wrap to -56
    STATIC_REQUIRE(set_pitch(-101) == std::pair<error, int>{error{errc::value_out_of_range, 7}, 5});
    STATIC_REQUIRE(set_pitch(-100) == std::pair<error, int>{error{}, -100});
    STATIC_REQUIRE(set_pitch(100) == std::pair<error, int>{error{}, 100});
    STATIC_REQUIRE(set_pitch(4294967296LL + 10) == std::pair<error, int>{error{errc::value_out_of_range, 7}, 5});
    nb::maneuver m{};
    CHECK(set_field<&nb::maneuver::height>(m, 100u) == error{});
    CHECK(m.height == 100);
    CHECK(set_field<&nb::maneuver::height>(m, -1) == error{errc::value_out_of_range, 6});
    CHECK(set_field<&nb::maneuver::height>(m, std::uint64_t{0xFFFFFFFFFFFFFFFF}) == error{errc::value_out_of_range, 6});
    CHECK(m.height == 100);
    CHECK(set_field<&nb::maneuver::ball_x>(m, 6) == error{errc::value_out_of_range, 13});
    // enums: only the enumeration's codes (switch_a: 0, 1, 2)
    CHECK(set_field<&nb::maneuver::switch_a>(m, 2) == error{});
    CHECK(m.switch_a == nb::switch_a::start_touch_panel);
    CHECK(set_field<&nb::maneuver::switch_a>(m, 3) == error{errc::invalid_enum, 9});
    CHECK(set_field<&nb::maneuver::switch_a>(m, 258) == error{errc::invalid_enum, 9});  // not 258 % 256 = 2
    CHECK(m.switch_a == nb::switch_a::start_touch_panel);
}

TEST_CASE("field_at and field_of name the field behind an offset", "[core][fields]") {
    STATIC_REQUIRE(field_at<nb::maneuver>(7).name == "pitch");
    STATIC_REQUIRE(field_at<nb::maneuver>(7).valid.min == -100);
    STATIC_REQUIRE(field_at<nb::maneuver>(7).valid.max == 100);
    STATIC_REQUIRE(field_at<nb::maneuver>(6).name == "height");
    STATIC_REQUIRE(field_at<nb::maneuver>(6).unit == "%");
    STATIC_REQUIRE(field_at<nb::maneuver>(9).is_enum);
    STATIC_REQUIRE(field_at<nb::maneuver>(error{errc::value_out_of_range, 14}).name == "ball_y");
    STATIC_REQUIRE(!field_at<nb::maneuver>(0));   // header byte
    STATIC_REQUIRE(!field_at<nb::maneuver>(16));  // reserved byte
    STATIC_REQUIRE(!field_at<nb::maneuver>(99));
    STATIC_REQUIRE(field_at<nb::maneuver>(0).message == "maneuver");
    STATIC_REQUIRE(field_of<&nb::maneuver::yaw>().offset == 8);
    STATIC_REQUIRE(field_of<&nb::maneuver::yaw>().size == 1);
    STATIC_REQUIRE(field_of<&nb::maneuver::ball_x>().valid.max == 5);
}

TEST_CASE("describe_error writes the field, its range and the offset", "[core][fields]") {
    std::array<char, 96> buf{};
    CHECK(describe(error{errc::value_out_of_range, 7}, buf) ==
          "maneuver.pitch: value out of range (valid -100..100 %) at byte 7");
    CHECK(describe(error{errc::invalid_enum, 9}, buf) == "maneuver.switch_a: value is not a valid code at byte 9");
    CHECK(describe(error{errc::bad_header, 1}, buf) == "maneuver: bad header byte at byte 1");
    // a unit that scales the raw values (BuWizz3 power: raw 127 is 100 %): the range says "raw"
    CHECK(describe_error<robowire::buwizz3::set_motor_data>(error{errc::value_out_of_range, 3}, buf) ==
          "set_motor_data.power: value out of range (valid -127..127 raw) at byte 3");
    STATIC_REQUIRE(!field_of<&robowire::buwizz3::set_motor_data::power>().raw_is_physical);
    STATIC_REQUIRE(field_of<&nb::maneuver::pitch>().raw_is_physical);
    std::array<char, 10> small{};
    CHECK(describe_error<nb::maneuver>(error{errc::value_out_of_range, 7}, small) == "maneuver.p");  // cut to fit
}

TEST_CASE("describe_error gives no range for text, records and floats", "[core][fields]") {
    namespace bw = robowire::buwizz3;
    std::array<char, 96> buf{};
    // their table range is a placeholder (0..0): a range would be false
    CHECK(describe_error<bw::set_device_name>(error{errc::value_out_of_range, 1}, buf) ==
          "set_device_name.name: value out of range at byte 1");
    CHECK(describe_error<bw::set_led_status>(error{errc::value_out_of_range, 5}, buf) ==
          "set_led_status.colors: value out of range at byte 5");
    CHECK(describe_error<bw::set_accel_calibration>(error{errc::value_out_of_range, 1}, buf) ==
          "set_accel_calibration.factors: value out of range at byte 1");
    STATIC_REQUIRE(!field_at<bw::set_device_name>(1).has_range);
    STATIC_REQUIRE(field_at<bw::set_data_period>(1).has_range);
}

TEST_CASE("describe_error gives the lengths a message takes for too_short and too_long", "[core][fields]") {
    std::array<char, 96> buf{};
    // BuWizz3 status: 54 bytes, or 68 with the PID block, up to 129 with trailing bytes (docs/buwizz3.md)
    CHECK(describe_error<robowire::buwizz3::status>(error{errc::too_short, 4}, buf) ==
          "status: input too short (54 or 68..129 bytes) at byte 4");
    // LED status 0x36: the command alone, with 4 colours (13), with blinking too (17)
    CHECK(describe_error<robowire::buwizz3::set_led_status>(error{errc::too_long, 17}, buf) ==
          "set_led_status: input too long (1, 13 or 17 bytes) at byte 17");
    CHECK(describe(error{errc::too_long, 20}, buf) == "maneuver: input too long (20 bytes) at byte 20");
    // a length error inside an optional block names that block, and the lengths too
    CHECK(describe_error<robowire::buwizz3::status>(error{errc::bad_length, 54}, buf) ==
          "status.pid_state: length matches no form of the message (54 or 68..129 bytes) at byte 54");
    CHECK(describe_error<robowire::buwizz3::set_led_status>(error{errc::bad_length, 13}, buf) ==
          "set_led_status.blink: length matches no form of the message (1, 13 or 17 bytes) at byte 13");
}

namespace {
// The longest describe_error line of a length error of any message of Variant.
template <class... M>
std::size_t longest_length_error(std::variant<M...>*) {
    std::size_t longest = 0;
    const auto measure = [&]<class T>(std::type_identity<T>) {
        std::array<char, 200> buf{};
        for (const errc code : {errc::too_short, errc::too_long}) {
            const auto s = describe_error<T>(error{code, 4}, buf);
            longest = s.size() > longest ? s.size() : longest;
        }
        for_each_field<T>([&](const auto& f) {
            if (!f.is_optional) return;
            const auto s = describe_error<T>(error{errc::bad_length, static_cast<std::uint16_t>(f.offset)}, buf);
            longest = s.size() > longest ? s.size() : longest;
        });
    };
    (measure(std::type_identity<M>{}), ...);
    return longest;
}
}  // namespace

TEST_CASE("describe_error's length errors fit the README's 96-byte buffer", "[core][fields]") {
    CHECK(longest_length_error(static_cast<robowire::buwizz3::command*>(nullptr)) < 96);
    CHECK(longest_length_error(static_cast<robowire::buwizz3::notification*>(nullptr)) < 96);
    CHECK(longest_length_error(static_cast<robowire::osp::message*>(nullptr)) < 96);
    CHECK(longest_length_error(static_cast<robowire::navbot::message*>(nullptr)) < 96);
}

TEST_CASE("describe_error of a variant decode names the message its key names", "[core][fields]") {
    namespace bw = robowire::buwizz3;
    std::array<char, 96> buf{};
    // status (0x01) cut after 2 bytes: the message is known from byte 0
    const std::uint8_t status_start[] = {0x01, 0x00};
    auto n = bw::decode_notification(status_start);
    REQUIRE(n.error() == error{errc::too_short, 2});
    CHECK(describe_error<bw::notification>(n.error(), status_start, buf) ==
          "status: input too short (54 or 68..129 bytes) at byte 2");
    // a command byte no notification has
    const std::uint8_t unknown[] = {0x3A, 0x00};
    n = bw::decode_notification(unknown);
    REQUIRE(n.error() == error{errc::unknown_message, 0});
    CHECK(describe_error<bw::notification>(n.error(), unknown, buf) == "unknown key 0x3A at byte 0");
    // nothing to read the key from
    n = bw::decode_notification({});
    REQUIRE(n.error() == error{errc::too_short, 0});
    CHECK(describe_error<bw::notification>(n.error(), {}, buf) == "input too short at byte 0");
    // a command: set_data_period (0x32) with 10 ms, below its 20..255 ms
    const std::uint8_t period[] = {0x32, 0x0A};
    const auto c = bw::decode_command(period);
    REQUIRE(c.error() == error{errc::value_out_of_range, 1});
    CHECK(describe_error<bw::command>(c.error(), period, buf) ==
          "set_data_period.period_ms: value out of range (valid 20..255 ms) at byte 1");
    std::array<char, 12> small{};
    // another error with a key no message has: "unknown key 0x3A: input too short at byte 0", cut to fit
    CHECK(describe_error<bw::notification>(n.error(), unknown, small) == "unknown key ");
}

TEST_CASE("navbot::describe_error names the maneuver or the frame", "[core][fields]") {
    std::array<char, 96> buf{};
    // a maneuver (command 0x10) with pitch 0x9B = -101
    std::array<std::uint8_t, 20> m{0x55, 0xAA, 0x10, 0x00, 0x00, 0, 0, 0x9B};
    const auto r = nb::decode_frame(m);
    REQUIRE(r.error() == error{errc::value_out_of_range, 7});
    CHECK(nb::describe_error(r.error(), m, buf) == "maneuver.pitch: value out of range (valid -100..100 %) at byte 7");
    // a reassembler outcome: a JSON message (0x02) of 3 frames whose middle frame was lost
    nb::reassembler<120> reassembly;
    std::array<std::uint8_t, 20> f{0x55, 0xAA, 0x02, 0x02, 0x00, '{'};
    REQUIRE(reassembly.push(f).value() == nb::reassembly::need_more);
    f[3] = 0x00;
    const auto lost = reassembly.push(f);
    REQUIRE(lost.error() == error{errc::bad_sequence, 3});
    CHECK(nb::describe_error(lost.error(), f, buf) == "frame.remaining: frame out of sequence at byte 3");
    // a bad header: the frame's line, whatever the command
    f[0] = 0x56;
    CHECK(nb::describe_error(reassembly.push(f).error(), f, buf) == "frame: bad header byte at byte 0");
    CHECK(nb::describe_error(error{errc::too_short, 2}, std::span(f).first(2), buf) ==
          "frame: input too short (20 bytes) at byte 2");
}
