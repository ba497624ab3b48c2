#include <robowire/buwizz3/units.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#include "check.hpp"

using namespace robowire;
using namespace robowire::buwizz3;

TEST_CASE("buwizz3: LPF setting <-> Hz", "[buwizz3][units]") {
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_0_781) == 0.781);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_6_25) == 6.25);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_100) == 100.0);
    // every code's frequency, as the document's 0x37 table gives it
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_1_563) == 1.563);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_3_125) == 3.125);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_12_5) == 12.5);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_25) == 25.0);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_50) == 50.0);
    STATIC_REQUIRE(lpf_from_hz(50.0).value() == lpf_setting::hz_50);
    STATIC_REQUIRE(lpf_from_hz(0.78).value() == lpf_setting::hz_0_781);
    STATIC_REQUIRE(lpf_from_hz(1.563).value() == lpf_setting::hz_1_563);
    STATIC_REQUIRE(lpf_from_hz(40.0).code() == errc::invalid_enum);
    // the 1 % window: 6.30625 = 6.25 x 1.009 is 6.25 Hz, 6.32 (1.0112 x) is none
    STATIC_REQUIRE(lpf_from_hz(6.30625).value() == lpf_setting::hz_6_25);
    STATIC_REQUIRE(lpf_from_hz(6.32).code() == errc::invalid_enum);
    STATIC_REQUIRE(lpf_from_hz(6.19).value() == lpf_setting::hz_6_25);  // 0.9904 x
    STATIC_REQUIRE(lpf_from_hz(6.18).code() == errc::invalid_enum);     // 0.9888 x
    CHECK(lpf_from_hz(3.125).value() == lpf_setting::hz_3_125);
}

TEST_CASE("buwizz3: ramp rate from seconds", "[buwizz3][units]") {
    STATIC_REQUIRE(ramp_rate_from_seconds(1.0).value() == 13);     // 100 / 7.8125 = 12.8
    STATIC_REQUIRE(ramp_rate_from_seconds(0.128).value() == 100);  // 100 / 1.0
    STATIC_REQUIRE(ramp_rate_from_seconds(2.0).value() == 6);      // 6.4
    STATIC_REQUIRE(ramp_rate_from_seconds(0.05).value() == 255);   // 256, clamped
    STATIC_REQUIRE(ramp_rate_from_seconds(100.0).value() == 1);    // 0.128, clamped
    STATIC_REQUIRE(ramp_rate_from_seconds(0.0).code() == errc::value_out_of_range);
    // Each pins 7.8125 (= 1000 / 128) against a near miss: with 7.8 instead,
    // 0.0503 s: 100 / 0.39234 = 254.88 -> 255, 0.1275 s: 100 / 0.9945 = 100.55 -> 101.
    STATIC_REQUIRE(ramp_rate_from_seconds(0.0503).value() == 254);  // 100 / 0.39296875 = 254.47
    STATIC_REQUIRE(ramp_rate_from_seconds(0.1275).value() == 100);  // 100 / 0.99609375 = 100.39
    STATIC_REQUIRE(ramp_seconds(100) == 0.128);
    STATIC_REQUIRE(ramp_seconds(0) == 0.0);
}

