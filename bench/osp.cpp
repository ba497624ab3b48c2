// OSP: per-message decode and dispatch; scanner throughput on clean streams,
// 30 % noise, pure noise and three hard streams (all FF, FF AA repeated,
// frames with one bad marker), fed in 1-byte, 64-byte and 4 KiB chunks.
// Baselines: hand-written decoders (the same checks in robowire's order, the
// same error report: bench::hw, an error code and its byte offset); for the
// scanner a careful hand-written one (memchr for the start byte in chunks of
// 64 and more, a byte-at-a-time state machine otherwise), that state machine
// alone (as MAVLink-style parsers work), and memchr for start bytes (floor).
#include <robowire/osp.hpp>

#include <bit>
#include <cstddef>
#include <span>

#include "common.hpp"
#include "handwritten/osp.hpp"

namespace {
namespace osp = robowire::osp;
using frame10 = std::array<std::uint8_t, 10>;

bench::vector<frame10> frames() {
    bench::rng r;
    bench::vector<frame10> v;
    const std::uint8_t keys[][2] = {{0, 0x11}, {1, 0x02}, {2, 0x11}, {2, 0x12}, {2, 0x13}, {2, 0x14}};
    for (std::size_t i = 0; i < bench::variants; ++i) {
        const auto& k = keys[i % 6];
        frame10 f{0xFF, 0xAA, k[0], k[1], r.byte(), r.byte(), 0, 0, 0x55, 0x77};
        if (k[1] == 0x11 && k[0] == 0) f[4] = static_cast<std::uint8_t>(1 + r.next() % 3);
        if (k[1] == 0x14) { f[4] = static_cast<std::uint8_t>(r.next() % 5); f[5] &= 0x0F; }
        v.push_back(f);
    }
    return v;
}
bench::vector<frame10> voltage_frames() {
    bench::rng r;
    bench::vector<frame10> v;
    for (std::size_t i = 0; i < bench::variants; ++i) v.push_back({0xFF, 0xAA, 2, 0x12, r.byte(), r.byte(), 0, 0, 0x55, 0x77});
    return v;
}


// With the length loaded per message from memory, as a UART driver hands a
// frame over ("_runtime_length" cases), or the constant 10.
template <bool RuntimeLength>
void voltage_rw(benchmark::State& state) {
    const auto v = voltage_frames();
    const bench::vector<std::size_t> len(v.size(), 10);
    const std::size_t count = v.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            const auto r = robowire::decode<osp::obp1::voltage>(std::span(v[i]).first(RuntimeLength ? len[i] : 10));
            bench::consume(r);
        }
    }
    bench::messages(state, v.size());
}
template <bool RuntimeLength>
void voltage_careful(benchmark::State& state) {
    const auto v = voltage_frames();
    const bench::vector<std::size_t> len(v.size(), 10);
    std::int16_t cv = 0;
    const std::size_t count = v.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            bench::consume(careful_voltage(v[i].data(), RuntimeLength ? len[i] : 10, cv));
            benchmark::DoNotOptimize(cv);
        }
    }
    bench::messages(state, v.size());
}
template <bool RuntimeLength>
void dispatch_rw(benchmark::State& state) {
    const auto v = frames();
    const bench::vector<std::size_t> len(v.size(), 10);
    const std::size_t count = v.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            auto r = osp::decode(std::span(v[i]).first(RuntimeLength ? len[i] : 10));
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, v.size());
}
template <bool RuntimeLength>
void dispatch_careful(benchmark::State& state) {
    const auto v = frames();
    const bench::vector<std::size_t> len(v.size(), 10);
    hw_msg m{};
    bench::in_memory(m);
    const std::size_t count = v.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            bench::consume(careful_decode_any(v[i].data(), RuntimeLength ? len[i] : 10, m));
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, v.size());
}

void voltage_robowire(benchmark::State& state) {
    const auto v = voltage_frames();
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            const auto r = robowire::decode<osp::obp1::voltage>(item);
            bench::consume(r);
        }
    }
    bench::messages(state, v.size());
}
void voltage_handwritten(benchmark::State& state) {
    const auto v = voltage_frames();
    std::int16_t cv = 0;
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            bench::consume(hw_voltage(item.data(), 10, cv));
            benchmark::DoNotOptimize(cv);
        }
    }
    bench::messages(state, v.size());
}
void dispatch_robowire(benchmark::State& state) {
    const auto v = frames();
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            auto r = osp::decode(item);
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, v.size());
}
void dispatch_handwritten(benchmark::State& state) {
    const auto v = frames();
    hw_msg m{};
    bench::in_memory(m);
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            bench::consume(hw_decode_any(item.data(), 10, m));
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, v.size());
}

