#include <robowire/osp/scanner.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "check.hpp"

using namespace robowire;
using osp::scanner;

// docs/osp.md, "The scanner": its buffer (10 bytes, 19 in speed builds), its
// length and three 64-bit counters.
static_assert(sizeof(scanner) == (sizeof(void*) == 8 ? (ROBOWIRE_OPTIMIZE_SIZE ? 48 : 56)
                                                      : (ROBOWIRE_OPTIMIZE_SIZE ? 40 : 48)));

namespace {
using frame10 = std::array<std::uint8_t, 10>;

// Fixed-seed generator (xorshift32).
struct rng {
    std::uint32_t s;
    std::uint32_t next() { s ^= s << 13; s ^= s >> 17; s ^= s << 5; return s; }
    std::uint8_t byte() { return static_cast<std::uint8_t>(next()); }
    std::size_t below(std::size_t n) { return next() % n; }
};

frame10 random_frame(rng& r) {
    frame10 f{0xFF, 0xAA, r.byte(), r.byte(), r.byte(), r.byte(), r.byte(), r.byte(), 0x55, 0x77};
    if (r.below(4) == 0) { f[4] = 0xFF; f[5] = 0xAA; }  // a false start inside the parameters
    return f;
}

// Reference: every window with the markers, leftmost first, a frame consumed whole.
std::vector<frame10> reference(const std::vector<std::uint8_t>& s) {
    std::vector<frame10> out;
    for (std::size_t i = 0; i + 10 <= s.size();) {
        if (s[i] == 0xFF && s[i + 1] == 0xAA && s[i + 8] == 0x55 && s[i + 9] == 0x77) {
            frame10 f{};
            for (std::size_t k = 0; k < 10; ++k) f[k] = s[i + k];
            out.push_back(f);
            i += 10;
        } else {
            ++i;
        }
    }
    return out;
}

struct run {
    std::vector<frame10> frames;
    std::uint64_t skipped = 0, false_starts = 0;
};

run scan_in_chunks(const std::vector<std::uint8_t>& s, std::size_t chunk) {
    scanner sc;
    run out;
    for (std::size_t i = 0; i < s.size(); i += chunk) {
        const std::size_t n = std::min(chunk, s.size() - i);
        sc.feed(std::span(s).subspan(i, n), [&](scanner::frame_bytes f) {
            frame10 a{};
            for (std::size_t k = 0; k < 10; ++k) a[k] = f[k];
            out.frames.push_back(a);
        });
    }
    CHECK(sc.frames() == out.frames.size());
    out.skipped = sc.skipped();
    out.false_starts = sc.false_starts();
    return out;
}

run scan_split_at(const std::vector<std::uint8_t>& s, std::size_t split) {
    scanner sc;
    run out;
    auto keep = [&](scanner::frame_bytes f) {
        frame10 a{};
        for (std::size_t k = 0; k < 10; ++k) a[k] = f[k];
        out.frames.push_back(a);
    };
    sc.feed(std::span(s).first(split), keep);
    sc.feed(std::span(s).subspan(split), keep);
    out.skipped = sc.skipped();
    out.false_starts = sc.false_starts();
    return out;
}

// Noise that contains FF, FF AA, 55, 55 77 often.
void add_noise(rng& r, std::vector<std::uint8_t>& s, std::size_t n) {
    static constexpr std::array<std::uint8_t, 4> tricky{0xFF, 0xAA, 0x55, 0x77};
    for (std::size_t i = 0; i < n; ++i) {
        switch (r.below(6)) {
        case 0: s.push_back(0xFF); s.push_back(0xAA); break;
        case 1: s.push_back(0x55); s.push_back(0x77); break;
        case 2: s.push_back(tricky[r.below(4)]); break;
        default: s.push_back(r.byte());
        }
    }
}

constexpr std::size_t count_frames(std::span<const std::uint8_t> s, std::size_t chunk) {
    scanner sc;
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.size(); i += chunk)
        sc.feed(s.subspan(i, std::min(chunk, s.size() - i)), [&](scanner::frame_bytes) { ++n; });
    return n;
}
}  // namespace

TEST_CASE("scanner: golden stream at compile time", "[osp][scanner]") {
    // noise, a false start (FF AA then a bad trailer), a frame with FF AA in its parameters, a frame
    constexpr auto s = test::hex(
        "00 55 77 FF FF AA 01 02 03 04 05 06 07 08 FF AA 02 11 FF AA 00 00 55 77 FF AA 02 12 D2 04 00 00 55 77");
    STATIC_REQUIRE(count_frames(s, 1) == 2);
    STATIC_REQUIRE(count_frames(s, 7) == 2);
    STATIC_REQUIRE(count_frames(s, 64) == 2);
}

