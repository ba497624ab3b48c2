// Shared by the fuzz harnesses: a byte reader, a table-driven message filler,
// and a check that aborts with a message (libFuzzer reports it as a crash).
#pragma once

#include <robowire/core.hpp>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <variant>

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

template <class E>
void fill_element(E& v, reader& r);

template <class M>
void fill(M& m, reader& r) {
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        auto& member = m.*f.member;
        if constexpr (F::is_optional) {
            if (r.byte() & 1) {
                auto& v = member.emplace();
                if constexpr (F::is_array) for (auto& e : v) fill_element(e, r);
                else fill_element(v, r);
            } else {
                member.reset();
            }
        } else if constexpr (F::is_array) {
            for (auto& e : member) fill_element(e, r);
        } else {
            fill_element(member, r);
        }
    });
}

template <class E>
void fill_element(E& v, reader& r) {
    if constexpr (std::is_same_v<E, bool>) {
        v = r.byte() & 1;
    } else if constexpr (std::is_enum_v<E>) {
        v = static_cast<E>(r.byte());  // also invalid codes
    } else if constexpr (std::is_same_v<E, float>) {
        v = std::bit_cast<float>(r.integer<std::uint32_t>());  // any bit pattern, NaNs too
    } else if constexpr (std::is_integral_v<E>) {
        v = r.integer<E>();
    } else if constexpr (requires { v.view(); }) {  // text<N>
        char buf[64] = {};
        const std::size_t n = r.byte() % (v.capacity() + 2);
        for (std::size_t i = 0; i < n && i < sizeof buf; ++i) buf[i] = static_cast<char>(r.byte());
        if (auto t = std::remove_cvref_t<E>::make(std::string_view(buf, n))) v = *t;
    } else if constexpr (requires { v.push_back(std::uint8_t{}); }) {  // bytes<N>
        v.clear();
        const std::size_t n = r.byte() % (v.capacity() + 1);
        for (std::size_t i = 0; i < n; ++i) (void)v.push_back(r.byte());
    } else {
        fill(v, r);  // record
    }
}

// Fills the alternative chosen by the first input byte.
template <class Variant, std::size_t I = 0>
Variant pick(std::size_t index, reader& r) {
    if constexpr (I + 1 == std::variant_size_v<Variant>) {
        std::variant_alternative_t<I, Variant> m{};
        fill(m, r);
        return Variant{std::in_place_index<I>, m};
    } else {
        if (index == I) {
            std::variant_alternative_t<I, Variant> m{};
            fill(m, r);
            return Variant{std::in_place_index<I>, m};
        }
        return pick<Variant, I + 1>(index, r);
    }
}

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