TEST_CASE("buwizz3: motor power from a percentage and back", "[buwizz3][units]") {
    // The document: 0x7F (127) full forwards, 0x81 (-127) full backwards.
    // raw = percent x 127 / 100, rounded half away from zero.
    STATIC_REQUIRE(power_from_percent(100.0).value() == 127);
    STATIC_REQUIRE(power_from_percent(-100.0).value() == -127);
    STATIC_REQUIRE(power_from_percent(50.0).value() == 64);    // 63.5 (truncation: 63)
    STATIC_REQUIRE(power_from_percent(-50.0).value() == -64);  // -63.5 (floor(x + 0.5): -63)
    STATIC_REQUIRE(power_from_percent(99.0).value() == 126);   // 125.73 (x 128 / 100: 127)
    STATIC_REQUIRE(power_from_percent(2.0).value() == 3);      // 2.54
    STATIC_REQUIRE(power_from_percent(1.0).value() == 1);      // 1.27
    STATIC_REQUIRE(power_from_percent(0.4).value() == 1);      // 0.508
    STATIC_REQUIRE(power_from_percent(-0.4).value() == -1);
    STATIC_REQUIRE(power_from_percent(0.3).value() == 0);      // 0.381
    STATIC_REQUIRE(power_from_percent(0.0).value() == 0);
    STATIC_REQUIRE(power_from_percent(100.01).error() == error{errc::value_out_of_range, 1});
    STATIC_REQUIRE(power_from_percent(-100.01).code() == errc::value_out_of_range);
    STATIC_REQUIRE(power_from_percent(std::numeric_limits<double>::quiet_NaN()).code() == errc::value_out_of_range);
    // whole percentages in integers: the same values
    STATIC_REQUIRE(power_from_percent(100).value() == 127);
    STATIC_REQUIRE(power_from_percent(-100).value() == -127);
    STATIC_REQUIRE(power_from_percent(50).value() == 64);
    STATIC_REQUIRE(power_from_percent(-50).value() == -64);
    STATIC_REQUIRE(power_from_percent(99).value() == 126);
    STATIC_REQUIRE(power_from_percent(-2).value() == -3);
    STATIC_REQUIRE(power_from_percent(1).value() == 1);
    STATIC_REQUIRE(power_from_percent(50L).value() == 64);
    STATIC_REQUIRE(power_from_percent(std::uint8_t{100}).value() == 127);
    STATIC_REQUIRE(power_from_percent(101).code() == errc::value_out_of_range);
    STATIC_REQUIRE(power_from_percent(-101).code() == errc::value_out_of_range);
    STATIC_REQUIRE(power_from_percent(std::uint64_t{1} << 40).code() == errc::value_out_of_range);
    STATIC_REQUIRE(power_from_percent(-(std::int64_t{1} << 40)).code() == errc::value_out_of_range);
    // the inverse: raw x 100 / 127
    STATIC_REQUIRE(percent_from_power(127) == 100.0);  // x 100 / 128: 99.22
    STATIC_REQUIRE(percent_from_power(-127) == -100.0);
    STATIC_REQUIRE(percent_from_power(0) == 0.0);
    CHECK(percent_from_power(64) == Approx(50.3937007874));  // 6400 / 127
    CHECK(percent_from_power(1) == Approx(0.7874015748));
    // every whole percentage comes back within half a step (100 / 127 / 2 = 0.3937 %)
    for (int p = -100; p <= 100; ++p) {
        const double back = percent_from_power(power_from_percent(p).value());
        CHECK(std::abs(back - p) <= 0.3938);
        CHECK(power_from_percent(p).value() == power_from_percent(static_cast<double>(p)).value());
    }
    // into a command
    set_motor_data m{};
    m.power = {power_from_percent(100).value(), power_from_percent(-50).value(), 0, 0, 0, 0};
    CHECK(robowire::encode(m).value() == test::hex("30 7F C0 00 00 00 00 00 00"));
}

TEST_CASE("buwizz3: current limits", "[buwizz3][units]") {
    STATIC_REQUIRE(current_limit_raw(1500).value() == 50);
    STATIC_REQUIRE(current_limit_raw(3000).value() == 100);
    STATIC_REQUIRE(current_limit_raw(1500, 35).value() == 43);  // 42.86
    STATIC_REQUIRE(current_limit_raw(7650).value() == 255);
    STATIC_REQUIRE(current_limit_raw(7665).code() == errc::value_out_of_range);  // 255.5 rounds to 256
    STATIC_REQUIRE(current_limit_raw(-1).code() == errc::value_out_of_range);
    STATIC_REQUIRE(current_limit_ma(50) == 1500.0);
    STATIC_REQUIRE(current_limit_ma(50, 35) == 1750.0);
    STATIC_REQUIRE(robowire::encode(default_current_limits).value() == test::hex("38 32 32 32 32 64 64"));
}

TEST_CASE("buwizz3: K_LP from cut-off frequency", "[buwizz3][units]") {
    // f = 10 Hz: 1 / (2 pi 10) = 0.0159155; 0.01 / 0.0259155 = 0.385869; K = 0.614131
    CHECK(k_lp_from_cutoff(10.0).value() == Approx(0.614131).epsilon(1e-5));
    // K = 0.5 where Ts = 1 / (2 pi f): f = 15.9155 Hz
    CHECK(k_lp_from_cutoff(15.915494).value() == Approx(0.5).epsilon(1e-5));
    STATIC_REQUIRE(k_lp_from_cutoff(0.0).code() == errc::value_out_of_range);
    STATIC_REQUIRE(k_lp_from_cutoff(10.0).value() > 0.6f);
}

