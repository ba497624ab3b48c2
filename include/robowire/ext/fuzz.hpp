// robowire/ext/fuzz.hpp - messages for fuzz harnesses, driven by the field tables.
// An optional extra: not in the umbrella robowire.hpp; it uses the public API only.
//
//   source s{data, size};                       // the fuzz input; zeros past its end
//   auto m = make<buwizz3::status>(s);          // every field in its valid range: encode succeeds
//   auto v = make<osp::message>(s);             // a std::variant: one byte picks the alternative
//   auto n = make<M>(s, out_of_range{});        // near-valid: a field out of range now and then
//   mutate<buwizz3::notification>(data, size, max_size, seed);  // for LLVMFuzzerCustomMutator
//
// No heap, no exceptions; source and make are constexpr. Nothing here is
// specific to one message: every function walks the message's table
// (table_v), so a message added to a protocol is covered as it is.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "../core/bits.hpp"
#include "../core/bytes.hpp"
#include "../core/decode.hpp"
#include "../core/dispatch.hpp"
#include "../core/encode.hpp"
#include "../core/endian.hpp"
#include "../core/fields.hpp"
#include "../core/table.hpp"
#include "../core/text.hpp"
#include "../core/wire.hpp"
#include "../reflect.hpp"

namespace robowire::fuzz {

// A byte source over the fuzz input, like FuzzedDataProvider but reading
// from the front: each value takes the next bytes; past the end every byte
// is 0, so a short input makes a message with every field at the low end of
// its range.
class source {
public:
    constexpr source() noexcept = default;
    constexpr source(const std::uint8_t* data, std::size_t size) noexcept : data_(data), size_(data ? size : 0) {}
    constexpr explicit source(std::span<const std::uint8_t> in) noexcept : source(in.data(), in.size()) {}

    // The next byte (0 past the end).
    constexpr std::uint8_t byte() noexcept { return pos_ < size_ ? data_[pos_++] : std::uint8_t{0}; }
    constexpr bool boolean() noexcept { return (byte() & 1) != 0; }
    // sizeof(T) bytes, the first the least significant.
    template <class T>
    requires std::is_integral_v<T>
    constexpr T integral() noexcept {
        std::uint64_t u = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i) u |= std::uint64_t{byte()} << (8 * i);
        return static_cast<T>(static_cast<std::make_unsigned_t<T>>(u));
    }
    // A value in lo..hi (lo <= hi): as many bytes as hi - lo needs (one for
    // up to 256 values), the first the least significant, taken modulo the
    // number of values and added to lo. All zeros: lo.
    template <class T>
    requires std::is_integral_v<T>
    constexpr T integral_in_range(T lo, T hi) noexcept {
        if (hi < lo) return lo;
        const std::uint64_t width = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
        std::uint64_t u = 0;
        for (std::size_t i = 0; i < 8 && (width >> (8 * i)) != 0; ++i) u |= std::uint64_t{byte()} << (8 * i);
        if (width != std::numeric_limits<std::uint64_t>::max()) u %= width + 1;
        return static_cast<T>(static_cast<std::uint64_t>(lo) + u);
    }
    // The bytes not read yet, which count as read from now on.
    constexpr std::span<const std::uint8_t> rest() noexcept {
        const std::span<const std::uint8_t> r =
            pos_ < size_ ? std::span<const std::uint8_t>(data_ + pos_, size_ - pos_) : std::span<const std::uint8_t>();
        pos_ = size_;
        return r;
    }
    constexpr std::size_t remaining() const noexcept { return pos_ < size_ ? size_ - pos_ : 0; }
    constexpr bool empty() const noexcept { return pos_ >= size_; }
    constexpr std::size_t position() const noexcept { return pos_; }  // bytes read so far (past the end too)

private:
    const std::uint8_t* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t pos_ = 0;
};

// The near-valid form of make: before each integer, enum, bool and text
// value, and before an optional block that follows an absent one, one more
// byte decides whether it is drawn out of range; it is when that byte is at least
// 256 - per_256, so with probability per_256 / 256 (default 8/256 = 1/32)
// for input bytes that look random, and never past the end of the input.
// Out of range means: an integer outside the table's range but inside what
// the wire type holds (fields whose range is the whole wire type stay
// valid), an enum code that is not in the enumeration, text with a NUL
// inside, an optional block present after one that is absent. bool, float
// and tail (bytes<N>) fields have no invalid values.
struct out_of_range {
    std::uint8_t per_256 = 8;
};

// g++ -O3 may report a disengaged std::optional's payload, copied with the
// message that make() returns, as maybe uninitialised (libstdc++'s optional
// leaves it unset by design): a false positive, silenced here only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
namespace impl {
// A float from its bit pattern and back, through the public little-endian helpers.
constexpr float float_of_bits(std::uint32_t u) noexcept {
    std::uint8_t b[4] = {};
    store_le<std::uint32_t>(b, u);
    return load_le<float>(b);
}
constexpr std::uint32_t bits_of_float(float v) noexcept {
    std::uint8_t b[4] = {};
    store_le<float>(b, v);
    return load_le<std::uint32_t>(b);
}

// What the wire type of F holds: the raw values a decoder can meet.
template <class F>
constexpr range wire_limits() noexcept {
    using W = typename F::wire_type;
    using E = typename F::element_type;
    if constexpr (std::is_same_v<E, bool>) return {0, 1};
    else if constexpr (W::kind == wire_kind::bits) return {0, low_mask(W::width)};
    else {
        using R = typename W::raw_type;
        return {std::numeric_limits<R>::min(), std::numeric_limits<R>::max()};
    }
}
constexpr std::int64_t max_of(std::int64_t a, std::int64_t b) noexcept { return a > b ? a : b; }
constexpr std::int64_t min_of(std::int64_t a, std::int64_t b) noexcept { return a < b ? a : b; }

// The valid range of an integer field, within what the member and the wire hold.
template <class F>
constexpr range valid_range(const F& f) noexcept {
    using E = typename F::element_type;
    const range w = wire_limits<F>();
    return {max_of(max_of(f.valid.min, w.min), std::int64_t{std::numeric_limits<E>::min()}),
            min_of(min_of(f.valid.max, w.max), static_cast<std::int64_t>(std::numeric_limits<E>::max()))};
}
// The values below and above the valid range that the member and the wire
// hold (empty when lo > hi).
template <class F>
constexpr range below_range(const F& f) noexcept {
    using E = typename F::element_type;
    const range w = wire_limits<F>();
    return {max_of(w.min, std::int64_t{std::numeric_limits<E>::min()}), valid_range(f).min - 1};
}
template <class F>
constexpr range above_range(const F& f) noexcept {
    using E = typename F::element_type;
    const range w = wire_limits<F>();
    return {valid_range(f).max + 1, min_of(w.max, static_cast<std::int64_t>(std::numeric_limits<E>::max()))};
}

template <class E>
constexpr E enum_code(std::int64_t code) noexcept {
    return static_cast<E>(static_cast<std::underlying_type_t<E>>(code));
}
// A code of E that is not in its table, starting the search at `from`
// (nullopt if every code of the underlying type is valid).
template <class E, class F>
constexpr std::optional<std::int64_t> invalid_code(std::int64_t from) noexcept {
    const range w = wire_limits<F>();
    const std::int64_t lo = max_of(w.min, std::int64_t{std::numeric_limits<std::underlying_type_t<E>>::min()});
    const std::int64_t hi =
        min_of(w.max, static_cast<std::int64_t>(std::numeric_limits<std::underlying_type_t<E>>::max()));
    const std::int64_t span = hi - lo + 1;
    for (std::int64_t k = 0; k < span && k < 512; ++k) {
        const std::int64_t c = lo + ((from - lo) % span + span + k) % span;
        if (!is_valid_enum(enum_code<E>(c))) return c;
    }
    return std::nullopt;
}

// The near-valid form's decision byte: true with probability bad / 256.
constexpr bool draw_out(source& s, std::uint8_t bad) noexcept { return bad != 0 && unsigned{s.byte()} + bad >= 256u; }

template <class M>
constexpr void make_fields(M& m, source& s, std::uint8_t bad) noexcept;

// One element (scalar, enum, bool, float, text, tail or record) of field f.
template <class F, class E>
constexpr void make_element(const F& f, E& v, source& s, std::uint8_t bad) noexcept {
    using W = typename F::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        make_fields(v, s, bad);
    } else if constexpr (W::kind == wire_kind::tail) {
        v.clear();
        const std::size_t n = s.integral_in_range<std::size_t>(0, E::capacity());
        for (std::size_t i = 0; i < n; ++i) (void)v.push_back(s.byte());
    } else if constexpr (std::is_same_v<E, float>) {
        v = float_of_bits(s.integral<std::uint32_t>());  // any bit pattern: NaNs and infinities too
    } else if constexpr (std::is_same_v<E, bool>) {
        if (bad != 0) (void)s.byte();
        v = s.boolean();
    } else {
        const bool out = draw_out(s, bad);
        if constexpr (W::kind == wire_kind::text) {
            std::array<char, E::capacity()> chars{};
            const std::size_t n = s.integral_in_range<std::size_t>(0, E::capacity());
            for (std::size_t i = 0; i < n; ++i) chars[i] = static_cast<char>(s.integral_in_range<unsigned>(1, 255));
            if (out && n > 0) chars[s.integral_in_range<std::size_t>(0, n - 1)] = '\0';
            (void)v.assign(std::string_view(chars.data(), n));
        } else if constexpr (std::is_enum_v<E>) {
            constexpr auto& codes = enum_table_v<E>;
            if (out) {
                if (const auto c = invalid_code<E, F>(s.byte())) {
                    v = enum_code<E>(*c);
                    return;
                }
            }
            if constexpr (codes.size() > 0) v = codes[s.integral_in_range<std::size_t>(0, codes.size() - 1)].value;
        } else {
            range r = valid_range(f);
            if (out) {
                const range below = below_range(f), above = above_range(f);
                const bool side = s.boolean();
                if (below.min <= below.max && (!side || above.min > above.max)) r = below;
                else if (above.min <= above.max) r = above;
            }
            v = static_cast<E>(s.integral_in_range<std::int64_t>(r.min, r.max));
        }
    }
}

// A value of field f's member (an element or a std::array of them).
template <class F, class V>
constexpr void make_value(const F& f, V& v, source& s, std::uint8_t bad) noexcept {
    if constexpr (F::is_array)
        for (auto& e : v) make_element(f, e, s, bad);
    else make_element(f, v, s, bad);
}

template <class M>
constexpr void make_fields(M& m, source& s, std::uint8_t bad) noexcept {
    bool absent_seen = false;  // an optional block after an absent one makes encode fail (missing_field)
    for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        auto& member = m.*f.member;
        if constexpr (F::is_optional) {
            bool present = s.boolean();
            if (present && absent_seen) present = draw_out(s, bad);
            if (present) {
                make_value(f, member.emplace(), s, bad);
            } else {
                member.reset();
                absent_seen = true;
            }
        } else {
            make_value(f, member, s, bad);
        }
    });
}

template <class T>
struct is_variant : std::false_type {};
template <class... M>
struct is_variant<std::variant<M...>> : std::true_type {};

template <class T>
constexpr T make(source& s, std::uint8_t bad) noexcept;

// Alternative `index` of variant T, built in place (emplace of another
// alternative than the first is not constexpr with every library).
template <class T, std::size_t I = 0>
constexpr T make_indexed_alternative(std::size_t index, source& s, std::uint8_t bad) noexcept {
    if constexpr (I + 1 < std::variant_size_v<T>) {
        if (index != I) return make_indexed_alternative<T, I + 1>(index, s, bad);
    }
    return T{std::in_place_index<I>, make<std::variant_alternative_t<I, T>>(s, bad)};
}

template <class T>
constexpr T make(source& s, std::uint8_t bad) noexcept {
    if constexpr (is_variant<T>::value) {
        return make_indexed_alternative<T>(s.integral_in_range<std::size_t>(0, std::variant_size_v<T> - 1), s, bad);
    } else {
        T m{};
        make_fields(m, s, bad);
        return m;
    }
}
}  // namespace impl
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// A message of type M (a described message, or a std::variant of them: the
// next byte, modulo the number of alternatives, picks one) made from the
// source, field by field in table order:
//  - an integer: a value of the table's valid range (source::integral_in_range);
//  - an enum: one of its codes (the next byte picks an entry of its table);
//  - bool: bit 0 of the next byte; float: the next 4 bytes as a bit pattern
//    (NaNs and infinities included: encode takes every float);
//  - text<N>: a length 0..N, then that many characters 1..255 (no NUL);
//  - bytes<N> (a tail): a length 0..N, then the bytes;
//  - a record or an array: element by element;
//  - an optional block: present when bit 0 of the next byte is set, but never
//    after an absent one.
// encode(make<M>(s)) always succeeds. An empty source makes every integer
// its range's minimum, every enum its table's first code, and no optional block.
template <class M>
[[nodiscard]] constexpr M make(source& s) noexcept {
    return impl::make<M>(s, 0);
}
// The near-valid form (see out_of_range): the same draws, with one byte more
// before each value that may put it out of range, for harnesses that test
// the rejection paths. Encode fails on such a message with the field's
// error (value_out_of_range, invalid_enum or missing_field).
template <class M>
[[nodiscard]] constexpr M make(source& s, out_of_range p) noexcept {
    return impl::make<M>(s, p.per_256);
}

// The byte-level mutator mutate() falls back on, e.g. libFuzzer's
// LLVMFuzzerMutate: mutates data[0..size) in place, returns the new size (<= max_size).
using byte_mutator = std::size_t (*)(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace impl::inline ROBOWIRE_MODE_NAMESPACE {  // decode and encode below depend on the size settings
// splitmix64: a small, good generator for the mutator's choices.
struct rng {
    std::uint64_t state;
    constexpr std::uint64_t next() noexcept {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15u);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
        return z ^ (z >> 31);
    }
    constexpr std::size_t below(std::size_t n) noexcept { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
    constexpr std::int64_t in(std::int64_t lo, std::int64_t hi) noexcept {
        const std::uint64_t width = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
        const std::uint64_t u = width == std::numeric_limits<std::uint64_t>::max() ? next() : next() % (width + 1);
        return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + u);
    }
};

// Random bytes for make() when the mutator needs a new value.
template <std::size_t N>
struct random_bytes {
    std::array<std::uint8_t, N> b{};
    constexpr explicit random_bytes(rng& r) noexcept {
        for (auto& x : b) x = static_cast<std::uint8_t>(r.next());
    }
    constexpr source get() const noexcept { return source{b.data(), b.size()}; }
};
// Enough for any message of Variant (make reads at most a few bytes per wire byte).
template <class Variant>
inline constexpr std::size_t scratch_size_v = 3 * variant_max_size_v<Variant> + 32;

// Decodes `in` as the first alternative of Variant that takes it.
template <class Variant>
constexpr bool decode_any(std::span<const std::uint8_t> in, Variant& out) noexcept {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        const auto one = [&](auto index) {
            constexpr std::size_t i = decltype(index)::value;
            auto r = robowire::decode<std::variant_alternative_t<i, Variant>>(in);
            if (!r) return false;
            out.template emplace<i>(*r);
            return true;
        };
        return (one(std::integral_constant<std::size_t, I>{}) || ...);
    }
    (std::make_index_sequence<std::variant_size_v<Variant>>{});
}

// Calls fn(field, element, offset) for every scalar, enum, bool, float,
// text and tail element of m (records and arrays walked, absent optional
// blocks skipped); offset: the element's first byte in the encoding.
template <class M, class Fn>
constexpr void each_leaf(M& m, std::size_t base, Fn& fn) noexcept {
    for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        auto& member = m.*f.member;
        const auto one = [&](auto& e, std::size_t off) {
            if constexpr (F::kind == wire_kind::record) each_leaf(e, off, fn);
            else fn(f, e, off);
        };
        const auto value = [&](auto& v) {
            if constexpr (F::is_array)
                for (std::size_t k = 0; k < F::count; ++k) one(v[k], base + f.offset + k * F::element_size);
            else one(v, base + f.offset);
        };
        if constexpr (F::is_optional) {
            if (member) value(*member);
        } else {
            value(member);
        }
    });
}

// A raw value written over the encoding after encode: how an out-of-range
// value reaches the wire (encode refuses it).
struct raw_write {
    void (*store)(std::uint8_t* out, std::size_t size, std::size_t offset, std::int64_t value) = nullptr;
    std::size_t offset = 0;
    std::int64_t value = 0;
};
template <class F>
constexpr void store_raw(std::uint8_t* out, std::size_t size, std::size_t offset, std::int64_t value) noexcept {
    using E = typename F::element_type;
    using W = typename F::wire_type;
    if (offset + F::element_size > size) return;
    if constexpr (W::kind == wire_kind::f32le) {
        store_le<float>(out + offset, static_cast<float>(value));
    } else {
        std::uint64_t raw = 0;
        if constexpr (std::is_enum_v<E>)
            raw = static_cast<std::uint64_t>(static_cast<std::underlying_type_t<E>>(enum_code<E>(value)));
        else raw = static_cast<std::uint64_t>(static_cast<E>(value));
        if constexpr (W::kind == wire_kind::bits) {
            constexpr auto mask = static_cast<unsigned>(low_mask(W::width) << W::lo);
            out[offset] = static_cast<std::uint8_t>((static_cast<unsigned>(out[offset]) & ~mask) |
                                                    ((static_cast<unsigned>(raw) << W::lo) & mask));
        } else {
            store_le<typename W::raw_type>(out + offset, static_cast<typename W::raw_type>(raw));
        }
    }
}

// Changes one element: a neighbouring value, a range end, a value just out
// of range (written raw), another enum code or an invalid one, a special or
// nearby float, new text or tail bytes.
template <class Variant, class F, class E>
constexpr void mutate_element(const F& f, E& v, std::size_t offset, rng& r, raw_write& raw) noexcept {
    using W = typename F::wire_type;
    if constexpr (W::kind == wire_kind::text || W::kind == wire_kind::tail) {
        const random_bytes<2 * E::capacity() + 8> bytes(r);
        source s = bytes.get();
        make_element(f, v, s, 0);
    } else if constexpr (std::is_same_v<E, bool>) {
        v = !v;
    } else if constexpr (std::is_same_v<E, float>) {
        constexpr float specials[] = {0.0f,
                                      -0.0f,
                                      1.0f,
                                      -1.0f,
                                      0.5f,
                                      100.0f,
                                      std::numeric_limits<float>::infinity(),
                                      -std::numeric_limits<float>::infinity(),
                                      std::numeric_limits<float>::quiet_NaN(),
                                      std::numeric_limits<float>::max(),
                                      std::numeric_limits<float>::denorm_min()};
        const auto u = bits_of_float(v);
        switch (r.below(4)) {
        case 0: v = float_of_bits(u + 1); break;  // the next float (by bit pattern)
        case 1: v = float_of_bits(u - 1); break;
        case 2: v = specials[r.below(std::size(specials))]; break;
        default: v = float_of_bits(static_cast<std::uint32_t>(r.next())); break;
        }
    } else if constexpr (std::is_enum_v<E>) {
        constexpr auto& codes = enum_table_v<E>;
        if (r.below(4) == 0) {
            if (const auto c = invalid_code<E, F>(static_cast<std::int64_t>(r.below(256)))) {
                raw = {&store_raw<F>, offset, *c};
                return;
            }
        }
        if constexpr (codes.size() > 1) {
            std::size_t k = r.below(codes.size() - 1);  // another code than v's
            for (std::size_t i = 0; i <= k && i < codes.size(); ++i)
                if (codes[i].value == v) ++k;
            v = codes[k < codes.size() ? k : 0].value;
        }
    } else {
        const range ok = valid_range(f);
        const auto x = static_cast<std::int64_t>(v);
        std::int64_t y = x;
        switch (r.below(6)) {
        case 0: y = x < ok.max ? x + 1 : x - 1; break;  // neighbours
        case 1: y = x > ok.min ? x - 1 : x + 1; break;
        case 2: y = ok.min; break;  // range ends
        case 3: y = ok.max; break;
        case 4: y = r.in(ok.min, ok.max); break;
        default: {  // just out of range, written raw
            const range below = below_range(f), above = above_range(f);
            const bool low = r.below(2) == 0;
            if (below.min <= below.max && (low || above.min > above.max)) raw = {&store_raw<F>, offset, below.max};
            else if (above.min <= above.max) raw = {&store_raw<F>, offset, above.min};
            else y = r.in(ok.min, ok.max);
        }
        }
        if (y < ok.min || y > ok.max) y = ok.min;
        v = static_cast<E>(y);
    }
}

