// Shared by the fuzz harnesses: the round-trip check, and a check that aborts
// with a message (libFuzzer reports it as a crash). Messages and values are
// made from the input by <robowire/ext/fuzz.hpp> (robowire::fuzz::make, fuzz::source).
#pragma once

#include <robowire/core.hpp>
#include <robowire/ext/fuzz.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <string_view>
#include <utility>
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

inline bool same_bytes(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    return robowire::equal_bytes(a, b);
}

// A result's error text: to_string of an error's code is a real text (not
// empty, not "ok", not that of a code outside errc); a value's code() is
// errc::ok, whose text is "ok". Cheap (a switch): for every result.
template <class T>
void check_text(const robowire::result<T>& r) {
    const std::string_view text = robowire::to_string(r.code());
    if (r) FUZZ_CHECK(r.code() == robowire::errc::ok && text == "ok");
    else FUZZ_CHECK(r.code() == r.error().code && !text.empty() && text != "ok" && text != "unknown error");
}

#if defined(__cpp_exceptions)
// check_text, and the exception a wrong access throws: bad_result_access
// built for the result's error (errc::ok for a value: what error() of a value
// throws) carries it, and its what() gives the code's text and ends with
// " at byte <offset>" (for a value: says error() was called on one). Built
// directly, not thrown, yet some 1 us under ASan, a frame decode's time:
// the frame decoders' harnesses (some 4 us an input) use check_text.
template <class T>
void check_access(const robowire::result<T>& r) {
    check_text(r);
    const robowire::error e = r ? robowire::error{} : r.error();
    const robowire::bad_result_access x(e);
    FUZZ_CHECK(x.error() == e && x.code() == e.code);
    const std::string_view what = x.what();
    if (r) {
        FUZZ_CHECK(what == "robowire: error() of a result that holds a value");
        return;
    }
    char at[24];
    const int n = std::snprintf(at, sizeof at, " at byte %u", unsigned{e.offset});
    FUZZ_CHECK(n > 0 && what.find(robowire::to_string(e.code)) != std::string_view::npos);
    FUZZ_CHECK(what.size() >= static_cast<std::size_t>(n) &&
               what.substr(what.size() - static_cast<std::size_t>(n)) == std::string_view(at, static_cast<std::size_t>(n)));
}

// check_access, and the wrong access itself: value() of an error, error() of
// a value, throws that exception. A throw costs some 20 us under ASan: for
// harnesses whose inputs take far longer than that (navbot_reassembler).
template <class T>
void check_throws(const robowire::result<T>& r) {
    check_access(r);
    const robowire::error e = r ? robowire::error{} : r.error();
    bool threw = false;
    try {
        if (r) (void)r.error();
        else (void)r.value();
    } catch (const robowire::bad_result_access& x) {
        threw = true;
        FUZZ_CHECK(x.error() == e && std::string_view(x.what()) == robowire::bad_result_access(e).what());
    }
    FUZZ_CHECK(threw);
}
#else
template <class T>
void check_access(const robowire::result<T>& r) {
    check_text(r);
}
template <class T>
void check_throws(const robowire::result<T>& r) {
    check_text(r);
}
#endif

// Input bytes with the message's reserved bytes set to 0 (what re-encoding sends).
template <class M>
robowire::bytes<robowire::max_size_v<M>> without_reserved(std::span<const std::uint8_t> in) {
    constexpr auto reserved = robowire::reserved_bytes<M>();
    auto out = robowire::bytes<robowire::max_size_v<M>>::from(in.first(std::min(in.size(), robowire::max_size_v<M>))).value();
    for (std::size_t i = 0; i < out.size(); ++i)
        if (reserved[i]) out[i] = 0;
    return out;
}

