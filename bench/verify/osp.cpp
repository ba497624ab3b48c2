// robowire and the hand-written baselines of bench/osp.cpp, run on the same inputs:
// the same outcome, error code and offset, and output (bench/verify/run). The
// scanners: the same frames, byte-exact and in order, and the same counters
// in each on_frame and after every chunk, on the bench streams and on random
// ones, in many chunkings.
#include "../osp.cpp"
#include "check.hpp"

static void check_voltage(const std::uint8_t* p, std::size_t n, const std::string& ctx) {
    auto r = robowire::decode<osp::obp1::voltage>(std::span<const std::uint8_t>(p, n));
    std::int16_t cv = 0x1234;
    const auto e = hw_voltage(p, n, cv);
    if (same_err("osp voltage", rw_err(r), e, ctx + " n=" + std::to_string(n)) && e == hw::good && cv != r->centivolts)
        mismatch("osp voltage", ctx);
    std::int16_t ccv = 0x1234;
    const auto ce = careful_voltage(p, n, ccv);
    if (same_err("osp voltage careful", rw_err(r), ce, ctx + " n=" + std::to_string(n)) &&
        (ce == hw::good ? ccv != r->centivolts : ccv != 0x1234))
        mismatch("osp voltage careful", ctx);
}
static void check_any(const std::uint8_t* p, std::size_t n, const std::string& ctx) {
    auto r = osp::decode(std::span<const std::uint8_t>(p, n));
    hw_msg m{}, c{};
    std::memset(&m, 0xEE, sizeof m);
    std::memset(&c, 0xEE, sizeof c);
    const auto e = hw_decode_any(p, n, m);
    const auto ce = careful_decode_any(p, n, c);
    if (ce != e || (e == hw::good && std::memcmp(&m, &c, sizeof m) != 0))
        mismatch("osp decode careful", ctx + " n=" + std::to_string(n));
    ++g_counts["osp decode careful"];
    if (!same_err("osp decode", rw_err(r), e, ctx + " n=" + std::to_string(n))) return;
    // frame(): held whenever the markers and length were right
    const bool framed = r.frame().has_value();
    const unsigned code = e & 0xFF;
    const bool hw_framed = e == hw::good || code == hw::unknown_message || code == hw::invalid_enum;
    if (framed != hw_framed) { mismatch("osp decode frame presence", ctx); return; }
    if (framed) {
        const auto& f = *r.frame();
        if (f.device != m.dev || f.command != m.cmd || std::memcmp(f.params.data(), m.p, 4) != 0)
            mismatch("osp decode frame", ctx);
    }
    if (e != hw::good) return;
    const unsigned key = static_cast<unsigned>(m.dev << 8 | m.cmd);
    bool ok = true;
    std::visit([&](const auto& x) {
        using T = std::remove_cvref_t<decltype(x)>;
        if (osp::impl::frame_key_of<T>() != key) ok = false;
        if constexpr (std::is_same_v<T, osp::generic::device_type>) ok = ok && m.b == static_cast<std::uint8_t>(x.type);
        else if constexpr (std::is_same_v<T, osp::arm1::set_angle>) ok = ok && m.b == x.joint && m.a == x.angle;
        else if constexpr (std::is_same_v<T, osp::obp1::soc>) ok = ok && m.a == x.soc_raw;
        else if constexpr (std::is_same_v<T, osp::obp1::voltage>) ok = ok && m.a == static_cast<std::uint16_t>(x.centivolts);
        else if constexpr (std::is_same_v<T, osp::obp1::current>) ok = ok && m.a == static_cast<std::uint16_t>(x.milliamps);
        else if constexpr (std::is_same_v<T, osp::obp1::status>) ok = ok && m.b == static_cast<std::uint8_t>(x.state) && m.a == x.flags;
    }, *r);
    if (!ok) mismatch("osp decode value", ctx);
}
template <class F>
static void sweep(const std::vector<frame10>& ins, F check) {
    bench::rng rr;
    for (std::size_t v = 0; v < ins.size(); ++v) {
        const auto buf = padded<12>(ins[v], rr);
        sweep_lengths(buf, [](std::size_t) { return true; }, [&](const std::uint8_t* p, std::size_t n, const std::string& ctx) {
            check(p, n, ctx + " v=" + std::to_string(v));
        });
        for (std::size_t a = 0; a < 10; ++a)
            for (std::size_t c = a + 1; c < 10; ++c)
                for (int x : {0x00, 0x13, 0xFF}) {
                    auto b = buf;
                    b[a] = static_cast<std::uint8_t>(x ^ 0x5A);
                    b[c] = static_cast<std::uint8_t>(x);
                    check(b.data(), 10, "pair");
                }
    }
}
using frame_list = std::vector<frame10>;
static frame10 to_frame(const std::uint8_t* f) {
    frame10 a{};
    std::memcpy(a.data(), f, 10);
    return a;
}
// `s` fed in chunks of `chunk` bytes (the last may be shorter) to robowire's
// scanner, the careful scanner and the state machine, which also takes it
// byte by byte; the counters as on_frame sees them are compared too.
static void check_scan(const std::uint8_t* s, std::size_t size, std::size_t chunk, const std::string& ctx) {
    osp::scanner rw;
    careful_scanner hand;
    state_machine sm;
    frame_list f_rw, f_hand, f_sm;
    using counts = std::array<std::uint64_t, 3>;  // frames, skipped, false starts, in on_frame
    std::vector<counts> c_rw, c_hand, c_sm;
    bool ok = true;
    for (std::size_t i = 0; i < size && ok; i += chunk) {
        const std::size_t n = std::min(chunk, size - i);
        rw.feed(std::span(s + i, n), [&](osp::scanner::frame_bytes f) {
            f_rw.push_back(to_frame(f.data()));
            c_rw.push_back({rw.frames(), rw.skipped(), rw.false_starts()});
        });
        hand.feed(s + i, n, [&](const std::uint8_t* f) {
            f_hand.push_back(to_frame(f));
            c_hand.push_back({hand.sm.frames, hand.sm.skipped, hand.sm.false_starts});
        });
        for (std::size_t k = i; k < i + n; ++k)
            sm.push(s[k], [&](const std::uint8_t* f) {
                f_sm.push_back(to_frame(f));
                c_sm.push_back({sm.frames, sm.skipped, sm.false_starts});
            });
        ok = f_rw == f_sm && f_hand == f_sm && c_rw == c_sm && c_hand == c_sm && rw.frames() == sm.frames &&
             hand.sm.frames == sm.frames && rw.skipped() == sm.skipped && hand.sm.skipped == sm.skipped &&
             rw.false_starts() == sm.false_starts && hand.sm.false_starts == sm.false_starts && rw.pending() == sm.n &&
             hand.sm.n == sm.n;
        if (!ok)
            std::printf("MISMATCH osp scanner %s chunk=%zu after %zu bytes: frames %zu/%zu/%zu skipped %llu/%llu/%llu "
                        "false starts %llu/%llu/%llu pending %zu/%zu/%zu (robowire/careful/bytewise)\n",
                        ctx.c_str(), chunk, i + n, f_rw.size(), f_hand.size(), f_sm.size(),
                        static_cast<unsigned long long>(rw.skipped()), static_cast<unsigned long long>(hand.sm.skipped),
                        static_cast<unsigned long long>(sm.skipped), static_cast<unsigned long long>(rw.false_starts()),
                        static_cast<unsigned long long>(hand.sm.false_starts),
                        static_cast<unsigned long long>(sm.false_starts), rw.pending(), hand.sm.n, sm.n);
    }
    ++g_counts["osp scanner"];
    if (!ok) mismatch("osp scanner", ctx);
}
static const std::size_t chunks[] = {1,  2,  3,  7,  9,  10, 11, 15, 16,  17,  18,   24,     25,
                                     26, 33, 40, 63, 64, 65, 72, 73, 74, 100, 137, 4096, 1 << 16};
