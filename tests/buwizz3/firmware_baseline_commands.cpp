// The hand-written BuWizz3 codec of firmware/footprint (firmware/hw_buwizz3.cpp)
// does what robowire's decode_command, encode and decode_notification do: the
// same error (code and offset) for every input, and the same bytes when a
// decoded command is encoded again. Its flash figure is only a fair comparison
// if so. Little-endian hosts: that codec copies wire runs as they are.
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
namespace hw_commands {
#define main hw_buwizz3_main  // the size program's own main
#include "../../firmware/hw_buwizz3.cpp"
#undef main
}  // namespace hw_commands

namespace {
namespace bw = robowire::buwizz3;
using hw_error = hw_commands::hw::error;

// Random bytes, often with the values a valid command has (zeros, small numbers).
std::vector<std::uint8_t> random_input(std::mt19937& rng, std::uint8_t first, std::size_t n) {
    std::vector<std::uint8_t> in(n);
    const auto style = rng() % 4;
    for (auto& b : in) {
        const auto r = rng();
        b = static_cast<std::uint8_t>(style == 0 ? r : style == 1 ? r % 4 : style == 2 ? (r % 3 ? 0 : r) : r % 40);
    }
    if (n > 0) in[0] = first;
    if (n > 1 && first == 0x40 && rng() % 4) in[1] = 0x10;
    return in;
}
}  // namespace

TEST_CASE("buwizz3: the hand-written command codec decodes and encodes like robowire", "[buwizz3][baseline]") {
    std::mt19937 rng(20261206);
    constexpr std::uint8_t kinds[] = {0x20, 0x21, 0x22, 0x23, 0x30, 0x31, 0x32, 0x33, 0x34, 0x35, 0x36, 0x37,
                                      0x38, 0x40, 0x50, 0x51, 0x52, 0x53, 0xA1, 0xAC, 0x00, 0x24, 0xFF};
    std::size_t decoded = 0, encoded = 0, decode_errors = 0;
    for (int k = 0; k < 200000; ++k) {
        const std::uint8_t kind = kinds[rng() % std::size(kinds)];
        const std::size_t want = hw_commands::wire_size(kind);
        const std::size_t n = rng() % 3 ? (kind == 0x36 ? std::size_t{1} + 4 * (rng() % 5) : want) : rng() % 40;
        const auto in = random_input(rng, kind, n);
        INFO("command 0x" << std::hex << int{kind} << std::dec << ", " << n << " bytes");
        const auto ours = bw::decode_command(std::span<const std::uint8_t>(in));
        hw_commands::command theirs{};
        const hw_error e = hw_commands::decode_command(in.data(), in.size(), theirs);
        REQUIRE(static_cast<int>(e.code) == static_cast<int>(ours.code()));
        if (!ours) {
            REQUIRE(e.offset == ours.error().offset);
            ++decode_errors;
            continue;
        }
        ++decoded;
        // encoded again: the same bytes, or the same error
        const auto w = robowire::encode(*ours);
        std::uint8_t out[38] = {};
        hw_error ee{};
        const std::size_t m = hw_commands::encode_command(theirs, out, ee);
        REQUIRE(static_cast<int>(ee.code) == static_cast<int>(w.code()));
        if (w) {
            ++encoded;
            REQUIRE(m == w->size());
            REQUIRE(std::memcmp(out, w->data(), m) == 0);
            REQUIRE(std::memcmp(out, in.data(), m) == 0);  // what was decoded
        }
    }
    CHECK(decoded > 10000);
    CHECK(encoded > 10000);
    CHECK(decode_errors > 10000);
}

TEST_CASE("buwizz3: the hand-written notification decoder decodes like robowire", "[buwizz3][baseline]") {
    std::mt19937 rng(20261207);
    constexpr std::uint8_t kinds[] = {0x01, 0x23, 0xAC, 0x00, 0x02};
    constexpr std::size_t sizes[] = {0, 1, 24, 25, 26, 53, 54, 55, 67, 68, 69, 129, 130};
    std::size_t good = 0, bad = 0;
    for (int k = 0; k < 50000; ++k) {
        const std::uint8_t kind = kinds[rng() % std::size(kinds)];
        const std::size_t n = rng() % 2 ? sizes[rng() % std::size(sizes)] : rng() % 140;
        const auto in = random_input(rng, kind, n);
        INFO("notification 0x" << std::hex << int{kind} << std::dec << ", " << n << " bytes");
        const auto ours = bw::decode_notification(std::span<const std::uint8_t>(in));
        hw_commands::notification theirs{};
        const hw_error e = hw_commands::decode_notification(in.data(), in.size(), theirs);
        REQUIRE(static_cast<int>(e.code) == static_cast<int>(ours.code()));
        if (!ours) {
            REQUIRE(e.offset == ours.error().offset);
            ++bad;
            continue;
        }
        ++good;
        if (const auto* s = std::get_if<bw::status>(&*ours)) {
            REQUIRE(theirs.s.flags == s->flags);
            REQUIRE(theirs.s.motors[3].position == s->pu_motors[3].position);
            REQUIRE(theirs.s.has_pid == s->pid_state.has_value());
            REQUIRE(theirs.s.ignored == s->ignored_trailing_bytes);
        } else if (const auto* a = std::get_if<bw::accel_calibration>(&*ours)) {
            REQUIRE(std::memcmp(theirs.factors, a->factors.data(), 24) == 0);
        } else {
            const auto& c = std::get<bw::charger_settings>(*ours);
            REQUIRE(theirs.charger.n == c.data.size());
            REQUIRE(std::memcmp(theirs.charger.data, c.data.data(), c.data.size()) == 0);
        }
    }
    CHECK(good > 5000);
    CHECK(bad > 5000);
}
#endif