// ---- streams (64 KiB)
constexpr std::size_t stream_size = 64 * 1024;
enum class kind { clean, noisy, noise, all_ff, ff_aa, near_miss };
bench::vector<std::uint8_t> stream(kind k) {
    bench::rng r;
    const auto fs = frames();
    bench::vector<std::uint8_t> s;
    s.reserve(stream_size + 16);
    std::size_t i = 0;
    if (k == kind::all_ff) s.assign(stream_size, 0xFF);
    if (k == kind::ff_aa)
        for (std::size_t j = 0; j < stream_size; ++j) s.push_back(j % 2 ? 0xAA : 0xFF);
    if (k == kind::near_miss)  // frames, each with one bad marker: AA, 55 or 77 in turn
        while (s.size() < stream_size) {
            auto f = fs[i % fs.size()];
            const std::size_t at = i % 3 == 0 ? 1 : i % 3 == 1 ? 8 : 9;
            f[at] = static_cast<std::uint8_t>(f[at] ^ 1);
            ++i;
            s.insert(s.end(), f.begin(), f.end());
        }
    while (s.size() < stream_size) {
        if (k == kind::noise || (k == kind::noisy && r.next() % 100 < 30 * 10 / 17)) {
            // noise bytes: 30 % of the stream overall (runs of 3 bytes, weighted for that share)
            for (int n = 0; n < 3; ++n) s.push_back(r.byte());
        } else {
            const auto& f = fs[i++ % fs.size()];
            s.insert(s.end(), f.begin(), f.end());
        }
    }
    s.resize(stream_size);
    return s;
}

void scan_robowire(benchmark::State& state, kind k) {
    const auto s = stream(k);
    const auto chunk = static_cast<std::size_t>(state.range(0));
    std::uint64_t found = 0, frames_seen = 0;
    for (auto _ : bench::measure(state)) {
        osp::scanner sc;
        for (std::size_t i = 0; i < s.size(); i += chunk)
            sc.feed(std::span(s.data() + i, std::min(chunk, s.size() - i)), [&](osp::scanner::frame_bytes f) {
                found += f[3];
            });
        benchmark::DoNotOptimize(found);
        frames_seen = sc.frames();
    }
    state.counters["frames"] = static_cast<double>(frames_seen);
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(s.size()));
}

// A careful byte-at-a-time parser with the scanner's semantics: every frame
// with the right markers is reported, also one that overlaps a failed
// candidate (after a mismatch it resumes at the next start byte of what it
// holds, which the usual state machine, restarting at the current byte,
// does not), and it counts frames, skipped bytes and false starts.
struct state_machine {
    std::uint8_t buf[19] = {};  // room for resync()'s fixed-size copies (from buf[9] at most)
    std::size_t n = 0;
    std::uint64_t frames = 0, skipped = 0, false_starts = 0;
    template <class F>
    void push(std::uint8_t b, F&& on_frame) {
        if (n == 0) {
            if (b == 0xFF) buf[n++] = b;
            else ++skipped;
            return;
        }
        buf[n++] = b;
        if (n == 10) {
            if (b == 0x77) {
                n = 0;
                ++frames;
                on_frame(buf);
            } else {
                resync();
            }
        } else if ((n == 2 && b != 0xAA) || (n == 9 && b != 0x55)) {
            resync();
        }
    }
    // Drops the first byte and everything up to the next start byte, until
    // what is left can still become a frame.
    void resync() {
        do {
            ++false_starts;
            std::size_t from = 1;
            while (from < n && buf[from] != 0xFF) ++from;
            skipped += from;
            if (from != n) {  // bytes left: one 8-byte and one 2-byte copy, both read first
                std::uint64_t lo;
                std::uint16_t hi;
                std::memcpy(&lo, buf + from, 8);
                std::memcpy(&hi, buf + from + 8, 2);
                std::memcpy(buf, &lo, 8);
                std::memcpy(buf + 8, &hi, 2);
            }
            n -= from;
        } while ((n >= 2 && buf[1] != 0xAA) || (n >= 9 && buf[8] != 0x55));
    }
};
// The careful hand-written scanner, with the same semantics: in chunks of 64
// bytes and more, memchr finds the start byte and a frame is checked and
// reported in place; the state machine takes short chunks, the bytes that
// decide a candidate held from the last chunk (at most 9), and the chunk's
// last 9 bytes (whose frames would end past it).
struct careful_scanner {
    state_machine sm;
    template <class F>
    void feed(const std::uint8_t* p, std::size_t n, F&& on_frame) {
        if (n == 1) return sm.push(p[0], on_frame);
        if (n < 64) {
            for (std::size_t k = 0; k < n; ++k) sm.push(p[k], on_frame);
            return;
        }
        std::size_t i = 0;
        if (sm.n != 0) {  // every candidate that starts in the held bytes ends within the next 9
            for (; i < 9; ++i) sm.push(p[i], on_frame);
            i -= sm.n;  // a candidate still held starts in this chunk: scan it in place
            sm.n = 0;
        }
        const std::size_t last = n - 9;  // a window from here on ends past the chunk
        while (i < last) {
            const auto* h = static_cast<const std::uint8_t*>(std::memchr(p + i, 0xFF, last - i));
            if (!h) {
                sm.skipped += last - i;
                i = last;
                break;
            }
            const auto at = static_cast<std::size_t>(h - p);
            sm.skipped += at - i;
            i = at;
            if (p[i + 1] == 0xAA && p[i + 8] == 0x55 && p[i + 9] == 0x77) {
                ++sm.frames;
                on_frame(p + i);
                i += 10;
            } else {
                ++sm.false_starts;
                ++sm.skipped;
                ++i;
            }
        }
        for (; i < n; ++i) sm.push(p[i], on_frame);
    }
};
void scan_careful(benchmark::State& state, kind k) {
    const auto s = stream(k);
    const auto chunk = static_cast<std::size_t>(state.range(0));
    std::uint64_t found = 0, frames_seen = 0;
    for (auto _ : bench::measure(state)) {
        careful_scanner sc;
        for (std::size_t i = 0; i < s.size(); i += chunk)
            sc.feed(s.data() + i, std::min(chunk, s.size() - i), [&](const std::uint8_t* f) { found += f[3]; });
        benchmark::DoNotOptimize(found);
        frames_seen = sc.sm.frames;
    }
    state.counters["frames"] = static_cast<double>(frames_seen);
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(s.size()));
}
void scan_state_machine(benchmark::State& state, kind k) {
    const auto s = stream(k);
    const auto chunk = static_cast<std::size_t>(state.range(0));
    std::uint64_t found = 0, frames_seen = 0;
    for (auto _ : bench::measure(state)) {
        state_machine sm;
        for (std::size_t i = 0; i < s.size(); i += chunk) {
            const std::size_t end = std::min(i + chunk, s.size());
            for (std::size_t j = i; j < end; ++j) sm.push(s[j], [&](const std::uint8_t* f) { found += f[3]; });
        }
        benchmark::DoNotOptimize(found);
        frames_seen = sm.frames;
    }
    state.counters["frames"] = static_cast<double>(frames_seen);
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(s.size()));
}
void scan_memchr(benchmark::State& state, kind k) {
    const auto s = stream(k);
    const auto chunk = static_cast<std::size_t>(state.range(0));
    for (auto _ : bench::measure(state)) {
        std::size_t starts = 0;
        for (std::size_t i = 0; i < s.size(); i += chunk) {
            const std::uint8_t* p = s.data() + i;
            const std::uint8_t* end = s.data() + std::min(i + chunk, s.size());
            while ((p = static_cast<const std::uint8_t*>(std::memchr(p, 0xFF, static_cast<std::size_t>(end - p))))) {
                ++starts;
                ++p;
            }
        }
        benchmark::DoNotOptimize(starts);
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(s.size()));
}
}  // namespace

