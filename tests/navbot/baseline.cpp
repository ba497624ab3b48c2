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

TEST_CASE("navbot: the hand-written maneuver codec decodes and encodes like robowire",
          "[navbot][maneuver][baseline]") {
    namespace nb = robowire::navbot;
    std::mt19937 rng(20261205);
    auto pick = [&](unsigned n) { return static_cast<unsigned>(rng() % n); };
    // a byte, often one a valid maneuver has
    auto value = [&]() {
        switch (pick(4)) {
        case 0: return static_cast<std::uint8_t>(rng());
        case 1: return static_cast<std::uint8_t>(pick(3));
        case 2: return static_cast<std::uint8_t>(256 - pick(6));
        default: return static_cast<std::uint8_t>(pick(101));
        }
    };
    std::size_t decoded = 0, encoded = 0, errors = 0;
    for (int k = 0; k < 100000; ++k) {
        const bool sm = pick(2) != 0;
        const auto enc = sm ? nb::sign_encoding::sign_magnitude : nb::sign_encoding::twos_complement;
        std::array<std::uint8_t, 24> wire{};
        for (auto& b : wire) b = value();
        // each channel valid 7 times in 8 (signed ones in the frame's sign encoding)
        constexpr int lo[10] = {-100, 0, -100, -100, 0, 0, 0, 0, -5, -5}, hi[10] = {100, 100, 100, 100, 2, 1, 1, 2, 5, 5};
        for (std::size_t c = 0; c < 10; ++c) {
            if (pick(8) == 0) continue;
            const int v = lo[c] + static_cast<int>(pick(static_cast<unsigned>(hi[c] - lo[c] + 1)));
            wire[5 + c] = static_cast<std::uint8_t>(sm && v < 0 ? 0x80 | -v : v & 0xFF);
        }
        const std::size_t n = pick(4) ? 20 : pick(24);
        if (pick(16)) wire[0] = 0x55;
        if (pick(16)) wire[1] = 0xAA;
        if (pick(8)) wire[2] = 0x10;
        if (pick(8)) wire[3] = 0;
        INFO("frame " << k << ": " << n << " bytes, " << (sm ? "sign-magnitude" : "two's complement"));
        const auto ours = nb::decode_maneuver(std::span<const std::uint8_t>(wire.data(), n), enc);
        maneuver theirs{};
        const hw::error e = decode_maneuver(wire.data(), n, sm, theirs);
        REQUIRE(static_cast<int>(e.code) == static_cast<int>(ours.code()));
        if (!ours) {
            REQUIRE(e.offset == ours.error().offset);
            ++errors;
        } else {
            ++decoded;
            REQUIRE(theirs.roll == ours->roll);
            REQUIRE(theirs.height == ours->height);
            REQUIRE(theirs.pitch == ours->pitch);
            REQUIRE(theirs.yaw == ours->yaw);
            REQUIRE(theirs.switch_a == static_cast<std::uint8_t>(ours->switch_a));
            REQUIRE(theirs.switch_b == static_cast<std::uint8_t>(ours->switch_b));
            REQUIRE(theirs.switch_c == static_cast<std::uint8_t>(ours->switch_c));
            REQUIRE(theirs.switch_d == static_cast<std::uint8_t>(ours->switch_d));
            REQUIRE(theirs.ball_x == ours->ball_x);
            REQUIRE(theirs.ball_y == ours->ball_y);
        }
        // encode the maneuver in wire[5..14] as values (two's complement)
        maneuver m;
        std::memcpy(&m, wire.data() + 5, sizeof m);
        if (pick(2)) m.pitch = static_cast<std::int8_t>(-static_cast<int>(pick(101)));
        const nb::maneuver mo{m.roll,
                              m.height,
                              m.pitch,
                              m.yaw,
                              static_cast<nb::switch_a>(m.switch_a),
                              static_cast<nb::switch_b>(m.switch_b),
                              static_cast<nb::switch_c>(m.switch_c),
                              static_cast<nb::switch_d>(m.switch_d),
                              m.ball_x,
                              m.ball_y};
        const auto w = nb::encode(mo, enc);
        std::uint8_t out[20];
        const hw::error ee = encode(m, sm, out);
        REQUIRE(static_cast<int>(ee.code) == static_cast<int>(w.code()));
        if (w) {
            ++encoded;
            REQUIRE(std::equal(out, out + 20, w->begin()));
        } else {
            REQUIRE(ee.offset == w.error().offset);
        }
    }
    CHECK(decoded > 1000);
    CHECK(encoded > 1000);
    CHECK(errors > 1000);
}