TEST_CASE("scanner: counters", "[osp][scanner]") {
    // 3 noise bytes, FF, a false start of 10 bytes (FF AA .. bad trailer), then a frame
    const auto s = test::hex("00 55 77 FF FF AA 01 02 03 04 05 06 07 08 FF AA 02 11 00 00 00 00 55 77");
    for (std::size_t chunk : {1u, 3u, 10u, 100u}) {
        scanner sc;
        std::size_t n = 0;
        for (std::size_t i = 0; i < s.size(); i += chunk)
            sc.feed(s.span().subspan(i, std::min(chunk, s.size() - i)), [&](scanner::frame_bytes f) {
                ++n;
                CHECK(test::same(f, test::hex("FF AA 02 11 00 00 00 00 55 77")));
            });
        CHECK(n == 1);
        CHECK(sc.frames() == 1);
        // skipped: 00 55 77; FF (lone: next byte is FF, not AA); FF AA 01 .. 08 (10 bytes)
        CHECK(sc.skipped() == 14);
        CHECK(sc.false_starts() == 2);
        CHECK(sc.pending() == 0);
    }
}

TEST_CASE("scanner: N frames split at every chunk boundary yield exactly N", "[osp][scanner]") {
    rng r{12345};
    std::vector<std::uint8_t> s;
    std::vector<frame10> want;
    for (int i = 0; i < 20; ++i) {
        const auto f = random_frame(r);
        want.push_back(f);
        s.insert(s.end(), f.begin(), f.end());
    }
    for (std::size_t split = 0; split <= s.size(); ++split) {
        const auto got = scan_split_at(s, split);
        REQUIRE(got.frames == want);
        CHECK(got.skipped == 0);
    }
    for (std::size_t chunk = 1; chunk <= s.size(); ++chunk) REQUIRE(scan_in_chunks(s, chunk).frames == want);
}

TEST_CASE("scanner: every frame survives noise between frames", "[osp][scanner]") {
    for (std::uint32_t seed = 1; seed <= 200; ++seed) {
        rng r{seed * 2654435761u};
        std::vector<std::uint8_t> s;
        std::vector<frame10> want;
        for (int i = 0; i < 10; ++i) {
            add_noise(r, s, r.below(12));
            const auto f = random_frame(r);
            want.push_back(f);
            s.insert(s.end(), f.begin(), f.end());
        }
        add_noise(r, s, 5);
        // Keep the streams where the noise cannot form a frame of its own or
        // swallow a real one: there the only windows with markers are ours.
        if (reference(s) != want) continue;
        for (std::size_t chunk : {1u, 2u, 3u, 7u, 9u, 10u, 11u, 64u, 4096u}) {
            INFO("seed " << seed << " chunk " << chunk);
            REQUIRE(scan_in_chunks(s, chunk).frames == want);
        }
    }
}

TEST_CASE("scanner: matches the reference on arbitrary streams, any chunking", "[osp][scanner]") {
    for (std::uint32_t seed = 1; seed <= 300; ++seed) {
        rng r{seed};
        std::vector<std::uint8_t> s;
        while (s.size() < 300) {
            if (r.below(3) == 0) {
                const auto f = random_frame(r);
                // sometimes cut a frame short
                s.insert(s.end(), f.begin(), f.begin() + static_cast<std::ptrdiff_t>(r.below(3) ? 10 : r.below(10)));
            } else {
                add_noise(r, s, r.below(8));
            }
        }
        const auto want = reference(s);
        const auto one = scan_in_chunks(s, 1);
        INFO("seed " << seed);
        REQUIRE(one.frames == want);
        for (std::size_t chunk : {2u, 5u, 10u, 13u, 63u, 64u, 65u, 100u, 127u, 128u, 4096u}) {
            const auto got = scan_in_chunks(s, chunk);
            REQUIRE(got.frames == want);
            CHECK(got.skipped == one.skipped);
            CHECK(got.false_starts == one.false_starts);
        }
    }
}

TEST_CASE("scanner: a truncated frame followed by a complete one", "[osp][scanner]") {
    const auto s = test::hex("FF AA 02 11 12 FF AA 02 12 D2 04 00 00 55 77");
    for (std::size_t chunk = 1; chunk <= s.size(); ++chunk) {
        scanner sc;
        std::vector<frame10> got;
        for (std::size_t i = 0; i < s.size(); i += chunk)
            sc.feed(s.span().subspan(i, std::min(chunk, s.size() - i)), [&](scanner::frame_bytes f) {
                frame10 a{};
                for (std::size_t k = 0; k < 10; ++k) a[k] = f[k];
                got.push_back(a);
            });
        REQUIRE(got.size() == 1);
        CHECK(test::same(got[0], test::hex("FF AA 02 12 D2 04 00 00 55 77")));
        CHECK(sc.skipped() == 5);
    }
}

