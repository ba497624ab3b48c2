// Shared by the benchmarks: a rotating set of inputs, so that no iteration
// sees a constant, and a deterministic generator.
#pragma once

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace bench {

inline constexpr std::size_t variants = 64;  // inputs per benchmark, used round-robin

struct rng {
    std::uint32_t s = 0x9E3779B9u;
    std::uint32_t next() { s ^= s << 13; s ^= s >> 17; s ^= s << 5; return s; }
    std::uint8_t byte() { return static_cast<std::uint8_t>(next()); }
};

// Keeps an output object in memory for the whole benchmark (its address
// escapes), as a caller's struct would be; otherwise the compiler may split a
// small struct into registers and spill it in pieces at every DoNotOptimize.
template <class T>
void in_memory(T& object) {
    T* p = &object;
    benchmark::DoNotOptimize(p);
}

// Reads a small result the way a caller does (the outcome, then the value),
// before any DoNotOptimize: its memory clobber would otherwise force the
// result, whose address the accessors take, to live on the stack, while the
// baselines' bool and scalar outputs stay in registers.
template <class Result>
void consume(const Result& r) {
    const bool ok = r.has_value();
    const auto value = ok ? *r : typename Result::value_type{};
    benchmark::DoNotOptimize(ok);
    benchmark::DoNotOptimize(value);
}

}  // namespace bench
