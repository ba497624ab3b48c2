#include <robowire/buwizz3/commands.hpp>
#include <robowire/buwizz3/decode.hpp>

#include <algorithm>

#include <catch2/catch.hpp>

#include "check.hpp"
#include "round_trips.hpp"

using namespace robowire;
using namespace robowire::buwizz3;

namespace {
template <class M>
constexpr bool golden(const M& m, std::string_view hex) {
    const auto want = test::hex(hex);
    const auto enc = robowire::encode(m);
    const auto dec = robowire::decode<M>(want);
    return enc && *enc == want && dec && *dec == m;
}
template <class M>
constexpr error decode_error(std::string_view hex) {
    return robowire::decode<M>(test::hex(hex)).error();
}
template <class M>
constexpr error encode_error(const M& m) {
    return robowire::encode(m).error();
}
// 1.0f 3F800000, -1.0f BF800000, 0.5f 3F000000, 0.6f 3F19999A, -2.5f C0200000, 0.0f
constexpr std::array<float, 6> factors{1.0f, -1.0f, 0.5f, 0.6f, -2.5f, 0.0f};
}  // namespace

TEST_CASE("buwizz3: 0x20 set_device_name", "[buwizz3][commands]") {
    // "MyBrick" = 4D 79 42 72 69 63 6B, NUL-padded to 12 bytes
    STATIC_REQUIRE(golden(set_device_name{"MyBrick"}, "20 4D 79 42 72 69 63 6B 00 00 00 00 00"));
    STATIC_REQUIRE(golden(set_device_name{"ABCDEFGHIJKL"}, "20 41 42 43 44 45 46 47 48 49 4A 4B 4C"));
    STATIC_REQUIRE(golden(set_device_name{}, "20 00 00 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(text<12>::make("ABCDEFGHIJKLM").error() == error{errc::value_out_of_range, 12});
    STATIC_REQUIRE(decode_error<set_device_name>("20 41 00 43 00 00 00 00 00 00 00 00 00") == error{errc::bad_padding, 3});
    STATIC_REQUIRE(decode_error<set_device_name>("20 41 42") == error{errc::too_short, 3});
    STATIC_REQUIRE(decode_error<set_device_name>("20 41 42 43 44 45 46 47 48 49 4A 4B 4C 4D") == error{errc::too_long, 13});
    STATIC_REQUIRE(encode_error(set_device_name{text<12>::make(std::string_view("a\0b", 3)).value()}) ==
                   error{errc::value_out_of_range, 2});
    CHECK(golden(set_device_name{text<12>::make("Truck").value()}, "20 54 72 75 63 6B 00 00 00 00 00 00 00"));
}

TEST_CASE("buwizz3: 0x21 set_motion_wakeup", "[buwizz3][commands]") {
    // idle 300 = 0x012C, shallow sleep 3600 = 0x0E10
    STATIC_REQUIRE(golden(set_motion_wakeup{true, 300, 3600}, "21 01 2C 01 00 00 10 0E 00 00"));
    STATIC_REQUIRE(golden(set_motion_wakeup{false, 10, 0}, "21 00 0A 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(decode_error<set_motion_wakeup>("21 02 2C 01 00 00 10 0E 00 00") == error{errc::value_out_of_range, 1});
    STATIC_REQUIRE(decode_error<set_motion_wakeup>("21 01 09 00 00 00 10 0E 00 00") == error{errc::value_out_of_range, 2});
    STATIC_REQUIRE(encode_error(set_motion_wakeup{true, 9, 0}) == error{errc::value_out_of_range, 2});
    CHECK(golden(set_motion_wakeup{true, 300, 3600}, "21 01 2C 01 00 00 10 0E 00 00"));
}

TEST_CASE("buwizz3: 0x22 / 0x23 accelerometer calibration", "[buwizz3][commands]") {
    STATIC_REQUIRE(golden(set_accel_calibration{factors}, "22 00 00 80 3F 00 00 80 BF 00 00 00 3F 9A 99 19 3F 00 00 20 C0 00 00 00 00"));
    STATIC_REQUIRE(golden(read_accel_calibration{}, "23"));
    STATIC_REQUIRE(golden(accel_calibration{factors}, "23 00 00 80 3F 00 00 80 BF 00 00 00 3F 9A 99 19 3F 00 00 20 C0 00 00 00 00"));
    STATIC_REQUIRE(decode_error<read_accel_calibration>("23 00") == error{errc::too_long, 1});
    STATIC_REQUIRE(decode_error<accel_calibration>("23 00 00 80 3F") == error{errc::too_short, 5});
    CHECK(golden(accel_calibration{factors}, "23 00 00 80 3F 00 00 80 BF 00 00 00 3F 9A 99 19 3F 00 00 20 C0 00 00 00 00"));
}

TEST_CASE("buwizz3: 0x30 set_motor_data", "[buwizz3][commands]") {
    // 127 7F, -127 81, 0, 64 40, -64 C0, 1; brake ports 1 and 6 (0x21); LUT off on all (0x3F)
    STATIC_REQUIRE(golden(set_motor_data{{127, -127, 0, 64, -64, 1}, 0x21, 0x3F}, "30 7F 81 00 40 C0 01 21 3F"));
    STATIC_REQUIRE(decode_error<set_motor_data>("30 80 00 00 00 00 00 00 00") == error{errc::value_out_of_range, 1});  // -128
    STATIC_REQUIRE(decode_error<set_motor_data>("30 00 00 00 00 00 80 00 00") == error{errc::value_out_of_range, 6});
    STATIC_REQUIRE(decode_error<set_motor_data>("30 00 00 00 00 00 00 40 00") == error{errc::value_out_of_range, 7});  // bit 6
    STATIC_REQUIRE(decode_error<set_motor_data>("30 00 00 00 00 00 00 00 80") == error{errc::value_out_of_range, 8});
    STATIC_REQUIRE(decode_error<set_motor_data>("31 00 00 00 00 00 00 00 00") == error{errc::bad_command, 0});
    STATIC_REQUIRE(decode_error<set_motor_data>("30 00 00 00 00 00 00 00") == error{errc::too_short, 8});
    STATIC_REQUIRE(decode_error<set_motor_data>("30 00 00 00 00 00 00 00 00 00") == error{errc::too_long, 9});
    STATIC_REQUIRE(encode_error(set_motor_data{{0, 0, -128, 0, 0, 0}, 0, 0}) == error{errc::value_out_of_range, 3});
    STATIC_REQUIRE(encode_error(set_motor_data{{}, 0x40, 0}) == error{errc::value_out_of_range, 7});
    CHECK(golden(set_motor_data{{127, -127, 0, 64, -64, 1}, 0x21, 0x3F}, "30 7F 81 00 40 C0 01 21 3F"));
}

TEST_CASE("buwizz3: 0x31 set_motor_data_extended", "[buwizz3][commands]") {
    // 1000 = E8 03 00 00, -1000 = 18 FC FF FF, 0, 0x12345678; power -127 (81), 100 (64); brake 0x03
    STATIC_REQUIRE(golden(set_motor_data_extended{{1000, -1000, 0, 0x12345678}, {-127, 100}, 0x03, 0x00},
                          "31 E8 03 00 00 18 FC FF FF 00 00 00 00 78 56 34 12 81 64 03 00"));
    STATIC_REQUIRE(decode_error<set_motor_data_extended>("31 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 80 00 00") ==
                   error{errc::value_out_of_range, 18});
    STATIC_REQUIRE(decode_error<set_motor_data_extended>("31 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 FF 00") ==
                   error{errc::value_out_of_range, 19});
    STATIC_REQUIRE(decode_error<set_motor_data_extended>("31 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 C0") ==
                   error{errc::value_out_of_range, 20});
    STATIC_REQUIRE(decode_error<set_motor_data_extended>("31 00") == error{errc::too_short, 2});
    CHECK(golden(set_motor_data_extended{{1000, -1000, 0, 0x12345678}, {-127, 100}, 0x03, 0x00},
                 "31 E8 03 00 00 18 FC FF FF 00 00 00 00 78 56 34 12 81 64 03 00"));
}

TEST_CASE("buwizz3: 0x32 .. 0x35 single-byte settings", "[buwizz3][commands]") {
    STATIC_REQUIRE(golden(set_data_period{50}, "32 32"));
    STATIC_REQUIRE(golden(set_data_period{20}, "32 14"));
    STATIC_REQUIRE(golden(set_data_period{255}, "32 FF"));
    STATIC_REQUIRE(decode_error<set_data_period>("32 13") == error{errc::value_out_of_range, 1});  // 19 ms
    STATIC_REQUIRE(encode_error(set_data_period{0}) == error{errc::value_out_of_range, 1});
    STATIC_REQUIRE(golden(set_ramp_rates{{1, 2, 3, 4, 5, 6}, {0, 13, 100, 255, 7, 8}}, "33 01 02 03 04 05 06 00 0D 64 FF 07 08"));
    STATIC_REQUIRE(decode_error<set_ramp_rates>("33 01 02 03 04 05 06 00 0D 64 FF 07") == error{errc::too_short, 12});
    STATIC_REQUIRE(golden(set_motor_timeout{11}, "34 0B"));
    STATIC_REQUIRE(golden(set_motor_timeout{254}, "34 FE"));
    STATIC_REQUIRE(decode_error<set_motor_timeout>("34 FF") == error{errc::value_out_of_range, 1});
    STATIC_REQUIRE(encode_error(set_motor_timeout{255}) == error{errc::value_out_of_range, 1});
    STATIC_REQUIRE(golden(activate_watchdog{5}, "35 05"));
    STATIC_REQUIRE(golden(activate_watchdog{0}, "35 00"));
    STATIC_REQUIRE(decode_error<activate_watchdog>("35") == error{errc::too_short, 1});
    CHECK(golden(set_ramp_rates{{1, 2, 3, 4, 5, 6}, {0, 13, 100, 255, 7, 8}}, "33 01 02 03 04 05 06 00 0D 64 FF 07 08"));
}

TEST_CASE("buwizz3: 0x36 set_led_status, three forms", "[buwizz3][commands]") {
    constexpr std::array<rgb, 4> colors{{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {16, 32, 48}}};
    // blink: frequency in bits 7-4, duty in bits 3-0: (1,15) 1F, (15,0) F0, (0,8) 08, (5,5) 55
    constexpr std::array<blink, 4> blinks{{{1, 15}, {15, 0}, {0, 8}, {5, 5}}};
    STATIC_REQUIRE(golden(set_led_status{}, "36"));
    STATIC_REQUIRE(golden(set_led_status{colors, std::nullopt}, "36 FF 00 00 00 FF 00 00 00 FF 10 20 30"));
    STATIC_REQUIRE(golden(set_led_status{colors, blinks}, "36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55"));
    STATIC_REQUIRE(decode_error<set_led_status>("36 FF 00") == error{errc::bad_length, 1});
    STATIC_REQUIRE(decode_error<set_led_status>("36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F") == error{errc::bad_length, 13});
    STATIC_REQUIRE(decode_error<set_led_status>("36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55 00") == error{errc::too_long, 17});
    STATIC_REQUIRE(encode_error(set_led_status{std::nullopt, blinks}) == error{errc::missing_field, 1});
    STATIC_REQUIRE(encode_error(set_led_status{colors, std::array<blink, 4>{{{16, 0}, {}, {}, {}}}}) ==
                   error{errc::value_out_of_range, 13});
    STATIC_REQUIRE(encode_error(set_led_status{colors, std::array<blink, 4>{{{}, {}, {}, {0, 16}}}}) ==
                   error{errc::value_out_of_range, 16});
    CHECK(golden(set_led_status{colors, blinks}, "36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55"));
}

TEST_CASE("buwizz3: 0x37 set_accel_lpf, the eight codes", "[buwizz3][commands]") {
    STATIC_REQUIRE(golden(set_accel_lpf{lpf_setting::hz_0_781}, "37 08"));
    STATIC_REQUIRE(golden(set_accel_lpf{lpf_setting::hz_6_25}, "37 0B"));
    STATIC_REQUIRE(golden(set_accel_lpf{lpf_setting::hz_12_5}, "37 00"));
    STATIC_REQUIRE(golden(set_accel_lpf{lpf_setting::hz_100}, "37 03"));
    for (int code : {0x04, 0x07, 0x0C, 0x10, 0xFF}) {
        const std::array<std::uint8_t, 2> b{0x37, static_cast<std::uint8_t>(code)};
        CHECK(robowire::decode<set_accel_lpf>(b).error() == error{errc::invalid_enum, 1});
    }
    STATIC_REQUIRE(encode_error(set_accel_lpf{lpf_setting{4}}) == error{errc::invalid_enum, 1});
}

TEST_CASE("buwizz3: 0x38 .. 0x52", "[buwizz3][commands]") {
    STATIC_REQUIRE(golden(set_current_limits{{50, 50, 50, 50, 100, 100}}, "38 32 32 32 32 64 64"));
    STATIC_REQUIRE(decode_error<set_current_limits>("38 32 32 32 32 64") == error{errc::too_short, 6});
    // channel 2, 115200 = 0x0001C200
    STATIC_REQUIRE(golden(set_uart_baudrate{2, 115200}, "40 10 02 00 C2 01 00"));
    STATIC_REQUIRE(decode_error<set_uart_baudrate>("40 11 02 00 C2 01 00") == error{errc::bad_command, 1});
    STATIC_REQUIRE(golden(set_pu_port_function{{port_function::pu_simple_pwm, port_function::pu_speed_servo,
                                                port_function::pu_position_servo, port_function::generic_pwm}},
                          "50 10 14 15 00"));
    STATIC_REQUIRE(golden(set_pu_port_function{{port_function::pu_absolute_position_servo, port_function::generic_pwm,
                                                port_function::generic_pwm, port_function::generic_pwm}},
                          "50 16 00 00 00"));
    STATIC_REQUIRE(decode_error<set_pu_port_function>("50 10 10 10 13") == error{errc::invalid_enum, 4});
    STATIC_REQUIRE(decode_error<set_pu_port_function>("50 01 10 10 10") == error{errc::invalid_enum, 1});
    STATIC_REQUIRE(golden(enable_pid_reporting{3}, "51 03"));
    STATIC_REQUIRE(golden(enable_pid_reporting{0}, "51 00"));
    STATIC_REQUIRE(decode_error<enable_pid_reporting>("51 05") == error{errc::value_out_of_range, 1});
    // -1 FF FF FF FF, 0, 90 5A 00 00 00, 0x7FFFFFFF
    STATIC_REQUIRE(golden(set_servo_reference{{-1, 0, 90, 0x7FFFFFFF}}, "52 FF FF FF FF 00 00 00 00 5A 00 00 00 FF FF FF 7F"));
    STATIC_REQUIRE(decode_error<set_servo_reference>("52 FF FF FF FF 00 00 00 00 5A 00 00 00 FF FF FF 7F 00") ==
                   error{errc::too_long, 17});
    CHECK(golden(set_uart_baudrate{2, 115200}, "40 10 02 00 C2 01 00"));
}

TEST_CASE("buwizz3: 0x53 set_pid_parameters", "[buwizz3][commands]") {
    // position servo defaults, port 0: out_lp 0, d_lp 0.9 (3F666666), speed_lp 0, kp 0.4 (3ECCCCCD),
    // ki 0.01 (3C23D70A), kd -0.8 (BF4CCCCD), lim_i 20 (41A00000), rate limit 0, lim_out 100 (64),
    // deadband 2, boost 2, mode position servo (15)
    constexpr std::string_view hex =
        "53 00 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 64 02 02 15";
    constexpr set_pid_parameters m{0, 0.0f, 0.9f, 0.0f, 0.4f, 0.01f, -0.8f, 20.0f, 0.0f, 100, 2, 2, port_function::pu_position_servo};
    STATIC_REQUIRE(test::hex(hex).size() == 38);
    STATIC_REQUIRE(golden(m, hex));
    STATIC_REQUIRE(decode_error<set_pid_parameters>(
                       "53 04 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 64 02 02 15") ==
                   error{errc::value_out_of_range, 1});
    STATIC_REQUIRE(decode_error<set_pid_parameters>(
                       "53 00 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 00 02 02 15") ==
                   error{errc::value_out_of_range, 34});  // lim_out 0
    STATIC_REQUIRE(decode_error<set_pid_parameters>(
                       "53 00 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 64 FF 02 15") ==
                   error{errc::value_out_of_range, 35});  // deadband -1
    STATIC_REQUIRE(decode_error<set_pid_parameters>(
                       "53 00 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 64 02 80 15") ==
                   error{errc::value_out_of_range, 36});
    STATIC_REQUIRE(decode_error<set_pid_parameters>(
                       "53 00 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 64 02 02 17") ==
                   error{errc::invalid_enum, 37});
    CHECK(golden(m, hex));
}

TEST_CASE("buwizz3: 0xA1, 0xAC", "[buwizz3][commands]") {
    STATIC_REQUIRE(golden(activate_shelf_mode{}, "A1"));
    STATIC_REQUIRE(decode_error<activate_shelf_mode>("A1 00") == error{errc::too_long, 1});
    STATIC_REQUIRE(golden(check_charger_settings{}, "AC"));
    STATIC_REQUIRE(golden(charger_settings{{0x01, 0x02, 0x03}}, "AC 01 02 03"));
    STATIC_REQUIRE(golden(charger_settings{}, "AC"));
    STATIC_REQUIRE(decode_error<charger_settings>("AD 01") == error{errc::bad_command, 0});
    CHECK(golden(charger_settings{{0xFE}}, "AC FE"));
}

TEST_CASE("buwizz3: decode_command and decode_notification dispatch", "[buwizz3][commands]") {
    STATIC_REQUIRE(std::get<set_motor_data>(decode_command(test::hex("30 7F 81 00 40 C0 01 21 3F")).value()).power[1] == -127);
    STATIC_REQUIRE(std::holds_alternative<read_accel_calibration>(decode_command(test::hex("23")).value()));
    STATIC_REQUIRE(std::holds_alternative<accel_calibration>(
        decode_notification(test::hex("23 00 00 80 3F 00 00 80 BF 00 00 00 3F 9A 99 19 3F 00 00 20 C0 00 00 00 00")).value()));
    STATIC_REQUIRE(std::holds_alternative<charger_settings>(decode_notification(test::hex("AC 05")).value()));
    STATIC_REQUIRE(decode_command(test::hex("01 00")).error() == error{errc::unknown_message, 0});
    STATIC_REQUIRE(decode_command(test::hex("99")).error() == error{errc::unknown_message, 0});
    STATIC_REQUIRE(decode_command(test::hex("")).error() == error{errc::too_short, 0});
    STATIC_REQUIRE(decode_notification(test::hex("30 00")).error() == error{errc::unknown_message, 0});
    STATIC_REQUIRE(decode_command(test::hex("30 00")).error() == error{errc::too_short, 2});
    CHECK(decode_command(test::hex("23 00")).error() == error{errc::too_long, 1});
}

TEST_CASE("buwizz3: decode_command at run time, every first byte", "[buwizz3][commands]") {
    // The 20 command bytes of the BuWizz3 document; every other byte is unknown_message at 0.
    constexpr std::array<std::uint8_t, 20> commands{0x20, 0x21, 0x22, 0x23, 0x30, 0x31, 0x32, 0x33, 0x34, 0x35,
                                                    0x36, 0x37, 0x38, 0x40, 0x50, 0x51, 0x52, 0x53, 0xA1, 0xAC};
    // Notifications: 0x01 status report, 0x23 accelerometer calibration, 0xAC charger settings.
    constexpr std::array<std::uint8_t, 3> notifications{0x01, 0x23, 0xAC};
    std::array<std::uint8_t, 64> in{};
    for (std::size_t k = 0; k < 256; ++k) {
        in[0] = static_cast<std::uint8_t>(k);
        const bool is_command = std::find(commands.begin(), commands.end(), k) != commands.end();
        const bool is_notification = std::find(notifications.begin(), notifications.end(), k) != notifications.end();
        for (std::size_t n : {std::size_t{1}, std::size_t{9}, in.size()}) {
            const auto c = decode_command(std::span<const std::uint8_t>(in.data(), n));
            const auto s = decode_notification(std::span<const std::uint8_t>(in.data(), n));
            INFO("first byte " << k << ", " << n << " bytes");
            CHECK((c.code() == errc::unknown_message) == !is_command);
            CHECK((s.code() == errc::unknown_message) == !is_notification);
            if (c.code() == errc::unknown_message) CHECK(c.error().offset == 0);
            if (s.code() == errc::unknown_message) CHECK(s.error().offset == 0);
        }
    }
    // Each known byte reaches its own alternative, not a neighbour's.
    CHECK(std::holds_alternative<set_led_status>(decode_command(test::hex("36")).value()));
    CHECK(std::holds_alternative<check_charger_settings>(decode_command(test::hex("AC")).value()));
    CHECK(std::holds_alternative<activate_shelf_mode>(decode_command(test::hex("A1")).value()));
    CHECK(std::holds_alternative<read_accel_calibration>(decode_command(test::hex("23")).value()));
}

TEST_CASE("buwizz3: every command and notification round trips through its variant", "[buwizz3][commands]") {
    STATIC_REQUIRE(std::variant_size_v<command> >= 20);
    test::check_each_round_trips<command>([](const command& m) { return robowire::encode(m); },
                                          [](std::span<const std::uint8_t> in) { return decode_command(in); });
    test::check_each_round_trips<notification>([](const notification& m) { return robowire::encode(m); },
                                               [](std::span<const std::uint8_t> in) { return decode_notification(in); });
}