TEST_CASE("scanner: push() one byte at a time, reset()", "[osp][scanner]") {
    scanner sc;
    const auto f = test::hex("FF AA 00 11 01 00 00 00 55 77");
    for (std::size_t i = 0; i + 1 < f.size(); ++i) CHECK_FALSE(sc.push(f[i]));
    CHECK(sc.pending() == 9);
    const auto got = sc.push(f[9]);
    REQUIRE(got);
    CHECK(test::same(*got, f));
    CHECK(sc.push(0xFF) == std::nullopt);
    sc.reset();
    CHECK(sc.pending() == 0);
    CHECK(sc.frames() == 0);
}

namespace {
// The stream's frames by the reference, and for each the stream offset where
// it ends; the counters a scanner must show after the whole stream: pending
// (the first candidate after the last frame that can still become one),
// skipped (the rest), false starts (the start bytes among the skipped bytes).
struct expected {
    std::vector<frame10> frames;
    std::vector<std::size_t> ends;
    std::uint64_t skipped = 0, false_starts = 0;
    std::size_t pending = 0;
};
expected expect(const std::vector<std::uint8_t>& s) {
    expected e;
    std::size_t i = 0, head = s.size();
    std::vector<bool> in_frame(s.size());
    while (i < s.size()) {
        const std::size_t m = s.size() - i;
        if (s[i] == 0xFF && m >= 10 && s[i + 1] == 0xAA && s[i + 8] == 0x55 && s[i + 9] == 0x77) {
            frame10 f{};
            for (std::size_t k = 0; k < 10; ++k) { f[k] = s[i + k]; in_frame[i + k] = true; }
            e.frames.push_back(f);
            e.ends.push_back(i + 10);
            i += 10;
            continue;
        }
        if (s[i] == 0xFF && m < 10 && (m < 2 || s[i + 1] == 0xAA) && (m < 9 || s[i + 8] == 0x55)) {
            head = i;
            break;
        }
        ++i;
    }
    e.pending = s.size() - head;
    for (std::size_t k = 0; k < head; ++k)
        if (!in_frame[k]) {
            ++e.skipped;
            if (s[k] == 0xFF) ++e.false_starts;
        }
    return e;
}

// Start bytes close together, as the chunk path takes 8 positions at a time.
std::vector<std::uint8_t> dense_stream(rng& r, std::size_t size) {
    std::vector<std::uint8_t> s;
    while (s.size() < size) {
        switch (r.below(7)) {
        case 0: s.insert(s.end(), r.below(40), 0xFF); break;  // a run of FF
        case 1: for (std::size_t k = r.below(20); k > 0; --k) { s.push_back(0xFF); s.push_back(0xAA); } break;
        case 2: {  // a frame, sometimes with one marker wrong, sometimes after stray FFs
            s.insert(s.end(), r.below(3), 0xFF);
            frame10 f = random_frame(r);
            if (r.below(3) == 0) f[1 + r.below(9)] ^= static_cast<std::uint8_t>(1 + r.below(255));
            s.insert(s.end(), f.begin(), f.end());
            break;
        }
        case 3: for (std::size_t k = r.below(20); k > 0; --k) s.push_back(static_cast<std::uint8_t>(r.below(0xFF))); break;
        default: add_noise(r, s, r.below(6));
        }
    }
    return s;
}
}  // namespace

