#include <robowire/core/endian.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>

using robowire::load_le;
using robowire::store_le;

namespace {
constexpr std::array<std::uint8_t, 4> b1234{0x78, 0x56, 0x34, 0x12};
constexpr std::array<std::uint8_t, 4> point_six{0x9A, 0x99, 0x19, 0x3F};  // 0x3F19999A = 0.6f
constexpr std::array<std::uint8_t, 4> minus_two_and_half{0x00, 0x00, 0x20, 0xC0};  // 0xC0200000 = -2.5f

template <class T>
constexpr std::array<std::uint8_t, sizeof(T)> stored(T v) {
    std::array<std::uint8_t, sizeof(T)> out{};
    store_le<T>(out.data(), v);
    return out;
}
}  // namespace

TEST_CASE("load_le reads little-endian integers", "[core][endian]") {
    STATIC_REQUIRE(load_le<std::uint8_t>(b1234.data()) == 0x78);
    STATIC_REQUIRE(load_le<std::int8_t>(b1234.data() + 3) == 0x12);
    STATIC_REQUIRE(load_le<std::uint16_t>(b1234.data()) == 0x5678);
    STATIC_REQUIRE(load_le<std::uint32_t>(b1234.data()) == 0x12345678u);
    constexpr std::array<std::uint8_t, 4> neg{0xFE, 0xFF, 0xFF, 0xFF};
    STATIC_REQUIRE(load_le<std::int8_t>(neg.data()) == -2);
    STATIC_REQUIRE(load_le<std::int16_t>(neg.data()) == -2);
    STATIC_REQUIRE(load_le<std::int32_t>(neg.data()) == -2);
    constexpr std::array<std::uint8_t, 2> fff0{0xF0, 0xFF};
    STATIC_REQUIRE(load_le<std::int16_t>(fff0.data()) == -16);
    STATIC_REQUIRE(load_le<std::uint16_t>(std::span<const std::uint8_t>(b1234), 2) == 0x1234);
    // run time, from a non-constant buffer
    std::array<std::uint8_t, 4> rt = b1234;
    CHECK(load_le<std::uint32_t>(rt.data()) == 0x12345678u);
    CHECK(load_le<std::int16_t>(std::span<const std::uint8_t>(rt), 1) == 0x3456);
}

TEST_CASE("load_le reads binary32 floats through bit_cast", "[core][endian]") {
    STATIC_REQUIRE(load_le<float>(point_six.data()) == 0.6f);
    STATIC_REQUIRE(load_le<float>(minus_two_and_half.data()) == -2.5f);
    std::array<std::uint8_t, 4> rt = point_six;
    CHECK(load_le<float>(rt.data()) == 0.6f);
}

TEST_CASE("store_le writes little-endian", "[core][endian]") {
    STATIC_REQUIRE(stored<std::uint32_t>(0x12345678u) == b1234);
    STATIC_REQUIRE(stored<std::int16_t>(-2) == std::array<std::uint8_t, 2>{0xFE, 0xFF});
    STATIC_REQUIRE(stored<std::int32_t>(-2) == std::array<std::uint8_t, 4>{0xFE, 0xFF, 0xFF, 0xFF});
    STATIC_REQUIRE(stored<std::uint16_t>(0xBEEF) == std::array<std::uint8_t, 2>{0xEF, 0xBE});
    STATIC_REQUIRE(stored<float>(0.6f) == point_six);
    STATIC_REQUIRE(stored<float>(-2.5f) == minus_two_and_half);
    std::array<std::uint8_t, 6> buf{};
    store_le<std::int16_t>(std::span<std::uint8_t>(buf), 4, -16);
    CHECK(buf == std::array<std::uint8_t, 6>{0, 0, 0, 0, 0xF0, 0xFF});
}
