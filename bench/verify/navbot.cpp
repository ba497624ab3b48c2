// robowire and the hand-written baselines of bench/navbot.cpp, run on the same inputs:
// the same outcome, error code and offset, and output (bench/verify/run).
#include "../navbot.cpp"
#include "check.hpp"

static void check_dec(const std::uint8_t* p, std::size_t n, const std::string& ctx) {
    auto r = robowire::decode<nb::maneuver>(std::span<const std::uint8_t>(p, n));
    nb::maneuver m{};
    const auto e = hw_decode(p, n, m);
    if (same_err("maneuver decode", rw_err(r), e, ctx + " n=" + std::to_string(n)) && e == hw::good && !(m == *r))
        mismatch("maneuver decode", ctx);
    const nb::maneuver sentinel{1, 2, 3, 4, nb::switch_a{1}, nb::switch_b{1}, nb::switch_c{1}, nb::switch_d{1}, 5, -5};
    const auto careful = [&](const char* what, auto dec) {
        nb::maneuver c = sentinel;
        const auto ce = dec(p, n, c);
        if (same_err(what, rw_err(r), ce, ctx + " n=" + std::to_string(n)) && !(ce == hw::good ? c == *r : c == sentinel))
            mismatch(what, ctx);
    };
    careful("maneuver decode careful", careful_decode);
    careful("maneuver decode scalar", careful_decode_scalar);
}
static void check_enc(const nb::maneuver& m, const std::string& ctx) {
    auto r = robowire::encode(m);
    std::array<std::uint8_t, 32> b;
    b.fill(0xA5);
    const auto e = hw_encode(m, b.data());
    if (same_err("maneuver encode", rw_err(r), e, ctx) && e == hw::good)
        if (r->size() != 20 || std::memcmp(r->data(), b.data(), 20) != 0) mismatch("maneuver encode", ctx);
    for (std::size_t i = e == hw::good ? 20 : 0; i < b.size(); ++i)
        if (b[i] != 0xA5) { mismatch("maneuver encode", ctx + " stray write"); break; }
    const auto careful = [&](const char* what, auto enc) {
        std::array<std::uint8_t, 32> c;
        c.fill(0xA5);
        const auto ce = enc(m, c.data());
        if (same_err(what, rw_err(r), ce, ctx) && ce == hw::good)
            if (std::memcmp(r->data(), c.data(), 20) != 0) mismatch(what, ctx);
        for (std::size_t i = ce == hw::good ? 20 : 0; i < c.size(); ++i)
            if (c[i] != 0xA5) { mismatch(what, ctx + " stray write"); break; }
    };
    careful("maneuver encode careful", careful_encode);
    careful("maneuver encode scalar", careful_encode_scalar);
}
static void set(nb::maneuver& m, std::size_t k, int v) {
    const auto s = static_cast<std::int8_t>(v);
    const auto u = static_cast<std::uint8_t>(v);
    switch (k) {
    case 0: m.roll = s; break;
    case 1: m.height = u; break;
    case 2: m.pitch = s; break;
    case 3: m.yaw = s; break;
    case 4: m.switch_a = static_cast<nb::switch_a>(u); break;
    case 5: m.switch_b = static_cast<nb::switch_b>(u); break;
    case 6: m.switch_c = static_cast<nb::switch_c>(u); break;
    case 7: m.switch_d = static_cast<nb::switch_d>(u); break;
    case 8: m.ball_x = s; break;
    default: m.ball_y = s; break;
    }
}
// The bench's receivers (handwritten and careful) against robowire's
// reassembler on the same stream of frames: the same outcome or error at
// every push, the same payload when a message completes. The stream is mostly
// messages of 1-16 frames counting down, with frames lost, repeated, of
// another command, cut short or too long, or with a broken header.
template <class Hw>
static void check_reassembly(const char* what, std::uint32_t seed) {
    bench::rng rr{seed};
    nb::reassembler<210> r;
    Hw h{};
    int remaining = -1;
    std::uint8_t command = 2;
    std::array<std::uint8_t, 22> b{};
    bool repeat = false;
    for (int k = 0; k < 20000; ++k) {
        if (!repeat) {  // a repeat sends the last frame's bytes again
            for (auto& x : b) x = rr.byte();
            if (remaining < 0 || rr.next() % 16 == 0) {  // a new message (another command now and then)
                command = static_cast<std::uint8_t>(rr.next() % 4 == 0 ? 1 + rr.next() % 3 : 2);
                remaining = static_cast<int>(rr.next() % 16);
            }
            b[0] = 0x55;
            b[1] = 0xAA;
            b[2] = command;
            b[3] = static_cast<std::uint8_t>(remaining);
        }
        std::size_t n = 20;
        switch (rr.next() % 32) {
        case 0: b[rr.next() % 2] ^= 0x01; break;                         // broken header
        case 1: n = rr.next() % 23; break;                                // any length
        case 2: --remaining; break;                                       // a frame lost before this one
        case 3: b[3] = static_cast<std::uint8_t>(rr.next() % 20); break;  // any remaining
        default: break;
        }
        b[3] = remaining < 0 ? 0 : b[3];
        const auto re = r.push(std::span<const std::uint8_t>(b.data(), n));
        const pushed he = h.push(b.data(), n);
        const std::string ctx = "frame " + std::to_string(k);
        if (!same_err(what, rw_err(re), static_cast<bench::hw::error>(he.error | he.at << 8), ctx) || !re) continue;
        if (static_cast<int>(*re) != static_cast<int>(he.what)) {
            mismatch(what, ctx + " outcome");
            continue;
        }
        if (*re == nb::reassembly::complete &&
            (r.payload().size() != h.size || std::memcmp(r.payload().data(), h.buf, h.size) != 0))
            mismatch(what, ctx + " payload");
        repeat = rr.next() % 8 == 0;
        if (!repeat) --remaining;
    }
}