TEST_CASE("scanner: dense start bytes, hand-counted", "[osp][scanner]") {
    struct golden {
        std::vector<std::uint8_t> s;
        std::size_t frames, pending;
        std::uint64_t skipped, false_starts;
    };
    std::vector<golden> cases;
    // 100 x FF: every FF but the last fails at its second byte; the last is held
    cases.push_back({std::vector<std::uint8_t>(100, 0xFF), 0, 1, 99, 99});
    // FF AA x 50: the candidates at 0..90 fail at EN1 (an FF); the one at 92 is held (8 bytes)
    std::vector<std::uint8_t> ffaa;
    for (int k = 0; k < 50; ++k) { ffaa.push_back(0xFF); ffaa.push_back(0xAA); }
    cases.push_back({ffaa, 0, 8, 92, 46});
    // three frames with a bad EN2, then a good one
    std::vector<std::uint8_t> near;
    const auto append = [](std::vector<std::uint8_t>& to, const auto& h) {
        for (std::size_t k = 0; k < h.size(); ++k) to.push_back(h[k]);
    };
    for (int k = 0; k < 3; ++k) append(near, test::hex("FF AA 01 02 03 04 05 06 55 00"));
    append(near, test::hex("FF AA 02 12 D2 04 00 00 55 77"));
    cases.push_back({near, 1, 0, 30, 3});
    // a stray FF before each of 5 frames
    std::vector<std::uint8_t> stray;
    for (int k = 0; k < 5; ++k) append(stray, test::hex("FF FF AA 02 12 D2 04 00 00 55 77"));
    cases.push_back({stray, 5, 0, 5, 5});
    for (const auto& g : cases)
        for (std::size_t chunk : {1u, 9u, 10u, 17u, 18u, 25u, 32u, 64u, 4096u}) {
            INFO("stream of " << g.s.size() << " bytes, chunk " << chunk);
            const auto got = scan_in_chunks(g.s, chunk);
            CHECK(got.frames.size() == g.frames);
            CHECK(got.skipped == g.skipped);
            CHECK(got.false_starts == g.false_starts);
            scanner sc;
            for (std::size_t i = 0; i < g.s.size(); i += chunk)
                sc.feed(std::span(g.s).subspan(i, std::min(chunk, g.s.size() - i)), [](scanner::frame_bytes) {});
            CHECK(sc.pending() == g.pending);
        }
}

TEST_CASE("scanner: dense streams match the reference and its counters, any chunking", "[osp][scanner]") {
    for (std::uint32_t seed = 1; seed <= 400; ++seed) {
        rng r{seed * 2246822519u};
        const auto s = dense_stream(r, 200 + r.below(600));
        const auto want = expect(s);
        for (std::size_t chunk : {1u, 10u, 17u, 18u, 19u, 24u, 25u, 26u, 33u, 64u, 100u, 4096u}) {
            INFO("seed " << seed << " chunk " << chunk);
            scanner sc;
            std::vector<frame10> got;
            for (std::size_t i = 0; i < s.size(); i += chunk)
                sc.feed(std::span(s).subspan(i, std::min(chunk, s.size() - i)), [&](scanner::frame_bytes f) {
                    // the counters are up to date in the callback
                    const std::size_t k = got.size();
                    REQUIRE(k < want.ends.size());
                    CHECK(sc.frames() == k + 1);
                    CHECK(sc.skipped() + 10 * sc.frames() == want.ends[k]);
                    frame10 a{};
                    for (std::size_t b = 0; b < 10; ++b) a[b] = f[b];
                    got.push_back(a);
                });
            REQUIRE(got == want.frames);
            CHECK(sc.skipped() == want.skipped);
            CHECK(sc.false_starts() == want.false_starts);
            CHECK(sc.pending() == want.pending);
        }
    }
}

namespace {
// 70 x FF, then a frame: feeds it in chunks; {frames seen, frames(), false_starts(), skipped()}.
constexpr std::array<std::uint64_t, 4> after_70_starts(std::size_t chunk) {
    std::array<std::uint8_t, 80> s{};
    for (std::size_t k = 0; k < 70; ++k) s[k] = 0xFF;
    const frame10 f{0xFF, 0xAA, 0x02, 0x11, 0x00, 0x00, 0x00, 0x00, 0x55, 0x77};
    for (std::size_t k = 0; k < 10; ++k) s[70 + k] = f[k];
    scanner sc;
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < s.size(); i += chunk)
        sc.feed(std::span<const std::uint8_t>(s).subspan(i, std::min(chunk, s.size() - i)),
                [&](scanner::frame_bytes) { ++n; });
    return {n, sc.frames(), sc.false_starts(), sc.skipped()};
}
}  // namespace

TEST_CASE("scanner: a frame after 70 start bytes, masks at compile and run time", "[osp][scanner]") {
    // each FF before the frame is followed by FF, not AA: 70 false starts, 70 bytes skipped.
    // 80: one chunk (a 64-position block, then the last 16); 75: the frame held across chunks.
    constexpr std::array<std::uint64_t, 4> golden{1, 1, 70, 70};
    STATIC_REQUIRE(after_70_starts(80) == golden);
    STATIC_REQUIRE(after_70_starts(75) == golden);
    for (std::size_t chunk : {1u, 16u, 64u, 75u, 80u}) {
        INFO("chunk " << chunk);
        CHECK(after_70_starts(chunk) == golden);
    }
}
