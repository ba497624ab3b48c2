#include <robowire/buwizz3/units.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"

using namespace robowire;
using namespace robowire::buwizz3;

TEST_CASE("buwizz3: LPF setting <-> Hz", "[buwizz3][units]") {
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_0_781) == 0.781);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_6_25) == 6.25);
    STATIC_REQUIRE(lpf_hz(lpf_setting::hz_100) == 100.0);
    STATIC_REQUIRE(lpf_from_hz(50.0).value() == lpf_setting::hz_50);
    STATIC_REQUIRE(lpf_from_hz(0.78).value() == lpf_setting::hz_0_781);
    STATIC_REQUIRE(lpf_from_hz(1.563).value() == lpf_setting::hz_1_563);
    STATIC_REQUIRE(lpf_from_hz(40.0).code() == errc::invalid_enum);
    CHECK(lpf_from_hz(3.125).value() == lpf_setting::hz_3_125);
}

TEST_CASE("buwizz3: ramp rate from seconds", "[buwizz3][units]") {
    STATIC_REQUIRE(ramp_rate_from_seconds(1.0).value() == 13);     // 100 / 7.8125 = 12.8
    STATIC_REQUIRE(ramp_rate_from_seconds(0.128).value() == 100);  // 100 / 1.0
    STATIC_REQUIRE(ramp_rate_from_seconds(2.0).value() == 6);      // 6.4
    STATIC_REQUIRE(ramp_rate_from_seconds(0.05).value() == 255);   // 256, clamped
    STATIC_REQUIRE(ramp_rate_from_seconds(100.0).value() == 1);    // 0.128, clamped
    STATIC_REQUIRE(ramp_rate_from_seconds(0.0).code() == errc::value_out_of_range);
    STATIC_REQUIRE(ramp_seconds(100) == 0.128);
    STATIC_REQUIRE(ramp_seconds(0) == 0.0);
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
