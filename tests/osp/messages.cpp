#include <robowire/osp/messages.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"

using namespace robowire;
using namespace robowire::osp;

namespace {
template <class M>
constexpr bool decodes_to(std::string_view hex, const M& want) {
    const auto b = test::hex(hex);
    const auto r = robowire::decode<M>(b);
    return r && *r == want;
}
template <class M>
constexpr bool encodes_to(const M& m, std::string_view hex) {
    const auto r = robowire::encode(m);
    return r && *r == test::hex(hex);
}
template <class M>
constexpr error decode_error(std::string_view hex) {
    return robowire::decode<M>(test::hex(hex)).error();
}
}  // namespace

// Golden frames from the document's layouts, worked out by hand.
TEST_CASE("osp: generic messages", "[osp]") {
    STATIC_REQUIRE(encodes_to(generic::request_device_type{}, "FF AA 00 01 00 00 00 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 00 01 00 00 00 00 55 77", generic::request_device_type{}));
    STATIC_REQUIRE(encodes_to(generic::device_type{device_type::obp1}, "FF AA 00 11 02 00 00 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 00 11 03 00 00 00 55 77", generic::device_type{device_type::o2d1}));
    STATIC_REQUIRE(decode_error<generic::device_type>("FF AA 00 11 04 00 00 00 55 77") == error{errc::invalid_enum, 4});
    CHECK(encodes_to(generic::device_type{device_type::arm1}, "FF AA 00 11 01 00 00 00 55 77"));
    CHECK(decodes_to("FF AA 00 11 02 00 00 00 55 77", generic::device_type{device_type::obp1}));
}

TEST_CASE("osp: ARM-1 set angle", "[osp]") {
    // joint 3, angle 0x1234 -> P1 03, P2 34 (LSB), P3 12 (MSB)
    STATIC_REQUIRE(encodes_to(arm1::set_angle{3, 0x1234}, "FF AA 01 02 03 34 12 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 01 02 03 34 12 00 55 77", arm1::set_angle{3, 0x1234}));
    STATIC_REQUIRE(decodes_to("FF AA 01 02 FF FF FF 00 55 77", arm1::set_angle{255, 65535}));
    CHECK(encodes_to(arm1::set_angle{1, 0x2000}, "FF AA 01 02 01 00 20 00 55 77"));
}

TEST_CASE("osp: OBP-1 requests", "[osp]") {
    STATIC_REQUIRE(encodes_to(obp1::request_soc{}, "FF AA 02 01 00 00 00 00 55 77"));
    STATIC_REQUIRE(encodes_to(obp1::request_voltage{}, "FF AA 02 02 00 00 00 00 55 77"));
    STATIC_REQUIRE(encodes_to(obp1::request_current{}, "FF AA 02 03 00 00 00 00 55 77"));
    STATIC_REQUIRE(encodes_to(obp1::request_status{}, "FF AA 02 04 00 00 00 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 02 04 00 00 00 00 55 77", obp1::request_status{}));
    CHECK(decodes_to("FF AA 02 01 00 00 00 00 55 77", obp1::request_soc{}));
}

TEST_CASE("osp: OBP-1 answers", "[osp]") {
    STATIC_REQUIRE(encodes_to(obp1::soc{65535}, "FF AA 02 11 FF FF 00 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 02 11 00 80 00 00 55 77", obp1::soc{32768}));
    // 12.34 V = 1234 = 0x04D2
    STATIC_REQUIRE(encodes_to(obp1::voltage{1234}, "FF AA 02 12 D2 04 00 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 02 12 00 80 00 00 55 77", obp1::voltage{-32768}));
    // -1500 mA = 0xFA24
    STATIC_REQUIRE(encodes_to(obp1::current{-1500}, "FF AA 02 13 24 FA 00 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 02 13 FF 7F 00 00 55 77", obp1::current{32767}));
    // charging (3), low voltage + overheat (0b0101) - status is CMD 0x14
    STATIC_REQUIRE(encodes_to(obp1::status{obp1::state::charging, 0x05}, "FF AA 02 14 03 05 00 00 55 77"));
    STATIC_REQUIRE(decodes_to("FF AA 02 14 04 08 00 00 55 77", obp1::status{obp1::state::fully_charged, 0x08}));
    STATIC_REQUIRE(decode_error<obp1::status>("FF AA 02 14 05 00 00 00 55 77") == error{errc::invalid_enum, 4});
    STATIC_REQUIRE(decode_error<obp1::status>("FF AA 02 13 03 05 00 00 55 77") == error{errc::bad_command, 3});
    constexpr obp1::status s{obp1::state::charging, 0x05};
    STATIC_REQUIRE((s.low_voltage() && !s.high_voltage() && s.overheat() && !s.short_circuit()));
    CHECK(encodes_to(obp1::current{-1500}, "FF AA 02 13 24 FA 00 00 55 77"));
}

TEST_CASE("osp: bad frames", "[osp]") {
    STATIC_REQUIRE(decode_error<obp1::soc>("FE AA 02 11 00 00 00 00 55 77") == error{errc::bad_header, 0});
    STATIC_REQUIRE(decode_error<obp1::soc>("FF AB 02 11 00 00 00 00 55 77") == error{errc::bad_header, 1});
    STATIC_REQUIRE(decode_error<obp1::soc>("FF AA 01 11 00 00 00 00 55 77") == error{errc::bad_device, 2});
    STATIC_REQUIRE(decode_error<obp1::soc>("FF AA 02 12 00 00 00 00 55 77") == error{errc::bad_command, 3});
    STATIC_REQUIRE(decode_error<obp1::soc>("FF AA 02 11 00 00 00 00 56 77") == error{errc::bad_trailer, 8});
    STATIC_REQUIRE(decode_error<obp1::soc>("FF AA 02 11 00 00 00 00 55 78") == error{errc::bad_trailer, 9});
    STATIC_REQUIRE(decode_error<obp1::soc>("FF AA 02 11 00 00 00 00 55") == error{errc::too_short, 9});
    STATIC_REQUIRE(decode_error<obp1::soc>("FF AA 02 11 00 00 00 00 55 77 00") == error{errc::too_long, 10});
    STATIC_REQUIRE(decode_error<obp1::soc>("") == error{errc::too_short, 0});
    CHECK(decode_error<arm1::set_angle>("FF AA 01 02 00 00 00 00 55 76") == error{errc::bad_trailer, 9});
}

TEST_CASE("osp: reserved bytes are ignored, strict check reports them", "[osp]") {
    constexpr auto soc_with_junk = test::hex("FF AA 02 01 01 00 00 00 55 77");
    STATIC_REQUIRE(robowire::decode<obp1::request_soc>(soc_with_junk).has_value());
    STATIC_REQUIRE(check_reserved<obp1::request_soc>(soc_with_junk).error() == error{errc::reserved_not_zero, 4});
    constexpr auto angle_with_junk = test::hex("FF AA 01 02 03 34 12 EE 55 77");
    STATIC_REQUIRE(robowire::decode<arm1::set_angle>(angle_with_junk).value() == arm1::set_angle{3, 0x1234});
    STATIC_REQUIRE(check_reserved<arm1::set_angle>(angle_with_junk).error() == error{errc::reserved_not_zero, 7});
    STATIC_REQUIRE(check_reserved<arm1::set_angle>(test::hex("FF AA 01 02 03 34 12 00 55 77")).has_value());
    // re-encoding sends reserved bytes as 0
    CHECK(robowire::encode(*robowire::decode<arm1::set_angle>(angle_with_junk)).value() ==
          test::hex("FF AA 01 02 03 34 12 00 55 77"));
}
