// NAVBOT: maneuver encode/decode; fragment + reassemble a 200-byte JSON payload.
// Baseline: the hand-written code a careful user would write, with the same
// checks in robowire's order and the same error report (bench::hw: an error
// code and its byte offset); the encoder checks every field before it writes.
#include <robowire/navbot.hpp>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <span>
#include <cstdlib>
#include <cstring>
#include <string>

#include "common.hpp"
#include "handwritten/navbot.hpp"

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
void encode_careful(benchmark::State& state) {
    const auto v = maneuvers();
    alignas(64) std::array<std::uint8_t, 20> out{};
    for (auto _ : bench::measure(state)) {
        for (const auto& item : v) {
            bench::consume(careful_encode(item, out.data()));
            benchmark::DoNotOptimize(out);
        }
    }
    bench::messages(state, v.size());
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
            bench::consume(hw_encode(item, out.data()));
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
            bench::consume(hw_decode(item.data(), 20, m));
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
template <bool RuntimeLength>
void decode_rw(benchmark::State& state) {
    const auto v = maneuver_frames();
    const bench::vector<std::size_t> len(v.size(), 20);
    const std::size_t count = v.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            auto r = robowire::decode<nb::maneuver>(std::span(v[i]).first(RuntimeLength ? len[i] : 20));
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, v.size());
}
template <bool RuntimeLength>
void decode_careful(benchmark::State& state) {
    const auto v = maneuver_frames();
    const bench::vector<std::size_t> len(v.size(), 20);
    nb::maneuver m{};
    bench::in_memory(m);
    const std::size_t count = v.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            bench::consume(careful_decode(v[i].data(), RuntimeLength ? len[i] : 20, m));
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, v.size());
}
void json_robowire(benchmark::State& state) {
    const auto v = json_payloads();
    nb::reassembler<210> r;
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        const auto frames = nb::json_frames(v[i++ % v.size()]).value();
        for (auto f : frames) {
            bench::received(f);
            auto st = r.push(f);
            bench::consume(st);
        }
        benchmark::DoNotOptimize(r.payload().data());
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 200);
}
// The hand-written receiver: the same rules as robowire's reassembler (and as
// firmware/hw_navbot.cpp, which tests/navbot/baseline.cpp checks against it):
// the frame's length and header are checked, a repeat of the last frame of a
// multi-frame message is ignored, a one-frame message of another command
// passes through, a sender starting over restarts the message, and after an
// error the rest of the broken message is discarded.
enum outcome : std::uint8_t { need_more, complete, single, duplicate, restarted, discarded };
enum hw_err : std::uint8_t { ok = 0, too_short = 1, too_long = 2, bad_header = 4, capacity_exceeded = 15,
                             bad_sequence = 16, command_changed = 17 };
