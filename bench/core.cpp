// Core primitives: little-endian loads vs memcpy, hex formatting vs a plain
// loop (which, as robowire::to_hex, checks that the text fits the caller's
// buffer: bench::hw's buffer_too_small at the size it needs).
#include <robowire/core.hpp>

#include <bit>

#include "common.hpp"

namespace {
bench::vector<std::uint8_t> random_bytes(std::size_t n) {
    bench::rng r;
    bench::vector<std::uint8_t> v(n);
    for (auto& b : v) b = r.byte();
    return v;
}

void load_u32_robowire(benchmark::State& state) {
    const auto buf = random_bytes(4096 + 4);
    std::size_t i = 0;
    std::uint32_t sum = 0;
    for (auto _ : bench::measure(state)) {
        sum += robowire::load_le<std::uint32_t>(buf.data() + (i++ & 4095));
        benchmark::DoNotOptimize(sum);
    }
}
void load_u32_memcpy(benchmark::State& state) {
    const auto buf = random_bytes(4096 + 4);
    std::size_t i = 0;
    std::uint32_t sum = 0;
    for (auto _ : bench::measure(state)) {
        std::uint32_t v;
        std::memcpy(&v, buf.data() + (i++ & 4095), 4);  // little-endian host
        sum += v;
        benchmark::DoNotOptimize(sum);
    }
}
void load_f32_robowire(benchmark::State& state) {
    const auto buf = random_bytes(4096 + 4);
    std::size_t i = 0;
    float sum = 0;
    for (auto _ : bench::measure(state)) {
        sum += robowire::load_le<float>(buf.data() + (i++ & 4095));
        benchmark::DoNotOptimize(sum);
    }
}
void load_f32_memcpy(benchmark::State& state) {
    const auto buf = random_bytes(4096 + 4);
    std::size_t i = 0;
    float sum = 0;
    for (auto _ : bench::measure(state)) {
        float v;
        std::memcpy(&v, buf.data() + (i++ & 4095), 4);
        sum += v;
        benchmark::DoNotOptimize(sum);
    }
}
void hex_robowire(benchmark::State& state) {
    const auto buf = random_bytes(68 * bench::variants);
    std::array<char, 3 * 68> out{};
    bench::in_memory(out);
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        bench::consume(robowire::to_hex(std::span(buf).subspan(68 * (i++ % bench::variants), 68), out));
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 68);
}
// Upper-case hex with a space between bytes; the size check of robowire::to_hex.
bench::hw::error hw_to_hex(const std::uint8_t* p, std::size_t n, char* out, std::size_t size) {
    static const char digits[] = "0123456789ABCDEF";
    const std::size_t need = n ? 3 * n - 1 : 0;
    if (need > size) return bench::hw::fail(bench::hw::buffer_too_small, need);
    for (std::size_t k = 0; k < n; ++k) {
        if (k) *out++ = ' ';
        *out++ = digits[p[k] >> 4];
        *out++ = digits[p[k] & 15];
    }
    return bench::hw::good;
}
// The careful version: the size check first, its error cold; a 256-entry
// table of the two digits and a space as 32-bit words, one overlapping
// 4-byte store per byte (eight bytes a step), the last byte's digits as a
// 2-byte store.
constexpr auto hex_quads = [] {
    std::array<std::uint32_t, 256> t{};
    constexpr char digits[] = "0123456789ABCDEF";
    for (std::uint32_t i = 0; i < 256; ++i)
        t[i] = static_cast<std::uint8_t>(digits[i >> 4]) | static_cast<std::uint32_t>(digits[i & 15]) << 8 |
               std::uint32_t{' '} << 16 | std::uint32_t{' '} << 24;
    return t;
}();
static_assert(std::endian::native == std::endian::little, "hex_quads holds the digits in memory order");
[[gnu::cold, gnu::noinline]] bench::hw::error careful_hex_error(std::size_t need) {
    return bench::hw::fail(bench::hw::buffer_too_small, need);
}
inline bench::hw::error careful_to_hex(const std::uint8_t* p, std::size_t n, char* out, std::size_t size) {
    const std::size_t need = n ? 3 * n - 1 : 0;
    if (need > size) [[unlikely]] return bench::hw::never_good(careful_hex_error(need));
    if (n == 0) return bench::hw::good;
    const auto put = [](char* o, std::uint8_t b) { std::memcpy(o, &hex_quads[b], 4); };
    std::size_t k = (n - 1) / 8;  // the bytes before the last have a space after them: 8 a step
    for (; k != 0; --k, p += 8, out += 24) {
        put(out, p[0]);
        put(out + 3, p[1]);
        put(out + 6, p[2]);
        put(out + 9, p[3]);
        put(out + 12, p[4]);
        put(out + 15, p[5]);
        put(out + 18, p[6]);
        put(out + 21, p[7]);
    }
    for (k = (n - 1) % 8; k != 0; --k, ++p, out += 3) put(out, *p);
    std::memcpy(out, &hex_quads[*p], 2);
    return bench::hw::good;
}
void hex_careful(benchmark::State& state) {
    const auto buf = random_bytes(68 * bench::variants);
    std::array<char, 3 * 68> out{};
    bench::in_memory(out);
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        bench::consume(careful_to_hex(buf.data() + 68 * (i++ % bench::variants), 68, out.data(), out.size()));
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 68);
}
void hex_handwritten(benchmark::State& state) {
    const auto buf = random_bytes(68 * bench::variants);
    std::array<char, 3 * 68> out{};
    bench::in_memory(out);
    std::size_t i = 0;
    for (auto _ : bench::measure(state)) {
        bench::consume(hw_to_hex(buf.data() + 68 * (i++ % bench::variants), 68, out.data(), out.size()));
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * 68);
}
}  // namespace

BENCHMARK(load_u32_robowire)->Name("core.load_u32:robowire")->Apply(bench::rounds<4096>);
BENCHMARK(load_u32_memcpy)->Name("core.load_u32:memcpy")->Apply(bench::rounds<4096>);
BENCHMARK(load_f32_robowire)->Name("core.load_f32:robowire")->Apply(bench::rounds<4096>);
BENCHMARK(load_f32_memcpy)->Name("core.load_f32:memcpy")->Apply(bench::rounds<4096>);
BENCHMARK(hex_robowire)->Name("core.to_hex_68:robowire")->Apply(bench::rounds<64>);
BENCHMARK(hex_handwritten)->Name("core.to_hex_68:handwritten")->Apply(bench::rounds<64>);
BENCHMARK(hex_careful)->Name("core.to_hex_68:careful")->Apply(bench::rounds<64>);