int main() {
    // the bench streams, and their first bytes cut at every length up to 100
    for (kind k : {kind::clean, kind::noisy, kind::noise, kind::all_ff, kind::ff_aa, kind::near_miss}) {
        const auto s = stream(k);
        const std::string name = "stream " + std::to_string(static_cast<int>(k));
        for (std::size_t c : chunks) check_scan(s.data(), s.size(), c, name);
        for (std::size_t n = 0; n <= 100; ++n)
            for (std::size_t c : chunks) check_scan(s.data(), n, c, name + " n=" + std::to_string(n));
    }
    // random streams: frames (some cut short, some with FF AA in their
    // parameters) and noise rich in FF, AA, 55 and 77; runs of one pattern
    bench::rng r;
    for (int seed = 0; seed < 3000; ++seed) {
        std::vector<std::uint8_t> s;
        const std::size_t size = 20 + r.next() % 600;
        while (s.size() < size) {
            const auto pick = r.next() % 8;
            if (pick < 2) {
                frame10 f{0xFF, 0xAA, r.byte(), r.byte(), r.byte(), r.byte(), r.byte(), r.byte(), 0x55, 0x77};
                if (r.next() % 4 == 0) { f[4] = 0xFF; f[5] = 0xAA; }
                if (r.next() % 4 == 0) f[1 + r.next() % 9] ^= static_cast<std::uint8_t>(1 + r.next() % 255);
                s.insert(s.end(), f.begin(), f.begin() + (r.next() % 4 ? 10 : static_cast<int>(r.next() % 10)));
            } else if (pick < 6) {
                static constexpr std::uint8_t tricky[] = {0xFF, 0xAA, 0x55, 0x77, 0x00};
                s.push_back(r.next() % 2 ? tricky[r.next() % 5] : r.byte());
            } else {
                static constexpr std::uint8_t runs[] = {0xFF, 0xAA, 0xFF, 0xAA, 0x55, 0x77};  // FF; FF AA; FF AA 55 77
                const std::size_t period = 1 + r.next() % 4, len = r.next() % 40;
                for (std::size_t k = 0; k < len; ++k) s.push_back(period == 3 ? runs[2 + k % 4] : runs[k % period]);
            }
        }
        for (std::size_t c : chunks)
            if (c <= 2 * s.size()) check_scan(s.data(), s.size(), c, "random " + std::to_string(seed));
        check_scan(s.data(), s.size(), 1 + r.next() % 80, "random " + std::to_string(seed));
    }

    const auto v = voltage_frames();
    sweep(std::vector<frame10>(v.begin(), v.end()), check_voltage);
    const auto f = frames();
    std::vector<frame10> all(f.begin(), f.end());
    // every DEV/CMD pair, with P1 over its range
    for (int dev = 0; dev < 256; ++dev)
        for (int cmd = 0; cmd < 256; ++cmd)
            for (int p1 : {0, 1, 3, 4, 5, 0xFF}) {
                frame10 x{0xFF, 0xAA, static_cast<std::uint8_t>(dev), static_cast<std::uint8_t>(cmd),
                          static_cast<std::uint8_t>(p1), 0x9C, 0x42, 0x17, 0x55, 0x77};
                check_any(x.data(), 10, "key");
            }
    sweep(all, check_any);
    return report();
}