BENCHMARK(voltage_careful<false>)->Name("osp.decode_voltage:careful")->Apply(bench::rounds<1>);
BENCHMARK(voltage_rw<true>)->Name("osp.decode_voltage_runtime_length:robowire")->Apply(bench::rounds<1>);
BENCHMARK(voltage_careful<true>)->Name("osp.decode_voltage_runtime_length:careful")->Apply(bench::rounds<1>);
BENCHMARK(dispatch_careful<false>)->Name("osp.decode_dispatch:careful")->Apply(bench::rounds<1>);
BENCHMARK(dispatch_rw<true>)->Name("osp.decode_dispatch_runtime_length:robowire")->Apply(bench::rounds<1>);
BENCHMARK(dispatch_careful<true>)->Name("osp.decode_dispatch_runtime_length:careful")->Apply(bench::rounds<1>);
BENCHMARK(voltage_robowire)->Name("osp.decode_voltage:robowire")->Apply(bench::rounds<1>);
BENCHMARK(voltage_handwritten)->Name("osp.decode_voltage:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(dispatch_robowire)->Name("osp.decode_dispatch:robowire")->Apply(bench::rounds<1>);
BENCHMARK(dispatch_handwritten)->Name("osp.decode_dispatch:handwritten")->Apply(bench::rounds<1>);
#define ROBOWIRE_SCAN(K)                                                                                    \
    BENCHMARK_CAPTURE(scan_robowire, K, kind::K)->Name("osp.scan_" #K ":robowire")->Arg(1)->Arg(64)->Arg(4096)->Apply(bench::rounds<1>); \
    BENCHMARK_CAPTURE(scan_careful, K, kind::K)->Name("osp.scan_" #K ":handwritten")->Arg(1)->Arg(64)->Arg(4096)->Apply(bench::rounds<1>); \
    BENCHMARK_CAPTURE(scan_state_machine, K, kind::K)->Name("osp.scan_" #K ":bytewise")->Arg(1)->Arg(64)->Arg(4096)->Apply(bench::rounds<1>); \
    BENCHMARK_CAPTURE(scan_memchr, K, kind::K)->Name("osp.scan_" #K ":memchr")->Arg(1)->Arg(64)->Arg(4096)->Apply(bench::rounds<1>);
ROBOWIRE_SCAN(clean)
ROBOWIRE_SCAN(noisy)
ROBOWIRE_SCAN(noise)
ROBOWIRE_SCAN(all_ff)
ROBOWIRE_SCAN(ff_aa)
ROBOWIRE_SCAN(near_miss)
