// Core primitives: little-endian loads vs memcpy, hex formatting vs a plain
// loop (which, as robowire::to_hex, checks that the text fits the caller's
// buffer: bench::hw's buffer_too_small at the size it needs).
#include <robowire/core.hpp>

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
// The careful version: a 256-entry table of digit pairs, no test in the loop
// (the last byte's pair written after it), the size check first.
constexpr auto hex_pairs = [] {
    std::array<std::array<char, 2>, 256> t{};
    constexpr char digits[] = "0123456789ABCDEF";
    for (std::size_t i = 0; i < 256; ++i) t[i] = {digits[i >> 4], digits[i & 15]};
    return t;
}();
inline bench::hw::error careful_to_hex(const std::uint8_t* p, std::size_t n, char* out, std::size_t size) {
    const std::size_t need = n ? 3 * n - 1 : 0;
    if (need > size) [[unlikely]] return bench::hw::fail(bench::hw::buffer_too_small, need);
    if (n == 0) return bench::hw::good;
    for (std::size_t k = 0; k + 1 < n; ++k, out += 3) {
        std::memcpy(out, hex_pairs[p[k]].data(), 2);
        out[2] = ' ';
    }
    std::memcpy(out, hex_pairs[p[n - 1]].data(), 2);
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