// The careful sender's frames and lengths are json_frames' for every text
// length a message takes (0 to 3840), with bytes that vary per length.
static void check_sender() {
    std::string text(nb::max_payload, ' ');
    for (std::size_t n = 0; n <= nb::max_payload; ++n) {
        for (std::size_t k = 0; k < n; ++k) text[k] = static_cast<char>((k * 131 + n * 7) & 0xFF);
        const std::string_view s(text.data(), n);
        const auto ours = nb::json_frames(s).value();
        auto next = ours.begin();
        std::size_t count = 0;
        bool same = true;
        careful_frames(s, [&](const sized_frame& w) {
            if (count++ >= ours.size()) {
                same = false;
                return;
            }
            const auto f = *next++;
            same = same && w.size == f.size() && std::memcmp(w.f, f.data(), f.size()) == 0;
        });
        ++g_counts["sender careful"];
        if (!same || count != ours.size()) mismatch("sender careful", "text length " + std::to_string(n));
    }
}

int main() {
    check_sender();
    check_reassembly<hw_reassembler<210>>("reassembly handwritten", 1);
    check_reassembly<hw_reassembler<210, true>>("reassembly careful", 2);
    bench::rng rr;
    const auto frames = maneuver_frames();
    for (std::size_t v = 0; v < frames.size(); ++v) {
        const auto buf = padded<22>(frames[v], rr);
        sweep_lengths(buf, [](std::size_t) { return true; }, check_dec);
        // two bytes changed: the first failing check wins
        for (std::size_t a = 0; a < 20; ++a)
            for (std::size_t b2 = a + 1; b2 < 20; ++b2) {
                auto b = buf;
                b[a] = 0x80;
                b[b2] = 0xFF;
                check_dec(b.data(), 20, "pair");
            }
    }
    const int bad[10] = {101, 101, -101, -128, 3, 2, 2, 3, 6, -6};
    for (const auto& base : maneuvers()) {
        check_enc(base, "bench");
        sweep_fields(base, 10, set, bad, check_enc);
    }
    return report();
}
