// robowire and the hand-written baselines of bench/osp.cpp, run on the same inputs:
// the same outcome, error code and offset, and output (bench/verify/run).
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
        if (osp::impl::key_of<T>() != key) ok = false;
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
int main() {
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
