// robowire/core/dispatch.hpp - decode into a std::variant of messages,
// choosing the alternative by the fixed byte at a key offset (the command).
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <variant>

#include "decode.hpp"
#include "encode.hpp"
#include "table.hpp"

namespace robowire {

namespace codec {
// Makes alternative I of v (default value) and returns it. With clang,
// constant evaluation assigns a new variant instead: clang 14 cannot evaluate
// libstdc++'s emplace. Not with g++, which can: there that branch, never
// taken at run time, still had g++ compile the variant's constructors for
// every alternative (a third of the functions of a TU using every dispatcher).
template <std::size_t I, class Variant>
inline constexpr auto& emplace_alternative(Variant& v) noexcept {
#if defined(__clang__)
    if (ROBOWIRE_CONSTANT_EVALUATED()) {
        v = Variant(std::in_place_index<I>);
        return *std::get_if<I>(&v);
    }
#endif
    return v.template emplace<I>();
}

// Calls f(x) for the alternative x that v holds (nothing if v is valueless):
// one compare per alternative. Cheaper to compile than std::visit, which
// instantiates a table of functions and checks every visitor result type.
// std::get, not std::get_if: g++ 12 cannot evaluate get_if on a temporary
// variant in a constant expression at namespace scope.
template <class Variant, class F, std::size_t... I>
inline constexpr void visit_held(Variant& v, F&& f, std::index_sequence<I...>) {
    const std::size_t held = v.index();
    (void)((held == I ? (f(std::get<I>(v)), true) : false) || ...);
}
template <class Variant, class F>
inline constexpr void visit_held(Variant& v, F&& f) {
    visit_held(v, f, std::make_index_sequence<std::variant_size_v<std::remove_const_t<Variant>>>{});
}
}  // namespace codec

namespace detail {
// The index of Variant's smallest alternative (the first of them).
template <class Variant, std::size_t... I>
constexpr std::size_t smallest_alternative(std::index_sequence<I...>) noexcept {
    constexpr std::size_t sizes[] = {sizeof(std::variant_alternative_t<I, Variant>)...};
    std::size_t best = 0;
    for (std::size_t i = 1; i < sizeof...(I); ++i)
        if (sizes[i] < sizes[best]) best = i;
    return best;
}
template <class Variant>
constexpr std::size_t smallest_alternative() noexcept {
    return smallest_alternative<Variant>(std::make_index_sequence<std::variant_size_v<Variant>>{});
}
}  // namespace detail

namespace codec::inline ROBOWIRE_MODE_NAMESPACE {
// Makes alternative I of the variant in r, in place, and returns it, for a
// dispatcher's result: one that holds nothing yet (result(codec::unset_t)),
// or, under ROBOWIRE_OPTIMIZE_SIZE, a variant (started as any alternative: less code).
template <std::size_t I, class Variant>
ROBOWIRE_ALWAYS_INLINE constexpr auto& make_alternative(result<Variant>& r) noexcept {
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) return emplace_alternative<I>(unchecked_value(r));
    else return *std::get_if<I>(&detail::build_value(r, std::in_place_index<I>));
}
// As make_alternative (not under ROBOWIRE_OPTIMIZE_SIZE), for a codec that has
// stored r's flag (as true) already, with other bytes: at run time the flag is left as it is.
// The variant is made holding its smallest alternative, then alternative I
// is emplaced: one variant constructor for every I (the constructor for index
// I instantiates I nested ones), and the first store is dead.
template <std::size_t I, class Variant>
ROBOWIRE_ALWAYS_INLINE constexpr auto& make_alternative_keep_flag(result<Variant>& r) noexcept {
    constexpr std::size_t first = detail::smallest_alternative<Variant>();
    if constexpr (I == first) return *std::get_if<I>(&detail::build_value_keep_flag(r, std::in_place_index<I>));
    else return emplace_alternative<I>(detail::build_value_keep_flag(r, std::in_place_index<first>));
}
}  // namespace codec::inline ROBOWIRE_MODE_NAMESPACE

