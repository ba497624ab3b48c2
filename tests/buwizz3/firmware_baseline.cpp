// The hand-written status decoder of firmware/footprint (firmware/hw_buwizz3_status.cpp)
// does what robowire::decode<buwizz3::status> does: the same error (code and
// offset) and the same fields for every input. Its flash figure is only a fair
// comparison if so. Little-endian hosts: that decoder copies wire runs as they are.
#include <catch2/catch.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <robowire/buwizz3.hpp>
#include <span>
#include <vector>

#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
namespace {
// A float's bit pattern (NaNs compare unequal as floats).
std::uint32_t bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}
}  // namespace

namespace hw_status {
#define main hw_buwizz3_status_main  // the size program's own main
#include "../../firmware/hw_buwizz3_status.cpp"
#undef main
}  // namespace hw_status

TEST_CASE("buwizz3: the hand-written status decoder decodes like robowire", "[buwizz3][status][baseline]") {
    std::mt19937 rng(20261205);
    auto pick = [&](unsigned n) { return static_cast<unsigned>(rng() % n); };
    constexpr std::size_t edges[] = {0, 1, 2, 53, 54, 55, 67, 68, 69, 128, 129, 130};
    std::size_t good = 0, codes[8] = {};
    for (int k = 0; k < 50000; ++k) {
        const std::size_t n = pick(2) ? edges[pick(std::size(edges))] : pick(140);
        std::vector<std::uint8_t> in(n);
        for (auto& b : in) b = static_cast<std::uint8_t>(rng());
        if (n > 0 && pick(8) != 0) in[0] = 0x01;
        const auto ours = robowire::decode<robowire::buwizz3::status>(std::span<const std::uint8_t>(in));
        hw_status::status theirs{};
        const hw_status::hw::error e = hw_status::decode_status(in.data(), in.size(), theirs);
        INFO("input of " << n << " bytes, byte 0 = " << (n ? int{in[0]} : -1));
        REQUIRE(static_cast<int>(e.code) == static_cast<int>(ours.code()));
        if (!ours) {
            REQUIRE(e.offset == ours.error().offset);
            ++codes[e.code < 8 ? e.code : 7];
            continue;
        }
        ++good;
        const auto& s = *ours;
        REQUIRE(theirs.flags == s.flags);
        REQUIRE(theirs.battery == s.battery_voltage_raw);
        REQUIRE(std::equal(s.motor_current_raw.begin(), s.motor_current_raw.end(), theirs.current));
        REQUIRE(theirs.temperature == s.temperature_c);
        REQUIRE(std::equal(s.accel_raw.begin(), s.accel_raw.end(), theirs.accel));
        REQUIRE(theirs.bl_command == s.bootloader_response.command);
        REQUIRE(theirs.bl_code == s.bootloader_response.code);
        REQUIRE(std::equal(s.bootloader_response.data.begin(), s.bootloader_response.data.end(), theirs.bl_data));
        REQUIRE(theirs.charge == s.charge_current_ma);
        for (std::size_t m = 0; m < 4; ++m) {
            REQUIRE(theirs.motors[m].type == static_cast<std::uint8_t>(s.pu_motors[m].type));
            REQUIRE(theirs.motors[m].velocity == s.pu_motors[m].velocity);
            REQUIRE(theirs.motors[m].absolute == s.pu_motors[m].absolute_position);
            REQUIRE(theirs.motors[m].position == s.pu_motors[m].position);
        }
        REQUIRE(theirs.has_pid == s.pid_state.has_value());
        if (s.pid_state) {  // bit patterns: NaNs compare unequal
            REQUIRE(bits(theirs.process_value) == bits(s.pid_state->process_value));
            REQUIRE(bits(theirs.error) == bits(s.pid_state->error));
            REQUIRE(bits(theirs.output) == bits(s.pid_state->output));
            REQUIRE(theirs.integrator == s.pid_state->integrator);
            REQUIRE(theirs.motor_output == s.pid_state->motor_output);
        }
        REQUIRE(theirs.ignored == s.ignored_trailing_bytes);
    }
    // both forms and every error the decoder has
    CHECK(good > 1000);
    for (std::size_t c : {1u, 2u, 3u, 6u}) {
        INFO("error code " << c);
        CHECK(codes[c] > 0);
    }
}
#endif
