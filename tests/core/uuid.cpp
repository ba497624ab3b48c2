#include <robowire/core/uuid.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <string>
#include <string_view>

using namespace robowire;

namespace {
// BuWizz3 service: on-air bytes as printed in its document, least significant first.
constexpr std::array<std::uint8_t, 16> on_air{0x93, 0x6E, 0x67, 0xB1, 0x19, 0x99, 0xB3, 0x88,
                                              0x81, 0x44, 0xFB, 0x74, 0xD1, 0x92, 0x05, 0x50};
constexpr auto service = uuid_literal("500592d1-74fb-4481-88b3-9919b1676e93");
constexpr bool chars_are(const uuid128& u, std::string_view s) {
    const auto c = u.to_chars();
    return std::string_view(c.data(), c.size()) == s;
}
}  // namespace

TEST_CASE("uuid128 string and on-air order", "[core][uuid]") {
    STATIC_REQUIRE(service.on_air() == on_air);
    STATIC_REQUIRE(uuid128::from_on_air(on_air) == service);
    STATIC_REQUIRE(chars_are(service, "500592d1-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(service.short_value() == 0x92D1);
    STATIC_REQUIRE(chars_are(service.with_short_value(0x2901), "50052901-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(uuid128::parse("500592D1-74FB-4481-88B3-9919B1676E93").value() == service);
    CHECK(uuid128::parse("500592d1-74fb-4481-88b3-9919b1676e9").error() == error{errc::bad_length, 35});
    CHECK(uuid128::parse("500592d1_74fb-4481-88b3-9919b1676e93").error() == error{errc::value_out_of_range, 8});
    CHECK(uuid128::parse("500592g1-74fb-4481-88b3-9919b1676e93").error() == error{errc::value_out_of_range, 6});
}

TEST_CASE("uuid128::parse takes 36 characters only: shorter and longer are bad_length", "[core][uuid]") {
    // the service UUID followed by more hex digits and dashes: every prefix of it, and a long one
    std::string text = "500592d1-74fb-4481-88b3-9919b1676e93";
    while (text.size() < 200) text += "-0123456789abcdef";
    for (std::size_t n = 0; n <= 40; ++n) {
        const auto r = uuid128::parse(std::string_view(text).substr(0, n));
        CAPTURE(n);
        if (n == 36) CHECK(r.value() == service);
        else CHECK(r.error() == error{errc::bad_length, static_cast<std::uint16_t>(n)});
    }
    CHECK(uuid128::parse(text).error() == error{errc::bad_length, static_cast<std::uint16_t>(text.size())});
}
