#include <robowire/core/bits.hpp>

#include <catch2/catch.hpp>

using namespace robowire;

TEST_CASE("bit ranges inside a byte", "[core][bits]") {
    // 0xB6 = 1011 0110: bits 3-4 are 1,0 (bit 4 = 1, bit 3 = 0) -> 0b10
    STATIC_REQUIRE(get_bits(0xB6, 3, 2) == 2);
    STATIC_REQUIRE(get_bits(0xB6, 4, 4) == 0xB);
    STATIC_REQUIRE(get_bits(0xB6, 0, 1) == 0);
    STATIC_REQUIRE(get_bits(0xB6, 7, 1) == 1);
    STATIC_REQUIRE(set_bits(0x00, 4, 4, 0xA).value() == 0xA0);
    STATIC_REQUIRE(set_bits(0xFF, 3, 2, 0).value() == 0xE7);  // 1110 0111
    STATIC_REQUIRE(set_bits(0x00, 0, 4, 16).code() == errc::value_out_of_range);
    CHECK(get_bits(0xB6, 3, 2) == 2);
    CHECK(set_bits(0x0F, 4, 4, 0x5).value() == 0x5F);
}

TEST_CASE("left-aligned 12-bit values", "[core][bits]") {
    // 0xFFF0 = -16 as int16: 12-bit count -1, -1 * 7.808 mg = -16 * 0.488 mg
    STATIC_REQUIRE(left12_count(-16) == -1);
    STATIC_REQUIRE(left12_count(0x7FF0) == 2047);
    STATIC_REQUIRE(left12_count(static_cast<std::int16_t>(-32768)) == -2048);
    STATIC_REQUIRE(left12_count(0x0010) == 1);
    STATIC_REQUIRE(left12_word(-1).value() == -16);
    STATIC_REQUIRE(left12_word(2047).value() == 0x7FF0);
    STATIC_REQUIRE(left12_word(-2048).value() == -32768);
    STATIC_REQUIRE(left12_word(2048).code() == errc::value_out_of_range);
    STATIC_REQUIRE(left12_word(-2049).code() == errc::value_out_of_range);
    CHECK(left12_count(-16) == -1);
}

TEST_CASE("sign-magnitude int8", "[core][bits]") {
    STATIC_REQUIRE(from_sign_magnitude(0x8A) == -10);
    STATIC_REQUIRE(from_sign_magnitude(0x88) == -8);
    STATIC_REQUIRE(from_sign_magnitude(0x0A) == 10);
    STATIC_REQUIRE(from_sign_magnitude(0x80) == 0);
    STATIC_REQUIRE(from_sign_magnitude(0xFF) == -127);
    STATIC_REQUIRE(to_sign_magnitude(-10).value() == 0x8A);
    STATIC_REQUIRE(to_sign_magnitude(-127).value() == 0xFF);
    STATIC_REQUIRE(to_sign_magnitude(127).value() == 0x7F);
    STATIC_REQUIRE(to_sign_magnitude(0).value() == 0x00);
    STATIC_REQUIRE(to_sign_magnitude(-128).code() == errc::value_out_of_range);
    CHECK(from_sign_magnitude(0x8A) == -10);
    CHECK(to_sign_magnitude(-8).value() == 0x88);
}
