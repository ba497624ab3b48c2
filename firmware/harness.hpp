// Shared by the firmware size programs: inputs come from a volatile buffer and
// results go to a volatile sink, so nothing is folded away. The empty baseline
// has the same harness; its size is subtracted from every program's.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

volatile std::uint8_t input[160];
volatile std::uint32_t sink;
volatile std::uint32_t input_size = 20;

// Copies n bytes of the volatile input into a local buffer.
template <std::size_t N>
inline std::array<std::uint8_t, N> read_input() {
    std::array<std::uint8_t, N> a{};
    for (std::size_t i = 0; i < N; ++i) a[i] = input[i];
    return a;
}
// At most max (no division: the empty program links no __udivsi3).
inline std::size_t size_in(std::size_t max) {
    const std::size_t n = input_size;
    return n < max ? n : max;
}
// Every byte to the sink: the same function for both programs of a pair (a
// span is passed on as pointer and length, as the hand-written programs pass).
inline void out_bytes(const std::uint8_t* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) sink = p[i];
}
[[gnu::always_inline]] inline void out(std::span<const std::uint8_t> b) { out_bytes(b.data(), b.size()); }
#define ENTRY extern "C" [[gnu::noinline]]