namespace detail {
// Tells the compiler that this point is never reached (a value out of range).
ROBOWIRE_ALWAYS_INLINE constexpr void unreachable() noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) return;
#if defined(__GNUC__)
    __builtin_unreachable();
#elif defined(_MSC_VER)
    __assume(false);
#endif
}
// Not constexpr: reached at compile time, it is the compile error (two
// alternatives of a variant have the same key: the second could never be decoded).
inline void variant_alternatives_share_a_key(std::string_view /*first_alternative*/, int /*key*/) noexcept {}

// Alternative index for each value of the key byte (variant_size: none).
template <class Variant, std::size_t KeyOffset>
inline constexpr auto key_index_v = [] {
    constexpr std::size_t count = std::variant_size_v<Variant>;
    static_assert(count < 255, "decode_variant: too many alternatives");
    const auto keys = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<int, count>{codec::key_of<std::variant_alternative_t<I, Variant>>(KeyOffset)...};
    }
    (std::make_index_sequence<count>{});
    std::array<std::uint8_t, 256> index{};
    index.fill(static_cast<std::uint8_t>(count));
    for (std::size_t i = 0; i < count; ++i) {
        if (keys[i] < 0) continue;
        auto& slot = index[static_cast<std::size_t>(keys[i])];
        if (slot != count)
            variant_alternatives_share_a_key(table_v<std::variant_alternative_t<0, Variant>>.name, keys[i]);
        slot = static_cast<std::uint8_t>(i);
    }
    return index;
}();