// Number of optional fields of M.
template <class M>
inline constexpr std::size_t optional_count_v = [] {
    std::size_t n = 0;
    for_each_field<M>([&](const auto& f) { n += std::remove_cvref_t<decltype(f)>::is_optional; });
    return n;
}();

// Changes one thing of message m: how many optional blocks it has (they are
// made from random bytes), or one element.
template <class Variant, class M>
constexpr void mutate_message(M& m, rng& r, raw_write& raw) noexcept {
    if constexpr (optional_count_v < M >> 0) {
        if (r.below(4) == 0) {
            const std::size_t keep = r.below(optional_count_v<M> + 1);  // the first `keep` blocks present
            std::size_t k = 0;
            const random_bytes<scratch_size_v<Variant>> bytes(r);
            source s = bytes.get();
            for_each_field<M>([&](const auto& f) {
                if constexpr (std::remove_cvref_t<decltype(f)>::is_optional) {
                    auto& member = m.*f.member;
                    if (k++ < keep) {
                        if (!member) make_value(f, member.emplace(), s, 0);
                    } else {
                        member.reset();
                    }
                }
            });
            return;
        }
    }
    std::size_t leaves = 0;
    auto count = [&](const auto&, auto&, std::size_t) { ++leaves; };
    each_leaf(m, 0, count);
    if (leaves == 0) return;
    const std::size_t pick = r.below(leaves);
    std::size_t k = 0;
    auto change = [&](const auto& f, auto& e, std::size_t offset) {
        if (k++ == pick) mutate_element<Variant>(f, e, offset, r, raw);
    };
    each_leaf(m, 0, change);
}

// Byte-level mutation: fallback when given, else a bit flipped, a byte
// replaced, inserted or erased. Changes the input whenever max_size > 0.
constexpr std::size_t mutate_bytes(std::uint8_t* data, std::size_t size, std::size_t max_size, rng& r,
                                   byte_mutator fallback) noexcept {
    if (fallback != nullptr) return fallback(data, size, max_size);
    if (size > max_size) size = max_size;
    if (max_size == 0) return 0;
    const std::size_t kind = size == 0 ? 2 : r.below(4);
    if (kind == 2 && size < max_size) {  // insert a byte
        const std::size_t at = r.below(size + 1);
        for (std::size_t i = size; i > at; --i) data[i] = data[i - 1];
        data[at] = static_cast<std::uint8_t>(r.next());
        return size + 1;
    }
    if (kind == 3 && size > 1) {  // erase a byte
        const std::size_t at = r.below(size);
        for (std::size_t i = at; i + 1 < size; ++i) data[i] = data[i + 1];
        return size - 1;
    }
    const std::size_t at = r.below(size);
    if (kind == 1) data[at] = static_cast<std::uint8_t>(data[at] ^ (1 + r.below(255)));  // another byte
    else data[at] = static_cast<std::uint8_t>(data[at] ^ (1u << r.below(8)));            // one bit flipped
    return size;
}

