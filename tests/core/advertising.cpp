#include <robowire/core/advertising.hpp>

#include <array>
#include <catch2/catch.hpp>

using namespace robowire;

namespace {
// flags (02 01 06), complete local name "BuWizz" (07 09 ...), manufacturer data (09 FF ...)
constexpr std::array<std::uint8_t, 21> adv{0x02, 0x01, 0x06, 0x07, 0x09, 0x42, 0x75, 0x57, 0x69, 0x7A, 0x7A,
                                           0x09, 0xFF, 0x4E, 0x05, 0x42, 0x57, 0x03, 0x22, 0x34, 0x12};
constexpr std::size_t count(std::span<const std::uint8_t> a) {
    std::size_t n = 0;
    ad::reader r(a);
    for ([[maybe_unused]] const auto& s : r) ++n;
    return n;
}
}  // namespace

TEST_CASE("AD structures are walked in order", "[core][advertising]") {
    STATIC_REQUIRE(ad::validate(adv).value() == 3);
    STATIC_REQUIRE(count(adv) == 3);
    STATIC_REQUIRE(ad::find(adv, ad::complete_local_name)->size() == 6);
    STATIC_REQUIRE((*ad::find(adv, ad::manufacturer_data))[0] == 0x4E);
    STATIC_REQUIRE(!ad::find(adv, ad::incomplete_uuid128_list));
    ad::reader r(adv);
    auto s = r.next();
    REQUIRE(s);
    CHECK(s->type == 0x01);
    CHECK(s->offset == 0);
    s = r.next();
    REQUIRE(s);
    CHECK(s->type == 0x09);
    CHECK(s->offset == 3);
    CHECK(s->data.size() == 6);
    s = r.next();
    REQUIRE(s);
    CHECK(s->offset == 11);
    CHECK(s->data.size() == 8);
    CHECK_FALSE(r.next());
    CHECK(r.error().code == errc::ok);
}

TEST_CASE("AD walk stops cleanly at malformed lengths", "[core][advertising]") {
    // length 5 at offset 3 but only 1 byte follows
    constexpr std::array<std::uint8_t, 5> overrun{0x02, 0x01, 0x06, 0x05, 0x09};
    STATIC_REQUIRE(ad::validate(overrun).error() == error{errc::bad_length, 3});
    STATIC_REQUIRE(count(overrun) == 1);
    // a zero length ends the data: padding after it is not read
    constexpr std::array<std::uint8_t, 6> padded{0x02, 0x01, 0x06, 0x00, 0xFF, 0xFF};
    STATIC_REQUIRE(ad::validate(padded).value() == 1);
    // a lone length byte with no type
    constexpr std::array<std::uint8_t, 1> lone{0x01};
    STATIC_REQUIRE(ad::validate(lone).error() == error{errc::bad_length, 0});
    STATIC_REQUIRE(ad::validate(std::span<const std::uint8_t>{}).value() == 0);
    // length 1: a type with no data
    constexpr std::array<std::uint8_t, 2> empty_data{0x01, 0x09};
    STATIC_REQUIRE(ad::find(empty_data, 0x09)->empty());
}