// decode_into of every message of Variant on `in`: an error leaves the
// object exactly as it was (every byte, padding included); a success gives
// decode()'s message.
inline void escape(void* p) { asm volatile("" : : "r"(p) : "memory"); }  // its bytes read from memory as they are
template <class M>
void check_decode_into_one(std::span<const std::uint8_t> in) {
    M obj{};
    escape(&obj);
    unsigned char before[sizeof(M)], after[sizeof(M)];
    std::memcpy(before, static_cast<const void*>(&obj), sizeof(M));
    const robowire::error e = robowire::decode_into(obj, in);
    escape(&obj);
    std::memcpy(after, static_cast<const void*>(&obj), sizeof(M));
    if (e.code != robowire::errc::ok) {
        FUZZ_CHECK(std::memcmp(before, after, sizeof(M)) == 0);
    } else {
        const auto r = robowire::decode<M>(in);
        FUZZ_CHECK(r.has_value());
        const auto a = robowire::encode(*r), b = robowire::encode(obj);
        FUZZ_CHECK(a.has_value() == b.has_value());
        if (a && b) FUZZ_CHECK(same_bytes(*a, *b));
    }
}
template <class Variant, std::size_t... I>
void check_decode_into_each(std::span<const std::uint8_t> in, std::index_sequence<I...>) {
    (check_decode_into_one<std::variant_alternative_t<I, Variant>>(in), ...);
}
template <class Variant>
void check_decode_into(std::span<const std::uint8_t> in) {
    check_decode_into_each<Variant>(in, std::make_index_sequence<std::variant_size_v<Variant>>{});
}

// The structure-aware round trip: encode(m) either fails with a field error
// inside the message, or decodes back to the same bytes (float bit patterns
// included, since the comparison is on bytes). `floats::none`: the protocol's
// messages have no float field, so that two of them compare equal exactly
// when they encode alike (+0.0 == -0.0 encode differently); operator== is
// checked too.
enum class floats { some, none };
template <floats F = floats::some, class Variant, class Decode>
void round_trip(const Variant& m, Decode&& decode_any) {
    const auto wire = robowire::encode(m);
    check_text(wire);
    if (!wire) {
        const auto e = wire.error();
        FUZZ_CHECK(e.code == robowire::errc::value_out_of_range || e.code == robowire::errc::invalid_enum ||
                   e.code == robowire::errc::missing_field);
        FUZZ_CHECK(e.offset < robowire::variant_max_size_v<Variant>);
        return;
    }
    // encode_to writes the same bytes into a buffer of exactly their size, and
    // fails with buffer_too_small (offset: the size needed) on one byte less.
    std::visit(
        [&](const auto& alt) {
            std::uint8_t buf[robowire::variant_max_size_v<Variant>] = {};
            const std::span<std::uint8_t> out(buf, wire->size());
            const auto n = robowire::encode_to(alt, out);
            check_text(n);
            FUZZ_CHECK(n.has_value() && *n == wire->size() && same_bytes(out, *wire));
            const auto short_by_one = robowire::encode_to(alt, out.first(out.size() - 1));
            check_text(short_by_one);
            FUZZ_CHECK(!short_by_one && short_by_one.error().code == robowire::errc::buffer_too_small &&
                       short_by_one.error().offset == wire->size());
        },
        m);
    const auto back = decode_any(std::span<const std::uint8_t>(wire->data(), wire->size()));
    check_text(back);
    FUZZ_CHECK(back.has_value());
    FUZZ_CHECK(back->index() == m.index());
    const auto again = robowire::encode(*back);
    FUZZ_CHECK(again.has_value());
    FUZZ_CHECK(same_bytes(*again, *wire));
    // Without floats, operator== agrees with the encoding: a frame one bit
    // off (at a byte chosen by the frame) that decodes is a message that
    // compares equal exactly when it encodes to the same bytes.
    if constexpr (F == floats::none) {
        unsigned sum = 0;
        for (const auto b : *wire) sum += b;
        auto off = *wire;
        off[sum % off.size()] ^= static_cast<std::uint8_t>(1u << (sum / off.size() % 8));
        const auto other = decode_any(std::span<const std::uint8_t>(off.data(), off.size()));
        if (!other) return;
        const auto other_wire = robowire::encode(*other);
        if (!other_wire) return;
        if (same_bytes(*other_wire, *wire)) FUZZ_CHECK(*other == *back);  // e.g. a reserved bit: ignored
        else FUZZ_CHECK(!(*other == *back) && *other != *back);
    }
}

}  // namespace fuzz
