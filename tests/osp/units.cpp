#include <robowire/osp/units.hpp>

#include <catch2/catch.hpp>

#include <numbers>

#include "check.hpp"

using namespace robowire;
using namespace robowire::osp;

TEST_CASE("osp: unit helpers, document scale", "[osp][units]") {
    STATIC_REQUIRE(obp1::soc_percent(65535) == 100.0);
    STATIC_REQUIRE(obp1::soc_percent(0) == 0.0);
    STATIC_REQUIRE(obp1::volts(obp1::voltage{-32768}) == -327.68);
    STATIC_REQUIRE(obp1::volts(1234) == 12.34);
    STATIC_REQUIRE(obp1::amps(obp1::current{-32768}) == -32.768);
    STATIC_REQUIRE(obp1::soc_from_percent(50.0).value() == 32768);  // 32767.5 rounds up
    STATIC_REQUIRE(obp1::soc_from_percent(100.0).value() == 65535);
    STATIC_REQUIRE(obp1::soc_from_percent(100.1).code() == errc::value_out_of_range);
    CHECK(obp1::amps(-1500) == Approx(-1.5));
}

TEST_CASE("osp: integer unit helpers, document scale", "[osp][units]") {
    // voltage: V x 100, so millivolts = raw x 10
    STATIC_REQUIRE(obp1::millivolts(1234) == 12340);
    STATIC_REQUIRE(obp1::millivolts(obp1::voltage{-32768}) == -327680);
    STATIC_REQUIRE(obp1::millivolts(32767) == 327670);
    STATIC_REQUIRE(obp1::milliamps(obp1::current{-1500}) == -1500);
    // SOC: raw x 10000 / 65535, rounded
    STATIC_REQUIRE(obp1::soc_basis_points(65535) == 10000);
    STATIC_REQUIRE(obp1::soc_basis_points(32768) == 5000);  // 5000.08
    STATIC_REQUIRE(obp1::soc_basis_points(obp1::soc{4}) == 1);  // 0.61
    STATIC_REQUIRE(obp1::soc_basis_points(1) == 0);             // 0.15
    // back to raw
    STATIC_REQUIRE(obp1::voltage_from_millivolts(12600).value() == 1260);
    STATIC_REQUIRE(obp1::voltage_from_millivolts(12605).value() == 1261);    // 1260.5 rounds away from zero
    STATIC_REQUIRE(obp1::voltage_from_millivolts(-12605).value() == -1261);
    STATIC_REQUIRE(obp1::voltage_from_millivolts(-327680).value() == -32768);
    STATIC_REQUIRE(obp1::voltage_from_millivolts(327680).error() == error{errc::value_out_of_range, 4});  // 32768
    STATIC_REQUIRE(obp1::soc_from_basis_points(10000).value() == 65535);
    STATIC_REQUIRE(obp1::soc_from_basis_points(5000).value() == 32768);  // 32767.5 rounds up
    STATIC_REQUIRE(obp1::soc_from_basis_points(10001).code() == errc::value_out_of_range);
}

TEST_CASE("osp: unit helpers, published firmware scale", "[osp][units]") {
    constexpr auto fw = scale::published_firmware;
    // OBP-1 firmware: 12.6 V is sent as 12600 (millivolts); the document's scale reads 126.00 V
    STATIC_REQUIRE(obp1::volts(obp1::voltage{12600}, fw) == 12.6);
    STATIC_REQUIRE(obp1::volts(obp1::voltage{12600}) == 126.0);
    STATIC_REQUIRE(obp1::millivolts(obp1::voltage{12600}, fw) == 12600);
    STATIC_REQUIRE(obp1::millivolts(obp1::voltage{12600}) == 126000);
    // SOC 10000 = 100 %
    STATIC_REQUIRE(obp1::soc_percent(obp1::soc{10000}, fw) == 100.0);
    STATIC_REQUIRE(obp1::soc_percent(5000, fw) == 50.0);
    STATIC_REQUIRE(obp1::soc_basis_points(obp1::soc{7525}, fw) == 7525);
    // current in mA in both
    STATIC_REQUIRE(obp1::milliamps(-1500, fw) == -1500);
    STATIC_REQUIRE(obp1::amps(obp1::current{-1500}, fw) == obp1::amps(obp1::current{-1500}));
    // back to raw
    STATIC_REQUIRE(obp1::voltage_from_millivolts(12600, fw).value() == 12600);
    STATIC_REQUIRE(obp1::voltage_from_millivolts(40000, fw).code() == errc::value_out_of_range);
    STATIC_REQUIRE(obp1::soc_from_basis_points(7500, fw).value() == 7500);
    STATIC_REQUIRE(obp1::soc_from_percent(50.0, fw).value() == 5000);
    STATIC_REQUIRE(obp1::soc_from_percent(100.0, fw).value() == 10000);
    CHECK(obp1::volts(std::int16_t{-250}, fw) == Approx(-0.25));
}

TEST_CASE("osp: ARM-1 angle in both readings", "[osp][units]") {
    constexpr auto fw = scale::published_firmware;
    // 16384 = pi: pi/2 -> 8192 = 0x2000
    STATIC_REQUIRE(arm1::angle_from_radians(std::numbers::pi / 2).value() == 0x2000);
    STATIC_REQUIRE(arm1::angle_to_radians(16384) == std::numbers::pi);
    STATIC_REQUIRE(arm1::angle_from_radians(-0.1).code() == errc::value_out_of_range);
    STATIC_REQUIRE(arm1::angle_from_radians(4 * std::numbers::pi).code() == errc::value_out_of_range);  // 65536
    // the ORM arm firmware reads the angle signed: 0xC000 is -16384 (-pi), not 49152 (3 pi)
    STATIC_REQUIRE(arm1::angle_count(0xC000) == 49152);
    STATIC_REQUIRE(arm1::angle_count(0xC000, fw) == -16384);
    STATIC_REQUIRE(arm1::angle_to_radians(0xC000, fw) == -std::numbers::pi);
    STATIC_REQUIRE(arm1::angle_to_radians(0xC000) == 3 * std::numbers::pi);
    STATIC_REQUIRE(arm1::angle_from_radians(-std::numbers::pi / 2, fw).value() == 0xE000);  // -8192
    STATIC_REQUIRE(arm1::angle_from_radians(-2 * std::numbers::pi, fw).value() == 0x8000);  // -32768
    STATIC_REQUIRE(arm1::angle_from_radians(2 * std::numbers::pi, fw).code() == errc::value_out_of_range);  // 32768
    STATIC_REQUIRE(arm1::angle_from_radians(-0.001, fw).value() == 0xFFFB);  // -5.215 counts -> -5
    STATIC_REQUIRE(robowire::encode(arm1::set_angle{1, arm1::angle_from_radians(-std::numbers::pi, fw).value()}).value() ==
                   test::hex("FF AA 01 02 01 00 C0 00 55 77"));
}
