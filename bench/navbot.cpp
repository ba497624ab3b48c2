// NAVBOT: maneuver encode/decode; fragment + reassemble a 200-byte JSON payload.
// Baseline: the hand-written code a careful user would write.
#include <robowire/navbot.hpp>

#include <string>

#include "common.hpp"

namespace {
namespace nb = robowire::navbot;

bench::vector<nb::maneuver> maneuvers() {
    bench::rng r;
    bench::vector<nb::maneuver> v(bench::variants);
    auto s = [&](int lim) { return static_cast<std::int8_t>(static_cast<int>(r.next() % static_cast<unsigned>(2 * lim + 1)) - lim); };
    for (auto& m : v) {
        m.roll = s(100);
        m.height = static_cast<std::uint8_t>(r.next() % 101);
        m.pitch = s(100);
        m.yaw = s(100);
        m.switch_a = static_cast<nb::switch_a>(r.next() % 3);
        m.switch_b = static_cast<nb::switch_b>(r.next() % 2);
        m.switch_c = static_cast<nb::switch_c>(r.next() % 2);
        m.switch_d = static_cast<nb::switch_d>(r.next() % 3);
        m.ball_x = s(5);
        m.ball_y = s(5);
    }
    return v;
}
bench::vector<std::array<std::uint8_t, 20>> maneuver_frames() {
    bench::vector<std::array<std::uint8_t, 20>> v;
    for (const auto& m : maneuvers()) {
        const auto b = robowire::encode(m).value();
        std::array<std::uint8_t, 20> a{};
        std::copy(b.begin(), b.end(), a.begin());
        v.push_back(a);
    }
    return v;
}

bool in(int v, int lo, int hi) { return v >= lo && v <= hi; }
bool hw_encode(const nb::maneuver& m, std::uint8_t* out) {
    if (!in(m.roll, -100, 100) || m.height > 100 || !in(m.pitch, -100, 100) || !in(m.yaw, -100, 100) ||
        static_cast<int>(m.switch_a) > 2 || static_cast<int>(m.switch_b) > 1 || static_cast<int>(m.switch_c) > 1 ||
        static_cast<int>(m.switch_d) > 2 || !in(m.ball_x, -5, 5) || !in(m.ball_y, -5, 5))
        return false;
    std::memset(out, 0, 20);
    out[0] = 0x55; out[1] = 0xAA; out[2] = 0x10;
    out[5] = static_cast<std::uint8_t>(m.roll);
    out[6] = m.height;
    out[7] = static_cast<std::uint8_t>(m.pitch);
    out[8] = static_cast<std::uint8_t>(m.yaw);
    out[9] = static_cast<std::uint8_t>(m.switch_a);
    out[10] = static_cast<std::uint8_t>(m.switch_b);
    out[11] = static_cast<std::uint8_t>(m.switch_c);
    out[12] = static_cast<std::uint8_t>(m.switch_d);
    out[13] = static_cast<std::uint8_t>(m.ball_x);
    out[14] = static_cast<std::uint8_t>(m.ball_y);
    return true;
}
bool hw_decode(const std::uint8_t* p, std::size_t n, nb::maneuver& m) {
    if (n != 20 || p[0] != 0x55 || p[1] != 0xAA || p[2] != 0x10 || p[3] != 0) return false;
    const auto s8 = [&](int i) { return static_cast<std::int8_t>(p[i]); };
    if (!in(s8(5), -100, 100) || p[6] > 100 || !in(s8(7), -100, 100) || !in(s8(8), -100, 100) || p[9] > 2 ||
        p[10] > 1 || p[11] > 1 || p[12] > 2 || !in(s8(13), -5, 5) || !in(s8(14), -5, 5))
        return false;
    m = {s8(5), p[6], s8(7), s8(8), static_cast<nb::switch_a>(p[9]), static_cast<nb::switch_b>(p[10]),
         static_cast<nb::switch_c>(p[11]), static_cast<nb::switch_d>(p[12]), s8(13), s8(14)};
    return true;
}

void encode_robowire(benchmark::State& state) {
    const auto v = maneuvers();
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            alignas(64) auto r = robowire::encode(item);  // aligned like the baselines' buffers
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, v.size());
}
void encode_handwritten(benchmark::State& state) {
    const auto v = maneuvers();
    alignas(64) std::array<std::uint8_t, 20> out{};
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            bool ok = hw_encode(item, out.data());
            benchmark::DoNotOptimize(ok);
            benchmark::DoNotOptimize(out);
        }
    }
    bench::messages(state, v.size());
}
void decode_robowire(benchmark::State& state) {
    const auto v = maneuver_frames();
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            auto r = robowire::decode<nb::maneuver>(item);
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, v.size());
}
void decode_handwritten(benchmark::State& state) {
    const auto v = maneuver_frames();
    nb::maneuver m{};
    bench::in_memory(m);
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            bool ok = hw_decode(item.data(), 20, m);
            benchmark::DoNotOptimize(ok);
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, v.size());
}

