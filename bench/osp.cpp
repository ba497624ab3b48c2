// OSP: per-message decode and dispatch; scanner throughput on clean streams,
// 30 % noise, pure noise and three hard streams (all FF, FF AA repeated,
// frames with one bad marker), fed in 1-byte, 64-byte and 4 KiB chunks.
// Baselines: hand-written decoders (the same checks in robowire's order, the
// same error report: bench::hw, an error code and its byte offset); for the
// scanner a careful hand-written one (SSE2 masks of start bytes and frames in
// chunks of 10 and more, a byte-at-a-time state machine otherwise), that state
// machine alone (as MAVLink-style parsers work), and memchr for start bytes
// (floor).
#include <robowire/osp.hpp>

#include <emmintrin.h>

#include <bit>
#include <cstddef>
#include <span>
#include <type_traits>

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
// The careful hand-written scanner, with the same semantics. Chunks of 10
// bytes and more: a held candidate is decided at once with the chunk's first
// 9 bytes; SSE2 masks of the start bytes (and, where a start byte is no
// frame, of whole frames) cover 64 or 16 positions a step; frames back to
// back are checked one by one (two 16-bit compares); the candidate to hold
// in the last 9 positions is found from masks and copied whole. The
// counters are up to date in on_frame. Short chunks: the state machine.
struct careful_scanner {
    state_machine sm;
    template <class F>
    void feed(const std::uint8_t* p, std::size_t n, F&& on_frame) {
        if (n == 1) return sm.push(p[0], on_frame);
        if (n < 10) {
            for (std::size_t k = 0; k < n; ++k) sm.push(p[k], on_frame);
            return;
        }
        if constexpr (!std::is_lvalue_reference_v<F> && std::is_trivially_copyable_v<F>) {
            F local = on_frame;  // a temporary's copy: the caller's loop keeps none in memory for the byte path
            chunk(p, n, local);
        } else {
            chunk(p, n, on_frame);
        }
    }

private:
    using v16 = __m128i;
    static v16 ld(const std::uint8_t* p) { return _mm_loadu_si128(reinterpret_cast<const v16*>(p)); }
    static std::uint16_t ld2(const std::uint8_t* p) { std::uint16_t v; std::memcpy(&v, p, 2); return v; }
    static bool frame_at(const std::uint8_t* w) { return ld2(w) == 0xAAFF && ld2(w + 8) == 0x7755; }
    static std::uint64_t mask(v16 v) { return static_cast<std::uint32_t>(_mm_movemask_epi8(v)); }
    static std::uint64_t starts16(const std::uint8_t* p) { return mask(_mm_cmpeq_epi8(ld(p), _mm_set1_epi8(-1))); }
    static std::uint64_t frames16(const std::uint8_t* p) {  // bit k: a frame at p + k (reads p[0, 25))
        const v16 a = _mm_and_si128(_mm_cmpeq_epi8(ld(p), _mm_set1_epi8(-1)),
                                    _mm_cmpeq_epi8(ld(p + 1), _mm_set1_epi8(static_cast<char>(0xAA))));
        const v16 b = _mm_and_si128(_mm_cmpeq_epi8(ld(p + 8), _mm_set1_epi8(0x55)),
                                    _mm_cmpeq_epi8(ld(p + 9), _mm_set1_epi8(0x77)));
        return mask(_mm_and_si128(a, b));
    }
    static std::uint64_t starts64(const std::uint8_t* p) {
        const v16 a = ld(p), b = ld(p + 16), c = ld(p + 32), d = ld(p + 48), ff = _mm_set1_epi8(-1);
        // FF is the largest byte: none in the 64 if none in their maximum
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_max_epu8(_mm_max_epu8(a, b), _mm_max_epu8(c, d)), ff)) == 0) return 0;
        return mask(_mm_cmpeq_epi8(a, ff)) | mask(_mm_cmpeq_epi8(b, ff)) << 16 | mask(_mm_cmpeq_epi8(c, ff)) << 32 |
               mask(_mm_cmpeq_epi8(d, ff)) << 48;
    }
    static bool any_start(const std::uint8_t* p, std::size_t i, std::size_t n) {  // in p[i, n): n - i in [16, 64]
        const std::size_t e = n - 16;
        const v16 m = _mm_max_epu8(_mm_max_epu8(ld(p + i), ld(p + std::min(i + 16, e))),
                                   _mm_max_epu8(ld(p + std::min(i + 32, e)), ld(p + e)));
        return _mm_movemask_epi8(_mm_cmpeq_epi8(m, _mm_set1_epi8(-1))) != 0;
    }
    static std::uint64_t frames64(const std::uint8_t* p) {
        return frames16(p) | frames16(p + 16) << 16 | frames16(p + 32) << 32 | frames16(p + 48) << 48;
    }
    static std::uint64_t popcount(std::uint64_t x) {  // no POPCNT in baseline x86-64
        x -= (x >> 1) & 0x5555555555555555u;
        x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
        x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Fu;
        return (x * 0x0101010101010101u) >> 56;
    }
    static constexpr auto bits9 = [] {  // bits set in each 9-bit value
        std::array<std::uint8_t, 512> t{};
        for (std::size_t v = 1; v < 512; ++v) t[v] = static_cast<std::uint8_t>(t[v & (v - 1)] + 1);
        return t;
    }();
    static std::size_t first(std::uint64_t m) { return static_cast<std::size_t>(__builtin_ctzll(m)); }

    // Positions [i, last) of a chunk of n bytes; from the start byte at p[i]
    // on, frames back to back. Returns the position to go on from.
    template <class F>
    std::size_t frames_from(const std::uint8_t* p, std::size_t i, std::size_t last, std::size_t& mark, F& on_frame) {
        sm.skipped += i - mark;
        do {
            ++sm.frames;
            on_frame(p + i);
            i += 10;
        } while (i < last && frame_at(p + i));
        mark = i;
        return i;
    }
    // The start bytes s of positions [base, base + W) (none before i): the
    // first frame there is reported with those after it; start bytes before
    // it are false starts. Returns the position to go on from.
    template <std::size_t W, class F>
    std::size_t block(const std::uint8_t* p, std::size_t base, std::uint64_t s, std::size_t last, std::size_t& mark,
                      F& on_frame) {
        if (s == 0) return base + W;
        std::size_t k = first(s);
        if (!frame_at(p + base + k)) {
            if ((s & (s - 1)) == 0) {  // a lone false start
                ++sm.false_starts;
                return base + W;
            }
            const std::uint64_t f = (W == 64 ? frames64(p + base) : frames16(p + base)) & s;
            if (f == 0) {
                sm.false_starts += popcount(s);
                return base + W;
            }
            k = first(f);
            sm.false_starts += popcount(s & ((std::uint64_t{1} << k) - 1));
        }
        return frames_from(p, base + k, last, mark, on_frame);
    }
    template <class F>
    [[gnu::noinline]] void chunk(const std::uint8_t* p, std::size_t n, F& on_frame) {
        std::size_t i = sm.n != 0 ? finish_held(p, on_frame) : 0;
        std::size_t mark = i;  // bytes from mark up to the next frame or held candidate are skipped
        const std::size_t last = n - 9;  // a window starting here or later ends past the chunk
        if (i < last && frame_at(p + i)) i = frames_from(p, i, last, mark, on_frame);  // often after a held one
        while (i + 64 <= last) i = block<64>(p, i, starts64(p + i), last, mark, on_frame);
        if (i + 32 <= last && i + 64 >= n && starts16(p + i) == 0) {  // none in the next 16: any left?
            i += 16;
            if (!any_start(p, i, n)) {
                sm.skipped += n - mark;
                return;
            }
        }
        while (i < last) {
            if (i + 16 <= last) {
                i = block<16>(p, i, starts16(p + i), last, mark, on_frame);
            } else if (n >= 25) {  // the 16 positions that end at last, those before i dropped
                const std::size_t base = last - 16;
                i = block<16>(p, base, starts16(p + base) >> (i - base) << (i - base), last, mark, on_frame);
            } else if (p[i] != 0xFF) {
                ++i;
            } else if (frame_at(p + i)) {
                i = frames_from(p, i, last, mark, on_frame);
            } else {
                ++sm.false_starts;
                ++i;
            }
        }
        // The last 9 positions (and those of a frame that ends in them): the
        // first candidate that can still become a frame is held.
        const auto partial_ok = [&](std::size_t at) {
            const std::size_t m = n - at;
            return (m < 2 || p[at + 1] == 0xAA) && (m < 9 || p[at + 8] == 0x55);
        };
        if (i < n && p[i] == 0xFF && partial_ok(i)) {  // as after frames back to back
            hold(p + i, n - i);
            sm.skipped += i - mark;
            return;
        }
        if (i < n && n >= 16) {  // from masks of the last 16 bytes: start bytes, and those followed by ST2
            const std::size_t base = n - 16, from = i - base;  // from: 7 or more
            const v16 v = ld(p + base);
            const std::uint64_t s = mask(_mm_cmpeq_epi8(v, _mm_set1_epi8(-1))) >> from;  // 9 bits at most
            if (s != 0 && partial_ok(i + first(s))) {  // the first start byte there
                const std::size_t at = i + first(s);
                hold(p + at, n - at);
                sm.skipped += at - mark;
                return;
            }
            if (s != 0) {  // more than one
                std::uint64_t ok = s & (mask(_mm_cmpeq_epi8(v, _mm_set1_epi8(static_cast<char>(0xAA)))) >> (from + 1) |
                                        std::uint64_t{1} << (15 - from));
                if (p[n - 1] != 0x55) ok &= ~(std::uint64_t{1} << 7 >> from);  // at last, EN1 is there too
                if (ok != 0) {
                    const std::size_t k = first(ok);
                    sm.false_starts += bits9[s & ((std::uint64_t{1} << k) - 1)];
                    hold(p + i + k, n - i - k);
                    sm.skipped += i + k - mark;
                    return;
                }
                sm.false_starts += bits9[s];
            }
        } else if (i < n) {
            std::uint64_t s = 0;
            for (std::size_t k = i; k < n; ++k) s |= std::uint64_t{p[k] == 0xFF} << (k - i);
            for (; s != 0; s &= s - 1) {
                const std::size_t at = i + first(s);
                if (partial_ok(at)) {
                    hold(p + at, n - at);
                    sm.skipped += at - mark;
                    return;
                }
                ++sm.false_starts;
            }
        }
        sm.skipped += n - mark;
    }
    // m (1..9) bytes into the held buffer: two overlapping fixed-size copies.
    void hold(const std::uint8_t* q, std::size_t m) {
        sm.n = m;
        if (m >= 8) {
            std::uint64_t a, b;
            std::memcpy(&a, q, 8);
            std::memcpy(&b, q + m - 8, 8);
            std::memcpy(sm.buf, &a, 8);
            std::memcpy(sm.buf + m - 8, &b, 8);
        } else if (m >= 4) {
            std::uint32_t a, b;
            std::memcpy(&a, q, 4);
            std::memcpy(&b, q + m - 4, 4);
            std::memcpy(sm.buf, &a, 4);
            std::memcpy(sm.buf + m - 4, &b, 4);
        } else {
            sm.buf[0] = q[0];
            sm.buf[m / 2] = q[m / 2];
            sm.buf[m - 1] = q[m - 1];
        }
    }
    // The held candidate and the chunk's first 9 bytes, which complete every
    // window that starts in the held bytes: reports the first frame there or
    // drops the held bytes. Returns the position in the chunk to go on from.
    template <class F>
    std::size_t finish_held(const std::uint8_t* p, F& on_frame) {
        const std::size_t held = sm.n;
        std::uint8_t c[19 + 8];
        std::uint64_t a, b;
        std::uint16_t h;
        std::memcpy(&a, sm.buf, 8);
        std::memcpy(&h, sm.buf + 8, 2);
        std::memcpy(&b, p, 8);
        std::memcpy(c, &a, 8);
        std::memcpy(c + 8, &h, 2);
        std::memcpy(c + held, &b, 8);
        c[held + 8] = p[8];
        sm.n = 0;
        for (std::size_t q = 0; q < held; ++q) {
            if (c[q] != 0xFF) continue;
            if (frame_at(c + q)) {
                sm.skipped += q;
                ++sm.frames;
                on_frame(static_cast<const std::uint8_t*>(c + q));
                return q + 10 - held;
            }
            ++sm.false_starts;
        }
        sm.skipped += held;
        return 0;
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