// The same as a list of (key, index) pairs, for ROBOWIRE_OPTIMIZE_SIZE: a
// short search instead of 256 bytes of flash.
template <class Variant, std::size_t KeyOffset>
inline constexpr auto key_list_v = [] {
    constexpr std::size_t count = std::variant_size_v<Variant>;
    constexpr std::size_t keyed = [] {
        std::size_t n = 0;
        for (std::size_t k = 0; k < 256; ++k) n += key_index_v<Variant, KeyOffset>[k] != count;
        return n;
    }();
    std::array<std::array<std::uint8_t, 2>, keyed> list{};
    std::size_t n = 0;
    for (std::size_t k = 0; k < 256; ++k)
        if (key_index_v<Variant, KeyOffset>[k] != count)
            list[n++] = {static_cast<std::uint8_t>(k), key_index_v<Variant, KeyOffset>[k]};
    return list;
}();
inline namespace ROBOWIRE_MODE_NAMESPACE {
// Index of the alternative whose key is `key` (variant_size: none).
template <class Variant, std::size_t KeyOffset>
constexpr std::size_t index_of_key(std::uint8_t key) noexcept {
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {
        for (const auto& entry : key_list_v<Variant, KeyOffset>)
            if (entry[0] == key) return entry[1];
        return std::variant_size_v<Variant>;
    } else {
        return key_index_v<Variant, KeyOffset>[key];
    }
}
// Makes alternative I of r's variant and decodes `in` into it (in place, or
// through a local: see alternative_via_local). Checked: fixed bytes and
// length checked already (see check_alternative); otherwise they are checked
// here (but the key) before the alternative is made, so that the fields'
// stores overwrite its member initialisers with no branch between and the
// compiler drops them (see decode()).
template <std::size_t I, std::size_t KeyOffset, bool Checked, class Variant>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_alternative(result<Variant>& r, in_bytes in) noexcept {
    using A = std::variant_alternative_t<I, Variant>;
    if constexpr (!Checked)
        if (!input_ok<KeyOffset, A>(r, in)) return;
    // The result is discarded on an error: one pass where two cost more
    // (less code; text walked once); else checked first, runs copied at once.
    constexpr bool one_pass = ROBOWIRE_OPTIMIZE_SIZE || has_text_or_tail<A>();
    if constexpr (alternative_via_local && !ROBOWIRE_OPTIMIZE_SIZE && flat_record_v<A>) {
        A local{};
        if (const error e = decode_body<A, true>(local, in); e.code != errc::ok) r = e;
        else codec::make_alternative<I>(r) = local;
    } else if (const error e = decode_body<A, one_pass, false, false>(codec::make_alternative<I>(r), in);
               e.code != errc::ok) {
        r = e;
    }
}
template <std::size_t KeyOffset, bool Checked, class Variant, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_index(result<Variant>& r, std::size_t index, in_bytes in,
                                                   std::index_sequence<I...>) noexcept {
    // false: no alternative has that index
    return ((index == I ? (decode_alternative<I, KeyOffset, Checked>(r, in), true) : false) || ...);
}

// The same for a key's index from key_index_v: one more case for an unknown
// key (variant_size), and no other value, so the jump table needs no range check.
template <std::size_t KeyOffset, class Variant, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_key_index(result<Variant>& r, std::size_t index, in_bytes in,
                                                       std::index_sequence<I...>) noexcept {
    (void)((index == I ? (decode_alternative<I, KeyOffset, false>(r, in), true) : false) || ... ||
           (index == sizeof...(I) ? (r = fail(errc::unknown_message, KeyOffset), true) : (unreachable(), false)));
}

// Input sizes (min, max) of each alternative, in flash: one length check for
// all of them under ROBOWIRE_OPTIMIZE_SIZE, instead of one per alternative.
// Bytes when every size fits (tables keep sizes below 65536).
template <class Variant>
struct size_limits;
template <class... M>
struct size_limits<std::variant<M...>> {
    using type = std::conditional_t<((table_v<M>.max_input() < 256) && ...), std::uint8_t, std::uint16_t>;
    static constexpr type value[sizeof...(M)][2] = {
        {static_cast<type>(table_v<M>.min_size()), static_cast<type>(table_v<M>.max_input())}...};
};
// The fixed bytes (but the key) and the length of alternative `index`, in
// decode_into's order: code only for alternatives with other fixed bytes.
template <class Variant, std::size_t KeyOffset, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr error check_alternative(std::size_t index, in_bytes in,
                                                         std::index_sequence<I...>) noexcept {
    error e{};
    (void)(((fixed_count_v<std::variant_alternative_t<I, Variant>> > 1 && index == I)
                ? (e = fixed_error<std::variant_alternative_t<I, Variant>, KeyOffset>(
                       in, std::make_index_sequence<fixed_count_v<std::variant_alternative_t<I, Variant>>>{}),
                   true)
                : false) ||
           ...);
    if (e.code != errc::ok) return e;
    const auto& size = size_limits<Variant>::value[index];
    if (in.size() < size[0]) return codec::fail_at(errc::too_short, in.size());
    if (in.size() > size[1]) return codec::fail_at(errc::too_long, size[1]);
    return e;
}
}  // namespace ROBOWIRE_MODE_NAMESPACE
}  // namespace detail

