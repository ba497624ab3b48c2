#include <robowire/osp/units.hpp>

#include <catch2/catch.hpp>

#include <limits>
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

// The integer helpers divide by a multiply on a core without a divide
// instruction (no __aeabi_uidiv / __aeabi_idiv linked): that form is exact on
// its whole input range, whichever form this build's helpers use.
template <class Divider, std::uint32_t D>
std::size_t multiply_mismatches() {
    std::size_t bad = 0;
    for (std::uint32_t n = 0; n <= Divider::max; ++n) bad += Divider::by_multiply(n) != n / D;
    return bad;
}
TEST_CASE("osp: the integer helpers' divisions by a multiply are exact", "[osp][units]") {
    CHECK(multiply_mismatches<obp1::units_detail::millivolts_by_10, 10>() == 0);
    CHECK(multiply_mismatches<obp1::units_detail::sixteenths_by_625, 625>() == 0);
}
// ... and the helpers equal the plain division on every input.
TEST_CASE("osp: integer unit helpers equal the exact division on every input", "[osp][units]") {
    std::size_t bad = 0;
    for (std::uint32_t raw = 0; raw <= 65535; ++raw) {  // raw x 10000 / 65535 rounded
        const auto exact = static_cast<std::uint16_t>((raw * 10000u + 32767u) / 65535u);
        bad += obp1::soc_basis_points(static_cast<std::uint16_t>(raw)) != exact;
    }
    CHECK(bad == 0);
    bad = 0;
    for (std::uint32_t bp = 0; bp <= 65535; ++bp) {  // bp x 65535 / 10000 rounded half up; above 10000 an error
        const auto r = obp1::soc_from_basis_points(static_cast<std::uint16_t>(bp));
        if (bp > 10000) bad += r.error() != error{errc::value_out_of_range, 4};
        else bad += !r || *r != static_cast<std::uint16_t>((bp * 65535u + 5000u) / 10000u);
    }
    CHECK(bad == 0);
    bad = 0;
    // mv / 10 rounded half away from zero: every mv that divides (|mv| + 5 <= 327689) and a margin of
    // errors on both sides; beyond it only the range check runs (the ends of the i32 range below)
    for (std::int32_t mv = -400000; mv <= 400000; ++mv) {
        const std::int32_t exact = (mv < 0 ? mv - 5 : mv + 5) / 10;
        const auto r = obp1::voltage_from_millivolts(mv);
        if (exact < -32768 || exact > 32767) bad += r.error() != error{errc::value_out_of_range, 4};
        else bad += !r || *r != exact;
    }
    CHECK(bad == 0);
    CHECK(obp1::voltage_from_millivolts(std::numeric_limits<std::int32_t>::max()).code() == errc::value_out_of_range);
    CHECK(obp1::voltage_from_millivolts(std::numeric_limits<std::int32_t>::min()).code() == errc::value_out_of_range);
    STATIC_REQUIRE(obp1::voltage_from_millivolts(327674).value() == 32767);  // the ends of the range
    STATIC_REQUIRE(obp1::voltage_from_millivolts(327675).code() == errc::value_out_of_range);
    STATIC_REQUIRE(obp1::voltage_from_millivolts(-327684).value() == -32768);
    STATIC_REQUIRE(obp1::voltage_from_millivolts(-327685).code() == errc::value_out_of_range);
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
