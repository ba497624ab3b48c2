// The hand-written OSP codec of firmware/footprint (firmware/hw_osp.cpp) does
// what robowire's osp::decode and osp::encode do: the same error (code and
// offset) and the same DEV, CMD, P1..P4 for every input, and the same frame
// when a decoded message is encoded again. Its flash figure is only a fair
// comparison if so.
#include <catch2/catch.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <robowire/osp.hpp>
#include <span>

namespace hw_osp {
#define main hw_osp_main  // the size program's own main
#include "../../firmware/hw_osp.cpp"
#undef main
}  // namespace hw_osp

TEST_CASE("osp: the hand-written codec decodes and encodes like robowire", "[osp][baseline]") {
    namespace osp = robowire::osp;
    std::mt19937 rng(20261208);
    auto pick = [&](unsigned n) { return static_cast<unsigned>(rng() % n); };
    constexpr std::uint8_t keys[][2] = {{0, 0x01}, {0, 0x11}, {1, 0x02}, {2, 0x01}, {2, 0x02}, {2, 0x03},
                                        {2, 0x04}, {2, 0x11}, {2, 0x12}, {2, 0x13}, {2, 0x14}, {3, 0x01}};
    std::size_t decoded = 0, errors = 0;
    for (int k = 0; k < 100000; ++k) {
        std::array<std::uint8_t, 12> in{};
        for (auto& b : in) b = static_cast<std::uint8_t>(pick(4) ? pick(6) : rng());
        in[0] = pick(16) ? 0xFF : in[0];
        in[1] = pick(16) ? 0xAA : in[1];
        in[8] = pick(16) ? 0x55 : in[8];
        in[9] = pick(16) ? 0x77 : in[9];
        const auto& key = keys[pick(std::size(keys))];
        in[2] = key[0];
        in[3] = key[1];
        const std::size_t n = pick(4) ? 10 : pick(13);
        INFO("frame " << k << ": " << n << " bytes, DEV " << int{in[2]} << " CMD " << int{in[3]});
        const auto ours = osp::decode(std::span<const std::uint8_t>(in.data(), n));
        hw_osp::osp_msg theirs{};
        const hw_osp::hw::error e = hw_osp::decode(in.data(), n, theirs);
        REQUIRE(static_cast<int>(e.code) == static_cast<int>(ours.code()));
        if (ours.frame()) {  // markers and length right: DEV, CMD, P1..P4 kept
            const auto& f = *ours.frame();
            const std::uint8_t kept[6] = {f.device, f.command, f.params[0], f.params[1], f.params[2], f.params[3]};
            REQUIRE(std::memcmp(kept, theirs.frame, 6) == 0);
        }
        if (!ours) {
            REQUIRE(e.offset == ours.error().offset);
            ++errors;
            continue;
        }
        ++decoded;
        const auto w = osp::encode(*ours);  // encoded again: the same frame
        std::uint8_t out[10];
        const hw_osp::hw::error ee = hw_osp::encode(theirs, out);
        REQUIRE(static_cast<int>(ee.code) == static_cast<int>(w.code()));
        REQUIRE(w);
        REQUIRE(std::memcmp(out, w->data(), 10) == 0);
    }
    CHECK(decoded > 10000);
    CHECK(errors > 10000);
}