namespace detail::inline ROBOWIRE_MODE_NAMESPACE {
// Index of the smallest alternative: the cheapest value a variant can start
// with before the decoded alternative replaces it.
template <class Variant>
struct smallest_alternative;
template <class... M>
struct smallest_alternative<std::variant<M...>> {
    static constexpr std::size_t value = [] {
        constexpr std::size_t sizes[] = {sizeof(M)...};
        std::size_t best = 0;
        for (std::size_t i = 1; i < sizeof...(M); ++i)
            if (sizes[i] < sizes[best]) best = i;
        return best;
    }();
};
// decode_variant's work, inlined into the caller (out of line, one copy, under
// ROBOWIRE_OPTIMIZE_SIZE): the input as pointer and size (a span that an
// inlined caller passes on by value is copied through the stack first).
template <class Variant, std::size_t KeyOffset>
ROBOWIRE_SPEED_INLINE constexpr result<Variant> decode_variant_at(const std::uint8_t* data, std::size_t size) noexcept {
    const in_bytes in(data, size);
    // Set on every path below: the decoded alternative is built in place
    // (nothing stored or cleared first); under ROBOWIRE_OPTIMIZE_SIZE it starts
    // as the smallest alternative, replaced below.
    result<Variant> r = ROBOWIRE_OPTIMIZE_SIZE
                            ? result<Variant>{std::in_place, std::in_place_index<smallest_alternative<Variant>::value>}
                            : result<Variant>{codec::unset_t{}};
    constexpr auto all = std::make_index_sequence<std::variant_size_v<Variant>>{};
    if (in.size() <= KeyOffset) {
        r = fail(errc::too_short, in.size());
    } else if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {
        const std::size_t index = index_of_key<Variant, KeyOffset>(in[KeyOffset]);
        if (index == std::variant_size_v<Variant>) r = fail(errc::unknown_message, KeyOffset);
        else if (const error e = check_alternative<Variant, KeyOffset>(index, in, all); e.code != errc::ok) r = e;
        else decode_index<KeyOffset, true>(r, index, in, all);
    } else {
        // An unknown key is one more case of the jump table: no range check.
        const std::size_t index = index_of_key<Variant, KeyOffset>(in[KeyOffset]);
        decode_key_index<KeyOffset>(r, index, in, all);
    }
    return r;
}
}  // namespace detail::inline ROBOWIRE_MODE_NAMESPACE

inline namespace ROBOWIRE_MODE_NAMESPACE {
// Decodes `in` as the alternative of Variant whose fixed byte at KeyOffset
// matches (alternatives sharing a key do not compile); unknown_message (at KeyOffset) if
// none does, too_short if the input does not reach the key. The message is
// decoded in place, without copies.
template <class Variant, std::size_t KeyOffset = 0>
[[nodiscard]] ROBOWIRE_ALWAYS_INLINE constexpr result<Variant> decode_variant(
    std::span<const std::uint8_t> in) noexcept {
    return detail::decode_variant_at<Variant, KeyOffset>(in.data(), in.size());
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

namespace detail {
template <class Variant>
struct max_size_of;
template <class... M>
struct max_size_of<std::variant<M...>> {
    static constexpr std::size_t value = [] {
        std::size_t n = 0;
        ((n = max_size_v<M> > n ? max_size_v<M> : n), ...);
        return n;
    }();
};
}  // namespace detail
template <class Variant>
inline constexpr std::size_t variant_max_size_v = detail::max_size_of<Variant>::value;

namespace detail::inline ROBOWIRE_MODE_NAMESPACE {
// Encodes the alternative v holds into out_data (see encode_into);
// unknown_message (offset 0) for a valueless variant.
template <class Variant, class Written, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr error encode_held(const Variant& v, std::uint8_t* out_data, std::size_t out_size,
                                                   Written& written, std::index_sequence<I...>) noexcept {
    error e = fail(errc::unknown_message, 0);
    const std::size_t held = v.index();  // std::get, not get_if: see visit_held
    (void)((held == I ? (e = encode_into(std::get<I>(v), out_data, out_size, written), true) : false) || ...);
    return e;
}
}  // namespace detail::inline ROBOWIRE_MODE_NAMESPACE

inline namespace ROBOWIRE_MODE_NAMESPACE {
// Encodes whichever message the variant holds, into the largest buffer any
// needs. Errors: the message's; unknown_message (offset 0) for a variant left
// valueless by an exception.
template <class... M>
[[nodiscard]] constexpr result<bytes<variant_max_size_v<std::variant<M...>>>> encode(
    const std::variant<M...>& v) noexcept {
    using out_t = bytes<variant_max_size_v<std::variant<M...>>>;
    result<out_t> r = detail::in_place_result<out_t>();
    auto& b = codec::unchecked_value(r);  // each message is encoded straight into it
    const error e = detail::encode_held(v, b.data(), out_t::capacity(), b, std::index_sequence_for<M...>{});
    if (e.code != errc::ok) r = e;
    return r;
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire
