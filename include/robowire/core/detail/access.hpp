// robowire/core/detail/access.hpp - internal: a table's fields and fixed
// bytes as compile-time constants, for the encoder and the decoder.
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <type_traits>

#include "../table.hpp"

namespace robowire::detail {

// The codec's steps take bytes as these views rather than std::span: their
// members are always inlined, so g++ folds each step where it is inlined
// (a span's data() and size() stay calls inside always-inlined code).
struct in_bytes {
    const std::uint8_t* p = nullptr;
    std::size_t n = 0;
    template <std::size_t E>
    ROBOWIRE_ALWAYS_INLINE constexpr in_bytes(std::span<const std::uint8_t, E> s) noexcept : p(s.data()), n(s.size()) {}
    ROBOWIRE_ALWAYS_INLINE constexpr in_bytes(const std::uint8_t* data, std::size_t size) noexcept : p(data), n(size) {}
    ROBOWIRE_ALWAYS_INLINE constexpr const std::uint8_t* data() const noexcept { return p; }
    ROBOWIRE_ALWAYS_INLINE constexpr std::size_t size() const noexcept { return n; }
    ROBOWIRE_ALWAYS_INLINE constexpr std::uint8_t operator[](std::size_t i) const noexcept { return p[i]; }
    ROBOWIRE_ALWAYS_INLINE constexpr in_bytes first(std::size_t k) const noexcept { return {p, k}; }
};
struct out_bytes {
    std::uint8_t* p = nullptr;
    std::size_t n = 0;
    template <std::size_t E>
    ROBOWIRE_ALWAYS_INLINE constexpr out_bytes(std::span<std::uint8_t, E> s) noexcept : p(s.data()), n(s.size()) {}
    ROBOWIRE_ALWAYS_INLINE constexpr out_bytes(std::uint8_t* data, std::size_t size) noexcept : p(data), n(size) {}
    ROBOWIRE_ALWAYS_INLINE constexpr std::uint8_t* data() const noexcept { return p; }
    ROBOWIRE_ALWAYS_INLINE constexpr std::size_t size() const noexcept { return n; }
    ROBOWIRE_ALWAYS_INLINE constexpr std::uint8_t& operator[](std::size_t i) const noexcept { return p[i]; }
    ROBOWIRE_ALWAYS_INLINE constexpr out_bytes first(std::size_t k) const noexcept { return {p, k}; }
};

// lo <= v <= hi, for a v known to lie in [full_lo, full_hi] (the decoder): in 32
// bits when that range fits (on a 32-bit core a 64-bit compare is several
// instructions), bounds clamped to it.
template <std::int64_t Lo, std::int64_t Hi, std::int64_t FullLo, std::int64_t FullHi>
ROBOWIRE_ALWAYS_INLINE constexpr bool in_range(std::int64_t v) noexcept {
    constexpr std::int64_t lo = Lo > FullLo ? Lo : FullLo, hi = Hi < FullHi ? Hi : FullHi;
    if constexpr (lo > hi) {  // no value the wire can hold is valid
        (void)v;
        return false;
    } else if constexpr (FullLo >= std::numeric_limits<std::int32_t>::min() &&
                         FullHi <= std::numeric_limits<std::int32_t>::max()) {
        // one unsigned compare: v - lo wraps above hi - lo when v < lo
        const auto d = static_cast<std::uint32_t>(static_cast<std::int32_t>(v)) - static_cast<std::uint32_t>(lo);
        return d <= static_cast<std::uint32_t>(hi - lo);
    } else if constexpr (FullLo >= 0 && FullHi <= std::numeric_limits<std::uint32_t>::max()) {  // a u32 wire value
        return static_cast<std::uint32_t>(v) - static_cast<std::uint32_t>(lo) <= static_cast<std::uint32_t>(hi - lo);
    } else {
        return static_cast<std::uint64_t>(v) - static_cast<std::uint64_t>(lo) <= static_cast<std::uint64_t>(hi - lo);
    }
}

template <class M>
concept reports_trailing = requires(M m) {
    m.ignored_trailing_bytes = std::size_t{};
};

// Field I of M's table, as a compile-time constant.
template <class M, std::size_t I>
inline constexpr const auto& field_v = table_v<M>.fields.template get<I>();
template <class M>
inline constexpr std::size_t field_count_v = std::remove_cvref_t<decltype(table_v<M>.fields)>::size;
template <class M, std::size_t I>
using field_t = std::remove_cvref_t<decltype(field_v<M, I>)>;
template <class M>
inline constexpr std::size_t fixed_count_v = table_v<M>.fixed.size();

// Wire type W holds one number, enum, bool or float (not a record, text or tail).
template <class W>
inline constexpr bool scalar_wire_v =
    W::kind != wire_kind::record&& W::kind != wire_kind::text&& W::kind != wire_kind::tail;

inline namespace ROBOWIRE_MODE_NAMESPACE {
// Whether array field F is coded as one element's code in a loop (ROBOWIRE_ARRAY_LOOPS).
template <class F>
constexpr bool decode_in_loop() noexcept {
    if constexpr (ROBOWIRE_ARRAY_LOOPS == 1) return F::count >= 2;
    else if constexpr (ROBOWIRE_ARRAY_LOOPS == 2) return F::count >= 4 && F::kind != wire_kind::record;
    else return false;
}
template <class F>
constexpr bool encode_in_loop() noexcept {
    return ROBOWIRE_ARRAY_LOOPS != 0 && F::count >= 2;
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

// Field I of M's shape (member and wire type: table.hpp): the per-field
// steps of the codec are instantiated per shape and range, not per field.
template <class M, std::size_t I>
using shape_t = typename field_t<M, I>::shape;

// An array of at least 2 one-byte integers whose wire bytes are their memory
// bytes (shape S): stored whole once checked (one copy at run time, not under
// ROBOWIRE_OPTIMIZE_SIZE).
template <class S>
inline constexpr bool byte_array_v = [] {
    using E = typename S::element_type;
    if constexpr (!S::is_array || S::count < 2 || std::is_enum_v<E> || std::is_same_v<E, bool> || sizeof(E) != 1 ||
                  !std::is_integral_v<E>) {
        return false;
    } else {
        return S::kind == wire_kind::u8 || S::kind == wire_kind::i8;
    }
}();
// Such an array of at least 4 valid in [Min, Max] that needs no validation:
// also decoded whole, and stored whole under ROBOWIRE_OPTIMIZE_SIZE too.
template <class S, std::int64_t Min, std::int64_t Max>
inline constexpr bool plain_byte_array_v = [] {
    if constexpr (!byte_array_v<S> || S::count < 4) {
        return false;
    } else {
        using E = typename S::element_type;
        return Min <= std::numeric_limits<E>::min() && Max >= std::numeric_limits<E>::max();
    }
}();

// Two fields name the same member (member pointers of different types never do).
template <class P, class Q>
constexpr bool same_member(P p, Q q) noexcept {
    if constexpr (std::is_same_v<P, Q>) return p == q;
    else return false;
}
template <class M, std::size_t A, std::size_t... I>
constexpr bool names_again(std::index_sequence<I...>) noexcept {
    return ((A < I && same_member(field_v<M, A>.member, field_v<M, I>.member)) || ...);
}
template <class M, std::size_t... I>
constexpr bool distinct_members(std::index_sequence<I...> all) noexcept {
    (void)all;  // messages without fields
    return (!names_again<M, I>(all) && ...);
}
// Decoding M writes every member: M is a standard-layout aggregate (no
// base with members, no constructor), its fields name distinct members, and
// none is outside the table but ignored_trailing_bytes, which decode sets.
// A decoder may then skip the member initialisers, or decode into a local
// and copy it whole into the output (see message_via_local).
template <class M>
constexpr bool decode_writes_every_member() noexcept {
    if constexpr (!std::is_aggregate_v<M> || !std::is_standard_layout_v<M>) return false;
    else if constexpr (table_v<M>.members_not_on_wire != (reports_trailing<M> ? 1u : 0u)) return false;
    else return distinct_members<M>(std::make_index_sequence<field_count_v<M>>{});
}
template <class M>
inline constexpr bool decode_writes_every_member_v = decode_writes_every_member<M>();
// M has no optional (unless Optionals), text or tail field, nor a record that
// has one, and decoding writes every member: each member is at a fixed place
// and written by a decode (which may then skip the member initialisers, or go
// through a local: see alternative_via_local). An optional block is written
// whole by a decode (made empty, or made and decoded).
template <class M, bool Optionals = false>
constexpr bool flat_record() noexcept;
template <class M, std::size_t I, bool Optionals>
constexpr bool flat_field() noexcept {
    using F = field_t<M, I>;
    if constexpr (F::is_optional) return Optionals;
    else if constexpr (F::kind == wire_kind::text || F::kind == wire_kind::tail) return false;
    else if constexpr (F::kind == wire_kind::record) return flat_record<typename F::element_type, Optionals>();
    else return true;
}
template <class M, bool Optionals>
constexpr bool flat_record() noexcept {
    return decode_writes_every_member_v<M>&&[]<std::size_t... I>(std::index_sequence<I...>) {
        return (flat_field<M, I, Optionals>() && ...);
    }
    (std::make_index_sequence<field_count_v<M>>{});
}
template <class M>
inline constexpr bool flat_record_v = flat_record<M>();
// M has a text or tail field (directly or in a record): a decode that checks
// before it writes walks those bytes twice.
template <class M>
constexpr bool has_text_or_tail() noexcept;
template <class M, std::size_t I>
constexpr bool field_has_text_or_tail() noexcept {
    using F = field_t<M, I>;
    if constexpr (F::kind == wire_kind::text || F::kind == wire_kind::tail) return true;
    else if constexpr (F::kind == wire_kind::record) return has_text_or_tail<typename F::element_type>();
    else return false;
}
template <class M, std::size_t... I>
constexpr bool any_text_or_tail(std::index_sequence<I...>) noexcept {
    return (field_has_text_or_tail<M, I>() || ... || false);
}
template <class M>
constexpr bool has_text_or_tail() noexcept {
    return any_text_or_tail<M>(std::make_index_sequence<field_count_v<M>>{});
}

// ---- runs (ROBOWIRE_COPY_RUNS, at run time; decode and encode): fields
// whose wire bytes are their members' bytes, next to each other on the wire
// and in memory, are copied at once. Member offsets are taken from the
// object: constants once inlined, so the tests fold away and each run is one
// memcpy of a constant size; the code stays correct if they do not.

// A scalar of wire type W whose wire bytes are the bytes of an E holding it
// (the value is checked already): same size, no conversion, host order.
template <class W, class E>
inline constexpr bool same_bytes_v = [] {
    if constexpr (!scalar_wire_v<W> || W::kind == wire_kind::bits || std::is_same_v<E, bool>) return false;
    else if constexpr (W::kind == wire_kind::f32le) return std::is_same_v<E, float> && sizeof(float) == 4;
    else if constexpr (!std::is_integral_v<E> && !std::is_enum_v<E>) return false;
    else if constexpr (sizeof(E) != sizeof(typename W::raw_type)) return false;
    else return sizeof(E) == 1 || std::endian::native == std::endian::little;
}();
struct run {
    std::size_t wire = 0, mem = 0, size = 0;  // byte offsets in the input and in the object; 0: no run
    std::size_t below = 0;                    // the end (object offset) of every field written before this run
};
// Copies a run of n bytes (a constant once inlined). Where words cannot be
// loaded unaligned (Cortex-M0+, RV32), a short run byte by byte: a few loads and
// stores instead of a library call.
ROBOWIRE_ALWAYS_INLINE void copy_run(unsigned char* to, const unsigned char* from, std::size_t n) noexcept {
#if (defined(__arm__) && !defined(__ARM_FEATURE_UNALIGNED)) || (defined(__riscv) && !defined(__riscv_misaligned_fast))
    if (n <= 4) {
        for (std::size_t k = 0; k < n; ++k) to[k] = from[k];
        return;
    }
#endif
    std::memcpy(to, from, n);
}
ROBOWIRE_ALWAYS_INLINE std::size_t offset_in(const void* object, const void* member) noexcept {
    return static_cast<std::size_t>(static_cast<const unsigned char*>(member) -
                                    static_cast<const unsigned char*>(object));
}
template <class E>
ROBOWIRE_ALWAYS_INLINE std::size_t record_copy_size(const E& e) noexcept;
// A member of shape S copied as bytes: its size on the wire, or 0 if it is not a copy.
template <class S>
ROBOWIRE_ALWAYS_INLINE std::size_t copy_size(const typename S::member_type& member) noexcept {
    using E = typename S::element_type;
    if constexpr (S::is_optional) {
        (void)member;
        return 0;
    } else if constexpr (S::kind == wire_kind::record) {
        const auto& first = [&]() -> const E& {
            if constexpr (S::is_array) return member[0];
            else return member;
        }();
        const std::size_t n = record_copy_size(first);
        if constexpr (S::is_array) return n == sizeof(E) && S::element_size == sizeof(E) ? S::count * sizeof(E) : 0;
        else return n == S::element_size ? n : 0;
    } else if constexpr (same_bytes_v<typename S::wire_type, E>) {
        (void)member;
        return S::count * sizeof(E);
    } else {
        (void)member;
        return 0;
    }
}
// A record E copied as bytes: the end of its last field, if every member is a
// field copied as bytes at its own wire offset; else 0.
template <class E>
ROBOWIRE_ALWAYS_INLINE std::size_t record_copy_size(const E& e) noexcept {
    if constexpr (!decode_writes_every_member_v<E> || reports_trailing<E>) {
        return 0;
    } else {
        return [&]<std::size_t... J>(std::index_sequence<J...>) {
            constexpr std::size_t covered = (field_t<E, J>::size + ... + 0);  // no byte between the fields
            std::size_t end = 0;
            const bool all = ((copy_size<shape_t<E, J>>(e.*(field_v<E, J>.member)) == field_t<E, J>::size &&
                               offset_in(&e, &(e.*(field_v<E, J>.member))) == field_v<E, J>.offset &&
                               ((end = end > field_v<E, J>.offset + field_t<E, J>::size
                                           ? end
                                           : field_v<E, J>.offset + field_t<E, J>::size),
                                true)) &&
                              ...);
            return all && end == covered ? end : 0;
        }
        (std::make_index_sequence<field_count_v<E>>{});
    }
}

// Is a field of shape S valid in [Min, Max] decoded with no check (every
// value of its wire bytes valid: full-range integers, floats, records of such
// fields)? Then a pass that checks as it writes may copy it too.
template <class S, std::int64_t Min, std::int64_t Max>
constexpr bool unchecked_field() noexcept;
template <class E, std::size_t... J>
constexpr bool unchecked_record(std::index_sequence<J...>) noexcept {
    return (unchecked_field<shape_t<E, J>, field_v<E, J>.valid.min, field_v<E, J>.valid.max>() && ...);
}
template <class S, std::int64_t Min, std::int64_t Max>
constexpr bool unchecked_field() noexcept {
    using E = typename S::element_type;
    using W = typename S::wire_type;
    if constexpr (S::is_optional) {
        return false;
    } else if constexpr (S::kind == wire_kind::record) {
        return unchecked_record<E>(std::make_index_sequence<field_count_v<E>>{});
    } else if constexpr (!scalar_wire_v<W> || std::is_enum_v<E> || !same_bytes_v<W, E>) {
        return false;
    } else if constexpr (W::kind == wire_kind::f32le) {
        return true;
    } else {
        using raw = typename W::raw_type;
        return Min <= std::numeric_limits<raw>::min() && Max >= std::numeric_limits<raw>::max();
    }
}
// A field that a one-pass decode may copy and check afterwards on its member
// (check_members, shared with encode): its checks on the member are its
// checks on the wire bytes (same bytes, same signedness), or it has none.
template <class S, std::int64_t Min, std::int64_t Max>
constexpr bool check_after_copy() noexcept {
    using E = typename S::element_type;
    using W = typename S::wire_type;
    if constexpr (unchecked_field<S, Min, Max>()) return true;
    else if constexpr (S::is_optional || S::kind == wire_kind::record || !scalar_wire_v<W>) return false;
    else if constexpr (!same_bytes_v<W, E>) return false;
    else if constexpr (std::is_enum_v<E>) return true;
    else return std::is_same_v<E, typename W::raw_type>;
}
inline constexpr std::size_t shared_check_min = 3;  // checked fields for one shared check function
template <class M, std::size_t... I>
constexpr bool copy_then_check(std::index_sequence<I...>) noexcept {
    constexpr bool all = (check_after_copy<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>() && ...);
    constexpr std::size_t checked =
        ((unchecked_field<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>() ? 0 : 1) + ... + 0);
    return all && checked >= shared_check_min;
}
inline namespace ROBOWIRE_MODE_NAMESPACE {
// Under ROBOWIRE_OPTIMIZE_SIZE with ROBOWIRE_COPY_RUNS, for a message with
// several checked fields: its one-pass decode copies every field, then
// checks the message with check_members, the function encode checks it with
// (one copy of the checks in a program).
// (Worked out only in those settings: nothing to compile otherwise.)
template <class M, bool = (ROBOWIRE_OPTIMIZE_SIZE != 0) && (ROBOWIRE_COPY_RUNS != 0)>
inline constexpr bool copy_then_check_v = false;
template <class M>
inline constexpr bool copy_then_check_v<M, true> = copy_then_check<M>(std::make_index_sequence<field_count_v<M>>{});
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire::detail
