// The hand-written NAVBOT baseline of firmware/footprint (firmware/hw_navbot.cpp)
// does what robowire's reassembler does: the same outcome and the same error
// for every frame of long random streams (repeats, restarts, lost frames,
// other commands, breaks). Its flash figure is only a fair comparison if so.
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <array>
#include <random>
#include <robowire/navbot.hpp>

#define main hw_navbot_main  // the size program's own main
#include "../../firmware/hw_navbot.cpp"
#undef main

namespace {
// robowire's outcome in the baseline's numbering.
outcome as_baseline(robowire::navbot::reassembly r) {
    using robowire::navbot::reassembly;
    switch (r) {
    case reassembly::need_more: return need_more;
    case reassembly::complete: return complete;
    case reassembly::single: return single;
    case reassembly::duplicate: return duplicate;
    case reassembly::restarted: return restarted;
    case reassembly::discarded: return discarded;
    }
    return need_more;
}
}  // namespace

TEST_CASE("navbot: the hand-written baseline reassembles like robowire", "[navbot][multiframe][baseline]") {
    std::mt19937 rng(20261201);
    auto pick = [&](unsigned n) { return static_cast<unsigned>(rng() % n); };
    robowire::navbot::reassembler<120> ours;
    reassembler theirs{};
    std::array<std::uint8_t, 20> wire{0x55, 0xAA, 0x02, 0};
    std::size_t outcomes[6] = {}, errors = 0;
    for (int n = 0; n < 20000; ++n) {
        const unsigned what = pick(10);
        if (what == 0) {
            // a repeat of the frame before
        } else if (what <= 5 && wire[3] > 0) {
            wire[3] = static_cast<std::uint8_t>(wire[3] - 1);  // the next frame of the message
        } else {
            wire[2] = pick(4) == 0 ? 0x10 : 0x02;               // maneuver or JSON
            wire[3] = static_cast<std::uint8_t>(pick(10));      // up to 10 frames (more than 120 bytes)
            if (pick(8) == 0) wire[3] = static_cast<std::uint8_t>(wire[3] + 1);  // a lost frame
        }
        if (what != 0)
            for (std::size_t i = 5; i < 20; ++i) wire[i] = static_cast<std::uint8_t>(pick(3) == 0 ? 0 : rng());
        const auto r = ours.push(wire);
        outcome o = need_more;
        const hw::error e = theirs.push(wire.data(), wire.size(), o);
        INFO("frame " << n << ": command " << int{wire[2]} << " remaining " << int{wire[3]});
        REQUIRE(static_cast<int>(e.code) == static_cast<int>(r ? robowire::errc::ok : r.code()));
        if (r) {
            REQUIRE(o == as_baseline(*r));
            ++outcomes[o];
            if (*r == robowire::navbot::reassembly::complete) {
                REQUIRE(theirs.size == ours.payload().size());
                REQUIRE(std::equal(theirs.buf, theirs.buf + theirs.size, ours.payload().begin()));
            }
        } else {
            REQUIRE(e.offset == r.error().offset);
            ++errors;
        }
    }
    // every outcome and errors occurred
    for (std::size_t k = 0; k < 6; ++k) {
        INFO("outcome " << k);
        CHECK(outcomes[k] > 0);
    }
    CHECK(errors > 0);
}