struct pushed {  // an error code and the byte it is about, or the outcome
    hw_err error;
    std::uint8_t at;
    outcome what;
};
constexpr pushed done(outcome o) { return {ok, 0, o}; }
// Reads what push() said as bench::consume reads robowire's result: the
// outcome, or the error and its byte.
void consume(const pushed& p) {
    if (p.error == ok) {
        const outcome what = p.what;
        benchmark::DoNotOptimize(what);
    } else {
        const auto e = static_cast<std::uint16_t>(p.error | p.at << 8);
        benchmark::DoNotOptimize(e);
    }
}
using bench::consume;
constexpr pushed fail(hw_err e, std::size_t at) { return {e, static_cast<std::uint8_t>(at), need_more}; }
struct hw_frame {
    std::uint8_t command, remaining;
    std::uint8_t payload[15];
};
// Careful: the frame's length and header as one test, the exact error in a
// cold function (robowire's order: the header bytes present, then the length).
inline std::uint16_t load16(const std::uint8_t* p) {
    std::uint16_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
[[gnu::cold, gnu::noinline]] pushed frame_error(const std::uint8_t* p, std::size_t n) {
    if (n > 0 && p[0] != 0x55) return fail(bad_header, 0);
    if (n > 1 && p[1] != 0xAA) return fail(bad_header, 1);
    return fail(n < 20 ? too_short : too_long, n < 20 ? n : 20);
}
template <std::size_t Capacity, bool Careful = false>
struct hw_reassembler {
    std::uint8_t buf[Capacity];
    std::size_t size;
    std::uint8_t command, last_remaining;
    std::uint8_t state;  // 0 idle, 1 collecting, 2 complete
    bool has_last, skipping;
    std::uint8_t skip_command;
    hw_frame last;
    void remember(const hw_frame& f) { has_last = true; last = f; }
    void skip(std::uint8_t c) { skipping = true; skip_command = c; }
    pushed append(const hw_frame& f) {
        std::memcpy(buf + size, f.payload, 15);
        size += 15;
        if (f.remaining != 0 || size > 15) remember(f);
        last_remaining = f.remaining;
        state = f.remaining == 0 ? 2 : 1;
        return done(f.remaining == 0 ? complete : need_more);
    }
    pushed start(const hw_frame& f) {
        state = 0;
        size = 0;
        command = f.command;
        if (f.remaining + 1u > Capacity / 15) {
            has_last = false;
            if (f.remaining != 0) { remember(f); skip(f.command); }
            return fail(capacity_exceeded, 3);
        }
        return append(f);
    }
    pushed push(const std::uint8_t* p, std::size_t n) {
        if constexpr (Careful) {
            if (n != 20 || load16(p) != (std::endian::native == std::endian::little ? 0xAA55 : 0x55AA)) [[unlikely]]
                return frame_error(p, n);
            // The next frame of the message being collected, read in place. While
            // collecting, a message being discarded has another command (skip()
            // follows a start of another command, or leaves the state idle), so
            // the discard test cannot hit here; and the last frame remembered is
            // either the last one appended (remaining == last_remaining, not
            // rem) or one of the discarded command: never a repeat of this one.
            // Command and remaining against command and last_remaining - 1 as one word.
            const std::uint8_t c = p[2], rem = p[3];
            const int key = std::endian::native == std::endian::little ? load16(p + 2) : (c | rem << 8);
            if (state == 1 && key + 0x100 == (command | last_remaining << 8)) [[likely]] {
                std::uint64_t lo, hi;  // the payload, loaded once: bytes 0..7 and 7..14
                std::memcpy(&lo, p + 5, 8);
                std::memcpy(&hi, p + 12, 8);
                const std::size_t at = size;
                std::memcpy(buf + at, &lo, 8);
                std::memcpy(buf + at + 7, &hi, 8);
                size = at + 15;
                // has_last: already true while collecting (the frame that set state 1 was remembered)
                last.command = c;
                last.remaining = rem;
                std::memcpy(last.payload, &lo, 8);
                std::memcpy(last.payload + 7, &hi, 8);
                last_remaining = rem;
                state = rem == 0 ? 2 : 1;
                return done(rem == 0 ? complete : need_more);
            }
        } else {
            if (n > 0 && p[0] != 0x55) return fail(bad_header, 0);  // robowire's order: the header bytes
            if (n > 1 && p[1] != 0xAA) return fail(bad_header, 1);  // that are there, then the length
            if (n < 20) return fail(too_short, n);
            if (n > 20) return fail(too_long, 20);
        }
        hw_frame f;
        f.command = p[2];
        f.remaining = p[3];
        std::memcpy(f.payload, p + 5, 15);
        if (has_last && std::memcmp(&f, &last, sizeof f) == 0) return done(duplicate);
        if (state == 2) { state = 0; size = 0; }
        if (skipping && f.command == skip_command) {
            if (f.remaining == 0) skipping = false;
            remember(f);
            return done(discarded);
        }
        if (state == 0) return start(f);
        if (f.command != command) {
            if (f.remaining == 0) return done(single);
            const std::uint8_t broken = command;
            if (auto e = start(f); e.error) return e;
            skip(broken);
            return fail(command_changed, 2);
        }
        if (f.remaining >= last_remaining) {
            if (auto e = start(f); e.error) return e;
            return done(restarted);
        }
        if (f.remaining + 1 != last_remaining) {  // frames lost
            state = 0;
            size = 0;
            remember(f);
            if (f.remaining != 0) skip(f.command);
            return fail(bad_sequence, 3);
        }
        return append(f);
    }
};
void json_handwritten(benchmark::State& state) {
    const auto v = json_payloads();
    hw_reassembler<210> r{};
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        // sender: the frames of one JSON message (at most 256)
        const std::string_view s = v[i++ % v.size()];
        const std::size_t frames = s.empty() ? 1 : (s.size() + 14) / 15;
        if (frames > 256) std::abort();
        for (std::size_t k = 0; k < frames; ++k) {
            std::uint8_t f[20] = {0x55, 0xAA, 0x02, static_cast<std::uint8_t>(frames - 1 - k), 0};
            const std::size_t n = std::min<std::size_t>(15, s.size() - 15 * k);
            std::memcpy(f + 5, s.data() + 15 * k, n);
            std::memset(f + 5 + n, 0, 15 - n);
            // receiver
            std::size_t size = sizeof f;  // with the length, as a BLE stack hands a write over
            bench::received(f);
            bench::received(size);
            auto st = r.push(f, size);
            consume(st);
        }
        benchmark::DoNotOptimize(r.buf);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 200);
}
// The last frame's n < 15 payload bytes as two overlapping fixed-size
// copies (no call of a run-time size), as robowire's fragmenter copies them.
inline void copy_tail(std::uint8_t* to, const char* from, std::size_t n) {
    const auto pair = [&](auto width) {
        constexpr std::size_t w = decltype(width)::value;
        std::memcpy(to, from, w);
        std::memcpy(to + n - w, from + n - w, w);
    };
    if (n >= 8) pair(std::integral_constant<std::size_t, 8>{});
    else if (n >= 4) pair(std::integral_constant<std::size_t, 4>{});
    else if (n >= 2) pair(std::integral_constant<std::size_t, 2>{});
    else if (n == 1) to[0] = static_cast<std::uint8_t>(from[0]);
}
// A frame with its length beside it (as robowire's bytes<20> holds its size).
struct sized_frame {
    std::uint8_t size;
    std::uint8_t f[20];
};
static_assert(sizeof(sized_frame) == 21);
// The careful sender: the whole frames in one loop, each as the size and
// header in one word from a register (55 AA 02 remaining 00; remaining counts
// down in its byte) and the payload copied with a constant size; then the
// last frame's n <= 15 bytes with copy_tail after zeros; put(frame) for each
// (at most 256).
template <class Put>
inline void careful_frames(std::string_view s, Put&& put) {
    const std::size_t frames = s.empty() ? 1 : (s.size() + 14) / 15;
    if (frames > 256) std::abort();
    const char* from = s.data();
    const char* const last = from + 15 * (frames - 1);
    constexpr std::uint64_t one = std::uint64_t{1} << 32;  // remaining: byte 4 of the word
    std::uint64_t head = 0x02AA5514u + (frames - 1) * one;  // 20, then 55 AA 02 remaining 00
    sized_frame w;
    for (; from != last; from += 15) {
        std::memcpy(&w, &head, 8);  // its last two bytes are the payload's, written next
        std::memcpy(w.f + 5, from, 15);
        head -= one;
        put(w);
    }
    std::memcpy(&w, &head, 8);
    std::memset(w.f + 5, 0, 15);
    copy_tail(w.f + 5, from, s.size() - 15 * (frames - 1));
    put(w);
}
void json_careful(benchmark::State& state) {
    const auto v = json_payloads();
    hw_reassembler<210, true> r{};
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        careful_frames(v[i++ % v.size()], [&](sized_frame& w) __attribute__((always_inline)) {  // two call sites
            bench::received(w);  // with the length, as a BLE stack hands a write over
            auto st = r.push(w.f, w.size);
            consume(st);
        });
        benchmark::DoNotOptimize(r.buf);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 200);
}
}  // namespace

BENCHMARK(encode_robowire)->Name("navbot.maneuver_encode:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode_handwritten)->Name("navbot.maneuver_encode:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(encode_careful)->Name("navbot.maneuver_encode:careful")->Apply(bench::rounds<1>);
BENCHMARK(decode_careful<false>)->Name("navbot.maneuver_decode:careful")->Apply(bench::rounds<1>);
BENCHMARK(decode_rw<true>)->Name("navbot.maneuver_decode_runtime_length:robowire")->Apply(bench::rounds<1>);
BENCHMARK(decode_careful<true>)->Name("navbot.maneuver_decode_runtime_length:careful")->Apply(bench::rounds<1>);
BENCHMARK(decode_robowire)->Name("navbot.maneuver_decode:robowire")->Apply(bench::rounds<1>);
BENCHMARK(decode_handwritten)->Name("navbot.maneuver_decode:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(json_robowire)->Name("navbot.json200_fragment_reassemble:robowire")->Apply(bench::rounds<8>);
BENCHMARK(json_careful)->Name("navbot.json200_fragment_reassemble:careful")->Apply(bench::rounds<8>);
BENCHMARK(json_handwritten)->Name("navbot.json200_fragment_reassemble:handwritten")->Apply(bench::rounds<8>);
