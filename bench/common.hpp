// Shared by the benchmarks: a rotating set of inputs, so that no iteration
// sees a constant, a deterministic generator, and the hooks that let
// bench/run --instructions count the measured loop under callgrind.
#pragma once

#include <benchmark/benchmark.h>
#include <valgrind/callgrind.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <vector>

#include "handwritten/hw.hpp"

namespace bench {

inline constexpr std::size_t variants = 64;  // inputs per benchmark, used round-robin

struct rng {
    std::uint32_t s = 0x9E3779B9u;
    std::uint32_t next() { s ^= s << 13; s ^= s >> 17; s ^= s << 5; return s; }
    std::uint8_t byte() { return static_cast<std::uint8_t>(next()); }
};

// Inputs live in page-aligned memory, so that their placement does not depend
// on what was allocated before (in Google Benchmark's start-up, which differs
// between machines): memchr's and memcpy's paths depend on alignment, and so
// does the cache simulation of bench/run --instructions.
template <class T>
struct page_allocator {
    using value_type = T;
    page_allocator() = default;
    template <class U>
    page_allocator(const page_allocator<U>&) noexcept {}
    T* allocate(std::size_t n) {
        return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t{4096}));
    }
    void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t{4096}); }
    friend bool operator==(const page_allocator&, const page_allocator&) = default;
};
template <class T>
using vector = std::vector<T, page_allocator<T>>;

// Keeps an output object in memory for the whole benchmark (its address
// escapes), as a caller's struct would be; otherwise the compiler may split a
// small struct into registers and spill it in pieces at every DoNotOptimize.
template <class T>
void in_memory(T& object) {
    T* p = &object;
    benchmark::DoNotOptimize(p);
}

// A frame as its receiver gets it: bytes in memory that the compiler did not
// see written (a BLE stack's buffer), so the receiver's checks of the bytes
// the sender wrote as constants are not folded away.
template <class T>
void received(T& frame) {
    benchmark::DoNotOptimize(frame);
}

// Reads a small result the way a caller does: branches on the outcome, then
// reads the value, or the error of a failure (as consume(hw::error) reads the
// baselines'). Each is read before its DoNotOptimize: the memory clobber would
// otherwise force the result, whose address the accessors take, to live on
// the stack, while the baselines' outputs stay in registers.
template <class Result>
void consume(const Result& r) {
    if (r.has_value()) {
        const auto value = *r;
        benchmark::DoNotOptimize(value);
    } else {
        const auto error = r.error();
        benchmark::DoNotOptimize(error);
    }
}

// Reads an error returned alone (decode_into, encode_to's error): the
// outcome, and the error of a failure, as consume(hw::error) reads the baselines'.
template <class Error>
requires(std::is_class_v<Error> && !requires(const Error& e) { e.has_value(); }) void consume(const Error& e) {
    if (e) benchmark::DoNotOptimize(e);
}

// Reads a baseline's error as consume(result) above reads robowire's: the
// outcome, and the error of a failure (the outputs are read by the caller).
inline void consume(hw::error e) {
    if (e != hw::good) benchmark::DoNotOptimize(e);
}

// ---- deterministic counts (bench/run --instructions)
//
// `for (auto _ : bench::measure(state))` is Google Benchmark's own loop (the
// same iterator, the same code in both modes). Under callgrind, collection is
// switched on just before the loop and off just after it, and the counts are
// dumped, one dump per benchmark run, in run order; set-up code and Google
// Benchmark's runner are not counted (bench/run also excludes the timer calls
// at the loop's start and end). Outside valgrind these are a few instructions
// before and after the loop.
class measure {
public:
    explicit measure(benchmark::State& state) : state_(state) {
        if (RUNNING_ON_VALGRIND) CALLGRIND_TOGGLE_COLLECT;
    }
    ~measure() {
        if (RUNNING_ON_VALGRIND) {
            CALLGRIND_TOGGLE_COLLECT;
            CALLGRIND_DUMP_STATS;
        }
    }
    measure(const measure&) = delete;
    measure& operator=(const measure&) = delete;
    auto begin() { return state_.begin(); }
    auto end() { return state_.end(); }

private:
    benchmark::State& state_;
};

// Registration option: with ROBOWIRE_BENCH_ROUNDS=k set, the benchmark runs
// exactly k * Unit iterations (once, no time-based calibration). Unit is a
// multiple of the benchmark's input rotation, so that every count covers
// whole rotations; bench/run takes the difference of two counts, which
// removes everything that does not repeat per iteration (the first, cold
// pass through the caches, the loop's entry and exit).
template <int Unit>
void rounds(benchmark::internal::Benchmark* b) {
    if (const char* k = std::getenv("ROBOWIRE_BENCH_ROUNDS")) b->Iterations(Unit * std::atoi(k));
}

// The messages one iteration processes: items per second for the wall-clock
// table, and the divisor of the per-iteration counts (counter "batch").
inline void messages(benchmark::State& state, std::size_t per_iteration) {
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(per_iteration));
    state.counters["batch"] = static_cast<double>(per_iteration);
}

}  // namespace bench