// 200-byte JSON payloads (14 frames), a few different ones.
// Each in a 256-byte slot of one page-aligned block.
bench::vector<std::string_view> json_payloads() {
    static bench::vector<std::array<char, 256>> slots(8);
    bench::vector<std::string_view> v;
    for (std::size_t k = 0; k < slots.size(); ++k) {
        std::string s = R"({"type":"set_config","id":)" + std::to_string(k) + R"(,"data":")";
        while (s.size() < 198) s += static_cast<char>('a' + (s.size() + k) % 26);
        s += "\"}";
        std::copy(s.begin(), s.end(), slots[k].begin());
        v.emplace_back(slots[k].data(), s.size());
    }
    return v;
}
void json_robowire(benchmark::State& state) {
    const auto v = json_payloads();
    nb::reassembler<210> r;
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        const auto frames = nb::json_frames(v[i++ % v.size()]).value();
        for (const auto& f : frames) {
            auto st = r.push(f);
            benchmark::DoNotOptimize(st);
        }
        benchmark::DoNotOptimize(r.payload().data());
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 200);
}
void json_handwritten(benchmark::State& state) {
    const auto v = json_payloads();
    std::array<std::uint8_t, 210> buf{};
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        const std::string_view s = v[i++ % v.size()];
        const std::size_t frames = (s.size() + 14) / 15;
        std::size_t have = 0;
        int expect = -1;
        for (std::size_t k = 0; k < frames; ++k) {
            std::uint8_t f[20] = {0x55, 0xAA, 0x02, static_cast<std::uint8_t>(frames - 1 - k), 0};
            const std::size_t n = std::min<std::size_t>(15, s.size() - 15 * k);
            std::memcpy(f + 5, s.data() + 15 * k, n);
            std::memset(f + 5 + n, 0, 15 - n);
            benchmark::DoNotOptimize(f);
            // receiver
            if (f[0] != 0x55 || f[1] != 0xAA) continue;
            if (expect >= 0 && f[3] != expect - 1) { have = 0; expect = -1; continue; }
            if (have + 15 > buf.size()) { have = 0; expect = -1; continue; }
            std::memcpy(buf.data() + have, f + 5, 15);
            have += 15;
            expect = f[3];
            if (f[3] == 0) expect = -1;
        }
        benchmark::DoNotOptimize(buf);
        benchmark::DoNotOptimize(have);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 200);
}
}  // namespace

BENCHMARK(encode_robowire)->Name("navbot.maneuver_encode:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode_handwritten)->Name("navbot.maneuver_encode:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(decode_robowire)->Name("navbot.maneuver_decode:robowire")->Apply(bench::rounds<1>);
BENCHMARK(decode_handwritten)->Name("navbot.maneuver_decode:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(json_robowire)->Name("navbot.json200_fragment_reassemble:robowire")->Apply(bench::rounds<8>);
BENCHMARK(json_handwritten)->Name("navbot.json200_fragment_reassemble:handwritten")->Apply(bench::rounds<8>);
