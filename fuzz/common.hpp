// Shared by the fuzz harnesses: a byte reader, the round-trip check, and a
// check that aborts with a message (libFuzzer reports it as a crash).
// Messages are made from the input by <robowire/fuzz.hpp> (robowire::fuzz::make).
#pragma once

#include <robowire/core.hpp>
#include <robowire/fuzz.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <variant>

// A decoder harness names its protocol's variant: FUZZ_STRUCTURE_AWARE(osp::message).
// Built with -DROBOWIRE_FUZZ_STRUCTURE_AWARE (the fuzz_<name>_structure_aware
// binaries of the harnesses marked `mutator` in fuzz/harnesses.txt), libFuzzer
// mutates through robowire::fuzz::mutate, with LLVMFuzzerMutate as its byte-level fallback.
#ifdef ROBOWIRE_FUZZ_STRUCTURE_AWARE
#define FUZZ_STRUCTURE_AWARE(...)                                                                          \
    extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size); \
    extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,   \
                                                   unsigned int seed) {                                   \
        return robowire::fuzz::mutate<__VA_ARGS__>(data, size, max_size, seed, LLVMFuzzerMutate);         \
    }
#else
#define FUZZ_STRUCTURE_AWARE(...)
#endif

namespace fuzz {

#define FUZZ_CHECK(cond)                                                                   \
    do {                                                                                   \
        if (!(cond)) {                                                                     \
            std::fprintf(stderr, "%s:%d: invariant failed: %s\n", __FILE__, __LINE__, #cond); \
            std::abort();                                                                  \
        }                                                                                  \
    } while (0)

// Reads values from the fuzz input; past the end it yields zeros.
struct reader {
    std::span<const std::uint8_t> in;
    std::size_t pos = 0;
    std::uint8_t byte() { return pos < in.size() ? in[pos++] : 0; }
    template <class T>
    T integer() {
        std::make_unsigned_t<T> u = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i) u = static_cast<decltype(u)>((u << 8) | byte());
        return static_cast<T>(u);
    }
    bool empty() const { return pos >= in.size(); }
    std::span<const std::uint8_t> rest() { auto r = in.subspan(pos < in.size() ? pos : in.size()); pos = in.size(); return r; }
};

inline bool same_bytes(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    return robowire::equal_bytes(a, b);
}

// Input bytes with the message's reserved bytes set to 0 (what re-encoding sends).
template <class M>
robowire::bytes<robowire::max_size_v<M>> without_reserved(std::span<const std::uint8_t> in) {
    constexpr auto reserved = robowire::reserved_bytes<M>();
    auto out = robowire::bytes<robowire::max_size_v<M>>::from(in.first(std::min(in.size(), robowire::max_size_v<M>))).value();
    for (std::size_t i = 0; i < out.size(); ++i)
        if (reserved[i]) out[i] = 0;
    return out;
}

// The structure-aware round trip: encode(m) either fails with a field error
// inside the message, or decodes back to the same bytes (float bit patterns
// included, since the comparison is on bytes).
template <class Variant, class Decode>
void round_trip(const Variant& m, Decode&& decode_any) {
    const auto wire = robowire::encode(m);
    if (!wire) {
        const auto e = wire.error();
        FUZZ_CHECK(e.code == robowire::errc::value_out_of_range || e.code == robowire::errc::invalid_enum ||
                   e.code == robowire::errc::missing_field);
        FUZZ_CHECK(e.offset < robowire::variant_max_size_v<Variant>);
        return;
    }
    const auto back = decode_any(std::span<const std::uint8_t>(wire->data(), wire->size()));
    FUZZ_CHECK(back.has_value());
    FUZZ_CHECK(back->index() == m.index());
    const auto again = robowire::encode(*back);
    FUZZ_CHECK(again.has_value());
    FUZZ_CHECK(same_bytes(*again, *wire));
}

}  // namespace fuzz
