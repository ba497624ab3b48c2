#include <robowire/osp/decode.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"
#include "round_trips.hpp"

using namespace robowire;
using namespace robowire::osp;

TEST_CASE("osp::decode dispatches on DEV and CMD", "[osp]") {
    STATIC_REQUIRE(std::get<obp1::status>(*osp::decode(test::hex("FF AA 02 14 03 05 00 00 55 77"))) ==
                   obp1::status{obp1::state::charging, 5});
    STATIC_REQUIRE(std::get<obp1::current>(*osp::decode(test::hex("FF AA 02 13 24 FA 00 00 55 77"))).milliamps == -1500);
    STATIC_REQUIRE(std::holds_alternative<generic::request_device_type>(
        *osp::decode(test::hex("FF AA 00 01 00 00 00 00 55 77"))));
    const auto a = osp::decode(test::hex("FF AA 01 02 03 34 12 00 55 77"));
    REQUIRE(a);
    CHECK(std::get<arm1::set_angle>(*a) == arm1::set_angle{3, 0x1234});
}

TEST_CASE("osp::decode: unknown messages still show DEV, CMD and parameters", "[osp]") {
    const auto r = osp::decode(test::hex("FF AA 03 01 0A 0B 0C 0D 55 77"));
    REQUIRE_FALSE(r);
    CHECK(r.error() == error{errc::unknown_message, 2});
    REQUIRE(r.frame());
    CHECK(r.frame()->device == 0x03);
    CHECK(r.frame()->command == 0x01);
    CHECK(r.frame()->params == std::array<std::uint8_t, 4>{0x0A, 0x0B, 0x0C, 0x0D});
    // a field error also keeps the frame; a marker error has none
    const auto bad_enum = osp::decode(test::hex("FF AA 02 14 09 00 00 00 55 77"));
    CHECK(bad_enum.error() == error{errc::invalid_enum, 4});
    CHECK(bad_enum.frame().has_value());
    const auto bad_end = osp::decode(test::hex("FF AA 02 14 01 00 00 00 55 00"));
    CHECK(bad_end.error() == error{errc::bad_trailer, 9});
    CHECK_FALSE(bad_end.frame().has_value());
}

TEST_CASE("osp: every message round trips through the variant", "[osp]") {
    STATIC_REQUIRE(std::variant_size_v<message> >= 11);
    test::check_each_round_trips<message>([](const message& m) { return osp::encode(m); },
                                          [](std::span<const std::uint8_t> in) { return osp::decode(in); });
    test::for_each_alternative<message>([](auto, auto m) { CHECK(osp::encode(m)->size() == frame_size); });
}

namespace {
// A battery pack's firmware: answers what it knows, ignores set_angle, and
// takes requests it only sometimes answers.
struct battery {
    int requests = 0;
    bool have_status = false;
    obp1::soc operator()(const obp1::request_soc&) { ++requests; return {52428}; }  // 80 %
    obp1::voltage operator()(const obp1::request_voltage&) { ++requests; return {1650}; }
    generic::device_type operator()(const generic::request_device_type&) { return {device_type::obp1}; }
    std::optional<obp1::status> operator()(const obp1::request_status&) {
        if (!have_status) return std::nullopt;
        return obp1::status{obp1::state::discharging, 0};
    }
    void operator()(const obp1::request_current&) { ++requests; }
};
}  // namespace

TEST_CASE("osp::serve answers requests on a device", "[osp]") {
    battery b;
    auto r = serve(test::hex("FF AA 02 01 00 00 00 00 55 77"), b);
    REQUIRE(r);
    REQUIRE(r->has_value());
    CHECK(**r == test::hex("FF AA 02 11 CC CC 00 00 55 77"));  // 52428 = 0xCCCC
    r = serve(test::hex("FF AA 00 01 00 00 00 00 55 77"), b);
    CHECK(**r == test::hex("FF AA 00 11 02 00 00 00 55 77"));
    r = serve(test::hex("FF AA 02 04 00 00 00 00 55 77"), b);  // optional: nothing yet
    REQUIRE(r);
    CHECK_FALSE(r->has_value());
    b.have_status = true;
    r = serve(test::hex("FF AA 02 04 00 00 00 00 55 77"), b);
    CHECK(**r == test::hex("FF AA 02 14 02 00 00 00 55 77"));
    r = serve(test::hex("FF AA 02 03 00 00 00 00 55 77"), b);  // void: handled, no answer
    REQUIRE(r);
    CHECK_FALSE(r->has_value());
    CHECK(b.requests == 2);
    r = serve(test::hex("FF AA 01 02 00 00 00 00 55 77"), b);  // not handled
    CHECK(r.error() == error{errc::unknown_message, 2});
    r = serve(test::hex("FF AA 02 01 00 00 00 00 55"), b);
    CHECK(r.error() == error{errc::too_short, 9});
}