TEST_CASE("buwizz3: the document's PID presets", "[buwizz3][units]") {
    // position servo, port 0 (see commands.cpp for the byte-by-byte derivation)
    STATIC_REQUIRE(robowire::encode(position_servo_preset(0)).value() ==
                   test::hex("53 00 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 64 02 02 15"));
    // speed servo, port 1: out_lp 0.5 (3F000000), d_lp 0.5, speed_lp 0.9 (3F666666), kp 0.8 (3F4CCCCD),
    // ki 0.06 (3D75C28F), kd -3 (C0400000), lim_i 127 (42FE0000), rate 0, lim_out 127, 2, 2, speed servo (14)
    STATIC_REQUIRE(robowire::encode(speed_servo_preset(1)).value() ==
                   test::hex("53 01 00 00 00 3F 00 00 00 3F 66 66 66 3F CD CC 4C 3F 8F C2 75 3D 00 00 40 C0 00 00 FE 42 00 00 00 00 7F 02 02 14"));
    STATIC_REQUIRE(generic_pid_preset(2, port_function::pu_speed_servo).lim_out == 127);
    CHECK(robowire::encode(generic_pid_preset(3, port_function::pu_position_servo)).has_value());
}

TEST_CASE("buwizz3: status units in integers", "[buwizz3][units]") {
    // battery: 9 V + raw x 0.05 V
    STATIC_REQUIRE(battery_millivolts(std::uint8_t{0}) == 9000);
    STATIC_REQUIRE(battery_millivolts(std::uint8_t{80}) == 13000);
    STATIC_REQUIRE(battery_millivolts(std::uint8_t{127}) == 15350);  // the document's top of range
    STATIC_REQUIRE(battery_millivolts(std::uint8_t{255}) == 21750);
    // motor current: raw x 0.015 A
    STATIC_REQUIRE(motor_milliamps(std::uint8_t{1}) == 15);
    STATIC_REQUIRE(motor_milliamps(std::uint8_t{200}) == 3000);
    STATIC_REQUIRE(motor_milliamps(std::uint8_t{255}) == 3825);
    // acceleration: the 16-bit word x 0.488 mg = x 488 ug; one 12-bit count (16) is 7.808 mg
    STATIC_REQUIRE(accel_micro_g(16) == 7808);
    STATIC_REQUIRE(accel_micro_g(-16) == -7808);
    STATIC_REQUIRE(accel_micro_g(0x7FF0) == 15982976);  // 32752 x 488
    STATIC_REQUIRE(accel_micro_g(-32768) == -15990784);
    STATIC_REQUIRE(accel_micro_g(2049) == 999912);  // about 1 g
    STATIC_REQUIRE(accel_milli_g_rounded(2049) == 1000);
    STATIC_REQUIRE(accel_milli_g_rounded(16) == 8);    // 7.808
    STATIC_REQUIRE(accel_milli_g_rounded(-16) == -8);  // -7.808
    STATIC_REQUIRE(accel_milli_g_rounded(1) == 0);     // 0.488
    STATIC_REQUIRE(accel_milli_g_rounded(-1) == 0);    // -0.488
    STATIC_REQUIRE(accel_milli_g_rounded(2) == 1);     // 0.976
    STATIC_REQUIRE(accel_milli_g_rounded(-32768) == -15991);  // -15990.784
    STATIC_REQUIRE(accel_milli_g_rounded(32767) == 15990);    // 15990.296
    // equal to the plain division on every word; the multiply form (a core without a
    // divide instruction) exact on its whole input range
    std::size_t bad = 0;
    for (std::uint32_t n = 0; n <= units_detail::milli_g_by_125::max; ++n)
        bad += units_detail::milli_g_by_125::by_multiply(n) != n / 125;
    CHECK(bad == 0);
    bad = 0;
    for (std::int32_t w = -32768; w <= 32767; ++w) {
        const std::int32_t ug = w * 488;
        bad += accel_milli_g_rounded(static_cast<std::int16_t>(w)) != (ug < 0 ? ug - 500 : ug + 500) / 1000;
    }
    CHECK(bad == 0);
    // from a status report
    constexpr status s = [] {
        status st{};
        st.battery_voltage_raw = 80;
        st.motor_current_raw = {0, 0, 0, 0, 0, 200};
        return st;
    }();
    STATIC_REQUIRE(battery_millivolts(s) == 13000);
    STATIC_REQUIRE(motor_milliamps(s, 5) == 3000);
    STATIC_REQUIRE(motor_milliamps(s, 0) == 0);
    CHECK(battery_millivolts(std::uint8_t{127}) == Approx(battery_volts(std::uint8_t{127}) * 1000));
}
