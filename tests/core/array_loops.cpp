// Array fields at run time, whether coded unrolled or as loops
// (ROBOWIRE_ARRAY_LOOPS; the ctest tests_optimized_for_size builds the whole
// suite with 1 and -Os, which turns ROBOWIRE_OPTIMIZE_SIZE on, and
// tests_optimized_for_size_loops2 this file and the BuWizz3 tests with 2).
#include <robowire/buwizz3.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"

using namespace robowire;
namespace bw = robowire::buwizz3;

namespace {
// The bytes through a volatile copy, so the codec runs at run time.
template <std::size_t N>
std::array<std::uint8_t, N> runtime(const std::array<std::uint8_t, N>& a) {
    std::array<std::uint8_t, N> out{};
    volatile std::uint8_t tmp = 0;
    for (std::size_t i = 0; i < N; ++i) {
        tmp = a[i];
        out[i] = tmp;
    }
    return out;
}
}  // namespace

TEST_CASE("arrays: an element in the middle reports its own offset", "[core][arrays]") {
    // 0x30: power[3] (byte 4) is -128
    const auto m = runtime(std::array<std::uint8_t, 9>{0x30, 1, 2, 3, 0x80, 5, 6, 0, 0});
    CHECK(bw::decode_command(m).error() == error{errc::value_out_of_range, 4});
    // 0x50: function[2] (byte 3) is 0x11, not a port function
    const auto f = runtime(std::array<std::uint8_t, 5>{0x50, 0x10, 0x10, 0x11, 0x10});
    CHECK(bw::decode_command(f).error() == error{errc::invalid_enum, 3});
    bw::set_motor_data md{{1, 2, 3, 4, 5, 6}, 0, 0};
    md.power[4] = static_cast<std::int8_t>(-128 + static_cast<int>(runtime(std::array<std::uint8_t, 1>{0})[0]));
    CHECK(robowire::encode(md).error() == error{errc::value_out_of_range, 5});
    bw::set_pu_port_function pf{};
    pf.function[3] = static_cast<bw::port_function>(0x17);
    CHECK(robowire::encode(pf).error() == error{errc::invalid_enum, 4});
}

TEST_CASE("arrays: status records and words decoded and encoded element by element", "[core][arrays]") {
    std::array<std::uint8_t, 54> s{};
    s[0] = 0x01;
    // accelerometer x, y, z: 0x0010, 0xFFF0 (-16), 0x7FF0
    s[10] = 0x10; s[11] = 0x00; s[12] = 0xF0; s[13] = 0xFF; s[14] = 0xF0; s[15] = 0x7F;
    // motor 3 (bytes 38-45): type 0x4B, velocity -2, absolute position -90 (0xFFA6), position -1000 (0xFFFFFC18)
    const std::uint8_t m3[8] = {0x4B, 0xFE, 0xA6, 0xFF, 0x18, 0xFC, 0xFF, 0xFF};
    for (std::size_t i = 0; i < 8; ++i) s[38 + i] = m3[i];
    // motor 4 (bytes 46-53): type 1, velocity 100, absolute position 179 (0x00B3), position 123456 (0x0001E240)
    const std::uint8_t m4[8] = {0x01, 0x64, 0xB3, 0x00, 0x40, 0xE2, 0x01, 0x00};
    for (std::size_t i = 0; i < 8; ++i) s[46 + i] = m4[i];
    const auto in = runtime(s);
    const auto st = robowire::decode<bw::status>(in);
    REQUIRE(st);
    CHECK(st->accel_raw == std::array<std::int16_t, 3>{16, -16, 0x7FF0});
    CHECK(st->pu_motors[2] == bw::pu_motor{0x4B, -2, -90, -1000});
    CHECK(st->pu_motors[3] == bw::pu_motor{1, 100, 179, 123456});
    CHECK(st->pu_motors[0] == bw::pu_motor{});
    const auto back = robowire::encode(*st);
    REQUIRE(back);
    CHECK(std::equal(back->begin(), back->end(), s.begin(), s.end()));
}

TEST_CASE("ROBOWIRE_OPTIMIZE_SIZE follows -Os unless defined", "[core]") {
#if defined(ROBOWIRE_TEST_SIZE_SET)  // the sanitizer build's size copies set it without -Os
    STATIC_REQUIRE(ROBOWIRE_OPTIMIZE_SIZE == 1);
#elif defined(__OPTIMIZE_SIZE__)
    STATIC_REQUIRE(ROBOWIRE_OPTIMIZE_SIZE == 1);
#else
    STATIC_REQUIRE(ROBOWIRE_OPTIMIZE_SIZE == 0);
#endif
}