// Repairs input that no alternative decodes: the fixed bytes and the length
// of the alternative whose fixed bytes it matches best (now and then any
// alternative). Returns the new size, or 0 when there was nothing to repair.
template <class Variant>
constexpr std::size_t repair(std::uint8_t* data, std::size_t size, std::size_t max_size, rng& r) noexcept {
    constexpr std::size_t n = std::variant_size_v<Variant>;
    std::size_t best = 0, best_score = 0;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        const auto score = [&](auto index) {
            constexpr std::size_t i = decltype(index)::value;
            std::size_t s = 1;
            for (const auto& b : table_v<std::variant_alternative_t<i, Variant>>.fixed)
                s += b.offset < size && data[b.offset] == b.value ? 2 : 0;
            if (s > best_score) best = i, best_score = s;
        };
        (score(std::integral_constant<std::size_t, I>{}), ...);
    }
    (std::make_index_sequence<n>{});
    if (r.below(8) == 0) best = r.below(n);
    std::size_t out = 0;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        const auto fix = [&](auto index) {
            constexpr std::size_t i = decltype(index)::value;
            using M = std::variant_alternative_t<i, Variant>;
            if (i != best) return;
            constexpr auto& runs = accepted_lengths_v<M>;
            std::size_t len = runs.run[0][0];  // the longest accepted length up to size (else the shortest)
            for (std::size_t k = 0; k < runs.count; ++k) {
                if (size >= runs.run[k][0]) len = size < runs.run[k][1] ? size : runs.run[k][1];
            }
            if (len > max_size) return;
            bool changed = len != size;
            for (std::size_t k = size; k < len; ++k) data[k] = 0;
            for (const auto& b : table_v<M>.fixed) {
                if (b.offset < len && data[b.offset] != b.value) {
                    data[b.offset] = b.value;
                    changed = true;
                }
            }
            if (changed) out = len;
        };
        (fix(std::integral_constant<std::size_t, I>{}), ...);
    }
    (std::make_index_sequence<n>{});
    return out;
}
}  // namespace impl::inline ROBOWIRE_MODE_NAMESPACE

inline namespace ROBOWIRE_MODE_NAMESPACE {
// A structure-aware mutator for libFuzzer's LLVMFuzzerCustomMutator:
//
//   extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
//                                                  std::size_t max_size, unsigned int seed) {
//       return robowire::fuzz::mutate<robowire::buwizz3::notification>(data, size, max_size, seed, LLVMFuzzerMutate);
//   }
//
// Decodes data[0..size) as the first alternative of Variant that takes it,
// changes one thing and re-encodes it into data; returns the new size (at most max_size):
//  - one element of one field (records and arrays included): to a neighbouring
//    value, a range end, a random valid value, or just out of range (written
//    over the encoding, since encode refuses it); an enum to another code or
//    an invalid one; a bool flipped; a float to the next or previous bit
//    pattern, a special value (0, -0, +-1, infinities, NaN, largest,
//    smallest) or random bits; text and tail bytes made anew;
//  - how many optional blocks the message has (1 time in 4 for messages with some);
//  - another alternative, made from random bytes (1 time in 8).
// Input that does not decode gets the fixed bytes and an accepted length of
// the alternative it matches best; when that changes nothing (a field value
// is what is wrong), or the result would not fit, it is mutated byte by byte:
// by `fallback` when given (pass LLVMFuzzerMutate), else by a bit flip or a
// byte replaced, inserted or erased. With a fallback, 1 call in 8 uses it
// straight away, so that the campaign keeps byte-level variety. The result
// differs from the input except when the fallback leaves it as it was.
template <class Variant>
requires impl::is_variant<Variant>::value constexpr std::size_t mutate(std::uint8_t* data, std::size_t size,
                                                                       std::size_t max_size, unsigned int seed,
                                                                       byte_mutator fallback = nullptr) noexcept {
    impl::rng r{seed};
    if (fallback != nullptr && r.below(8) == 0) return fallback(data, size, max_size);
    Variant held{};
    if (!impl::decode_any(std::span<const std::uint8_t>(data, size), held)) {
        if (const std::size_t n = impl::repair<Variant>(data, size, max_size, r); n != 0) return n;
        return impl::mutate_bytes(data, size, max_size, r, fallback);
    }
    for (int attempt = 0; attempt < 4; ++attempt) {
        Variant m = held;
        impl::raw_write raw{};
        if (r.below(8) == 0) {
            const impl::random_bytes<impl::scratch_size_v<Variant>> bytes(r);
            source s = bytes.get();
            m = make<Variant>(s);
        } else {
            std::visit([&](auto& alt) { impl::mutate_message<Variant>(alt, r, raw); }, m);
        }
        auto wire = robowire::encode(m);
        if (!wire || wire->size() > max_size) continue;
        if (raw.store != nullptr) raw.store(wire->data(), wire->size(), raw.offset, raw.value);
        if (wire->size() == size && equal_bytes(wire->span(), std::span<const std::uint8_t>(data, size))) continue;
        for (std::size_t i = 0; i < wire->size(); ++i) data[i] = (*wire)[i];
        return wire->size();
    }
    return impl::mutate_bytes(data, size, max_size, r, fallback);
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire::fuzz
