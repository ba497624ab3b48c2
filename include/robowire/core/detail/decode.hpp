// robowire/core/detail/decode.hpp - internal: the table-driven decoder,
// one inlined step per field; every offset and range is a template constant.
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../bits.hpp"
#include "../endian.hpp"
#include "../result.hpp"
#include "../table.hpp"
#include "access.hpp"
#include "lanes.hpp"

// Every step in the inline namespace of the size settings (config.hpp).
namespace robowire::detail::inline ROBOWIRE_MODE_NAMESPACE {

// ---- decode: ranges, sizes and kinds are template constants; byte offsets
// are arguments (constants again once inlined), so that each field is
// instantiated once, not once per array element or record position.
//
// Two passes: check_record finds the first error without writing anything;
// decode_record then writes the fields. Its error sink Err is `error` (every
// check made as the field is decoded: codec::decode_fields' callers' old
// contract) or `prechecked` (check_record passed: no check, and runs of
// fields whose wire bytes are their members' bytes are copied at once).

// The error sink of a write pass whose input check_record passed.
struct prechecked {};
// The range a write pass steps with: none checked, one step per field shape.
inline constexpr std::int64_t any_min = std::numeric_limits<std::int64_t>::min(),
                              any_max = std::numeric_limits<std::int64_t>::max();
// The same, into storage whose members are not initialised (see unset).
struct prechecked_unset {};
template <class Err>
inline constexpr bool checks_v = !std::is_same_v<Err, prechecked> && !std::is_same_v<Err, prechecked_unset>;
// The error sinks of a one-pass decode() under ROBOWIRE_OPTIMIZE_SIZE: `fresh`
// into a message made just before (an absent optional block is left as made,
// empty); `unset` into storage whose members are not initialised (every
// optional block is made here, empty or holding the decoded value).
struct fresh : error {
    using error::operator=;
};
struct unset : error {
    using error::operator=;
};
template <class Err>
inline constexpr bool fresh_v = std::is_same_v<Err, fresh>;
template <class Err>
inline constexpr bool unset_v = std::is_same_v<Err, unset> || std::is_same_v<Err, prechecked_unset>;
// The write-pass sink for the storage Err decodes into.
template <class Err>
using prechecked_t = std::conditional_t<unset_v<Err>, prechecked_unset, prechecked>;

// An optional made empty, or holding a value-initialised value, without
// reading its flag (its storage may be unset). Its value type is trivially
// destructible (a result's values are).
template <class O>
ROBOWIRE_ALWAYS_INLINE constexpr void make_empty(O& o) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) o.reset();
    else ::new (static_cast<void*>(&o)) O();
}
template <class O>
ROBOWIRE_ALWAYS_INLINE constexpr auto& make_engaged(O& o) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) return o.emplace();
    return **::new (static_cast<void*>(&o)) O(std::in_place);
}

// A number, enum, bool or float of wire type W, valid in [Min, Max]: shared
// by every field of the same kind and range (fewer functions to compile).
template <class W, std::int64_t Min, std::int64_t Max, class E, class Err>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_scalar(E& v, in_bytes in, std::size_t off, Err& err) noexcept {
    if constexpr (W::kind == wire_kind::f32le) {
        v = load_le<float>(in.data() + off);
        return true;
    } else {
        std::int64_t raw = 0;
        if constexpr (W::kind == wire_kind::bits)
            raw = get_bits(load_le<std::uint8_t>(in.data() + off), W::lo, W::width);
        else raw = load_le<typename W::raw_type>(in.data() + off);
        if constexpr (std::is_enum_v<E>) {
            const auto e = static_cast<E>(raw);
            if constexpr (checks_v<Err>) {
                if (!valid_enum(e)) [[unlikely]] {
                    err = codec::fail_at(errc::invalid_enum, off);
                    return false;
                }
            }
            v = e;
        } else {
            constexpr range full = [] {  // what the wire bytes can hold
                if constexpr (W::kind == wire_kind::bits) return range{0, low_mask(W::width)};
                else
                    return range{std::numeric_limits<typename W::raw_type>::min(),
                                 std::numeric_limits<typename W::raw_type>::max()};
            }();
            if constexpr (checks_v<Err> && (Min > full.min || Max < full.max)) {
                if (!in_range<Min, Max, full.min, full.max>(raw)) [[unlikely]] {
                    err = codec::fail_at(errc::value_out_of_range, off);
                    return false;
                }
            }
            if constexpr (std::is_same_v<E, bool>) v = raw != 0;
            else v = static_cast<E>(raw);
        }
        return true;
    }
}
// A text field of N bytes at `off`: its length (up to the first NUL), and
// whether every byte after it is a NUL (else bad_padding at the first that is not).
template <std::size_t N>
ROBOWIRE_ALWAYS_INLINE constexpr std::size_t text_length(in_bytes in, std::size_t off) noexcept {
    std::size_t len = 0;
    while (len < N && in[off + len] != 0) ++len;
    return len;
}
template <std::size_t N>
ROBOWIRE_ALWAYS_INLINE constexpr bool text_padding_ok(in_bytes in, std::size_t off, std::size_t len,
                                                      error& err) noexcept {
    for (std::size_t i = len; i < N; ++i)
        if (in[off + i] != 0) [[unlikely]] {
            err = codec::fail_at(errc::bad_padding, off + i);
            return false;
        }
    return true;
}
// Each step below is instantiated per field shape S (member and wire type:
// table.hpp) and valid range [Min, Max], not per field: fields of the same
// kind, in any message, share them. `off` is the field's byte offset in `in`.
template <class S, std::int64_t Min, std::int64_t Max, class E, class Err>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_element(E& v, in_bytes in, std::size_t off, Err& err) noexcept;

template <class M, class Err, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_record(M& m, in_bytes in, std::size_t base, Err& err,
                                                    std::index_sequence<I...>) noexcept;

template <class S, std::int64_t Min, std::int64_t Max, class V, class Err, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_array(V& v, in_bytes in, std::size_t off, Err& err,
                                                   std::index_sequence<K...>) noexcept {
    constexpr std::size_t es = S::element_size;
    if constexpr (decode_in_loop<S>()) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {  // one copy of the element's code, in a loop
            ROBOWIRE_NO_UNROLL
            for (std::size_t k = 0; k < sizeof...(K); ++k)
                if (!decode_element<S, Min, Max>(v[k], in, off + k * es, err)) return false;
            return true;
        }
    }
    return (decode_element<S, Min, Max>(v[K], in, off + K * es, err) && ...);
}

template <class S, std::int64_t Min, std::int64_t Max, class V, class Err>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_value(V& v, in_bytes in, std::size_t off, Err& err) noexcept {
    if constexpr (plain_byte_array_v<S, Min, Max>) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            std::memcpy(v.data(), in.data() + off, S::count);
            return true;
        }
    }
    if constexpr (S::is_array) return decode_array<S, Min, Max>(v, in, off, err, std::make_index_sequence<S::count>{});
    else return decode_element<S, Min, Max>(v, in, off, err);
}

template <class S, std::int64_t Min, std::int64_t Max, class Err>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_field(typename S::member_type& member, in_bytes in, std::size_t off,
                                                   Err& err) noexcept {
    if constexpr (S::is_optional) {
        if (in.size() <= off) {
            if constexpr (unset_v<Err>) make_empty(member);
            else if constexpr (!fresh_v<Err>) member.reset();
            return true;
        }  // absent
        if constexpr (checks_v<Err>) {
            if (in.size() < off + S::size) {
                err = codec::fail_at(errc::bad_length, off);
                return false;
            }
        }
        if constexpr (ROBOWIRE_OPTIMIZE_SIZE || (!checks_v<Err> && ROBOWIRE_COPY_RUNS)) {  // decoded in place
            if constexpr (unset_v<Err>) return decode_value<S, Min, Max>(make_engaged(member), in, off, err);
            else return decode_value<S, Min, Max>(member.emplace(), in, off, err);
        } else {
            value_t<typename S::member_type> tmp{};  // stored whole once decoded: the stores merge
            if (!decode_value<S, Min, Max>(tmp, in, off, err)) return false;
            member = tmp;
            return true;
        }
    } else if constexpr (!S::is_array && scalar_wire_v<typename S::wire_type>) {
        return decode_scalar<typename S::wire_type, Min, Max>(member, in, off, err);
    } else {
        return decode_value<S, Min, Max>(member, in, off, err);
    }
}

// ---- runs (ROBOWIRE_COPY_RUNS; access.hpp), the decode side: a run is
// copied from the input into the object at `obj`.

// (g++ cannot always see that a run past the end of a caller's buffer is
// reached only by a longer input, and warns.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overread"
#endif
ROBOWIRE_ALWAYS_INLINE void flush(unsigned char* obj, in_bytes in, const run& r) noexcept {
    if (r.size != 0) copy_run(obj + r.mem, in.data() + r.wire, r.size);
}
// flush, where the next field (a run, copied after this one, ending at
// next_end in the object) follows: on 64-bit hosts a run of 9..15 bytes is
// copied as 16 (one move, not two or three), its last bytes landing in
// padding or in memory the next run overwrites. Only where no field written
// before lies above the run and the input holds the 16 bytes (avail: bytes
// present; 0: never wider).
ROBOWIRE_ALWAYS_INLINE void flush_before(unsigned char* obj, in_bytes in, const run& r, std::size_t next_end,
                                         std::size_t avail) noexcept {
#if defined(__x86_64__) || defined(__aarch64__)
    if (!ROBOWIRE_OPTIMIZE_SIZE && r.size > 8 && r.size < 16 && r.below <= r.mem && r.mem + 16 <= next_end &&
        r.wire + 16 <= avail) {
        // A plain store, not memcpy: clang++ would cut a memcpy short where
        // the next run overwrites its end, and split it in two.
        using chunk [[gnu::vector_size(16), gnu::aligned(1), gnu::may_alias]] = unsigned char;
        chunk c;
        std::memcpy(&c, in.data() + r.wire, 16);
        *reinterpret_cast<chunk*>(obj + r.mem) = c;
        return;
    }
#else
    (void)next_end, (void)avail;
#endif
    flush(obj, in, r);
}
// r's fields are written: the next run starts above them.
ROBOWIRE_ALWAYS_INLINE void written(run& r, std::size_t end) noexcept {
    if (end > r.below) r.below = end;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
// A field at byte `wire`: joins the current run, starts one, or is decoded on
// its own (P: prechecked, or prechecked_unset for unset storage).
// avail: the input bytes a run may be widened into (flush_before; 0: none).
template <class S, class P>
ROBOWIRE_ALWAYS_INLINE void copy_or_decode(unsigned char* obj, typename S::member_type& member, in_bytes in,
                                           std::size_t wire, run& r, std::size_t avail = 0) noexcept {
    const std::size_t size = copy_size<S>(member);
    const std::size_t mem = offset_in(obj, &member);
    if (size != 0) {
        if (r.size != 0 && r.wire + r.size == wire && r.mem + r.size == mem) {
            r.size += size;
        } else {
            flush_before(obj, in, r, mem + size, avail);
            written(r, r.size != 0 ? r.mem + r.size : 0);
            r.wire = wire, r.mem = mem, r.size = size;
        }
    } else {
        flush(obj, in, r);
        written(r, r.size != 0 ? r.mem + r.size : 0);
        written(r, mem + sizeof(member));
        r.size = 0;
        P none{};
        (void)decode_field<S, any_min, any_max>(member, in, wire, none);
    }
}

// copy_or_decode for a pass that checks as it writes (one pass; its output is
// discarded on an error, so a run left pending then is never copied).
template <class S, std::int64_t Min, std::int64_t Max, class Err>
ROBOWIRE_ALWAYS_INLINE bool copy_or_check(unsigned char* obj, typename S::member_type& member, in_bytes in,
                                          std::size_t wire, run& r, Err& err) noexcept {
    if constexpr (unchecked_field<S, Min, Max>()) {
        copy_or_decode<S, prechecked_t<Err>>(obj, member, in, wire, r);
        return true;
    } else {
        flush(obj, in, r);
        r = {};
        return decode_field<S, Min, Max>(member, in, wire, err);
    }
}

template <class M, class Err, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_record(M& m, in_bytes in, std::size_t base, Err& err,
                                                    std::index_sequence<I...>) noexcept {
    (void)m, (void)in, (void)base, (void)err;  // messages without fields
    if constexpr (!checks_v<Err> && ROBOWIRE_COPY_RUNS) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            const auto obj = reinterpret_cast<unsigned char*>(&m);
            run r{};
            // Runs widened only where every member is a field (no other member in a gap).
            constexpr std::size_t min = decode_writes_every_member_v<M> ? table_v<M>.min_size() : 0;
            const std::size_t avail = min != 0 ? base + min : 0;
            (copy_or_decode<shape_t<M, I>, Err>(obj, m.*(field_v<M, I>.member), in, base + field_v<M, I>.offset, r,
                                                avail),
             ...);
            flush(obj, in, r);
            return true;
        }
    } else if constexpr (ROBOWIRE_OPTIMIZE_SIZE && ROBOWIRE_COPY_RUNS) {  // one pass: unchecked fields copied
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            const auto obj = reinterpret_cast<unsigned char*>(&m);
            run r{};
            if (!(copy_or_check<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>(
                      obj, m.*(field_v<M, I>.member), in, base + field_v<M, I>.offset, r, err) &&
                  ...))
                return false;
            flush(obj, in, r);
            return true;
        }
    }
    if constexpr (!checks_v<Err>) {  // no range checked: one step per shape, whatever its range
        return (decode_field<shape_t<M, I>, any_min, any_max>(m.*(field_v<M, I>.member), in,
                                                              base + field_v<M, I>.offset, err) &&
                ...);
    } else {
        return (decode_field<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>(
                    m.*(field_v<M, I>.member), in, base + field_v<M, I>.offset, err) &&
                ...);
    }
}

template <class S, std::int64_t Min, std::int64_t Max, class E, class Err>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_element(E& v, in_bytes in, std::size_t off, Err& err) noexcept {
    using W = typename S::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        if constexpr (ROBOWIRE_OPTIMIZE_SIZE || (!checks_v<Err> && ROBOWIRE_COPY_RUNS)) {  // in place
            return decode_record<E>(v, in, off, err, std::make_index_sequence<field_count_v<E>>{});
        } else {
            // Decoded into a local, then stored whole: the loads are not ordered
            // behind byte stores that might alias the input, so they merge.
            E tmp{};
            if (!decode_record<E>(tmp, in, off, err, std::make_index_sequence<field_count_v<E>>{})) return false;
            v = tmp;
            return true;
        }
    } else if constexpr (W::kind == wire_kind::text) {
        constexpr std::size_t n = text_traits<E>::size;
        const std::size_t len = text_length<n>(in, off);
        if constexpr (checks_v<Err>) {
            if (!text_padding_ok<n>(in, off, len, err)) return false;
        }
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {  // straight from the input (char may view any bytes)
            v.assign(std::string_view(reinterpret_cast<const char*>(in.data() + off), len));
            return true;
        }
        std::array<char, n> chars{};
        for (std::size_t i = 0; i < len; ++i) chars[i] = static_cast<char>(in[off + i]);
        v.assign(std::string_view(chars.data(), len));
        return true;
    } else if constexpr (W::kind == wire_kind::tail) {
        const std::size_t end = in.size() < off + S::size ? in.size() : off + S::size;
        v.clear();
        (void)v.append(std::span<const std::uint8_t>(in.data() + off, end > off ? end - off : 0));
        return true;
    } else {
        return decode_scalar<W, Min, Max>(v, in, off, err);
    }
}

// ---- check: the first error decode_record<M, error> would find, in the
// same order, without writing anything.
template <class M, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_record(in_bytes in, std::size_t base, error& err,
                                                   std::index_sequence<I...>) noexcept;
template <class S, std::int64_t Min, std::int64_t Max>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_element(in_bytes in, std::size_t off, error& err) noexcept {
    using E = typename S::element_type;
    using W = typename S::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        return check_record<E>(in, off, err, std::make_index_sequence<field_count_v<E>>{});
    } else if constexpr (W::kind == wire_kind::text) {
        constexpr std::size_t n = text_traits<E>::size;
        return text_padding_ok<n>(in, off, text_length<n>(in, off), err);
    } else if constexpr (W::kind == wire_kind::tail || W::kind == wire_kind::f32le) {
        return true;
    } else {
        E unused{};  // decode_scalar's checks; the store is dead
        return decode_scalar<W, Min, Max>(unused, in, off, err);
    }
}
template <class S, std::int64_t Min, std::int64_t Max, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_array(in_bytes in, std::size_t off, error& err,
                                                  std::index_sequence<K...>) noexcept {
    constexpr std::size_t es = S::element_size;
    if constexpr (decode_in_loop<S>()) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            ROBOWIRE_NO_UNROLL
            for (std::size_t k = 0; k < sizeof...(K); ++k)
                if (!check_element<S, Min, Max>(in, off + k * es, err)) return false;
            return true;
        }
    }
    return (check_element<S, Min, Max>(in, off + K * es, err) && ...);
}
template <class S, std::int64_t Min, std::int64_t Max>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_field(in_bytes in, std::size_t off, error& err) noexcept {
    if constexpr (S::is_optional) {
        if (in.size() - (off + 1) < S::size - 1) [[unlikely]] {  // one compare: off < size < off + S::size
            err = codec::fail_at(errc::bad_length, off);
            return false;
        }
        if (in.size() <= off) return true;  // absent
    }
    using W = typename S::wire_type;
    if constexpr (plain_byte_array_v<S, Min, Max>) {
        return true;
    } else if constexpr (S::is_array) {
        return check_array<S, Min, Max>(in, off, err, std::make_index_sequence<S::count>{});
    } else if constexpr (scalar_wire_v<W> && W::kind != wire_kind::f32le) {  // no step between
        typename S::element_type unused{};                                   // the store is dead
        return decode_scalar<W, Min, Max>(unused, in, off, err);
    } else {
        return check_element<S, Min, Max>(in, off, err);
    }
}
template <class M, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_record(in_bytes in, std::size_t base, error& err,
                                                   std::index_sequence<I...>) noexcept {
    (void)in, (void)base, (void)err;  // messages without fields
    return (check_field<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>(
                in, base + field_v<M, I>.offset, err) &&
            ...);
}

// No byte offset (check_fixed: no fixed byte is skipped).
inline constexpr std::size_t no_offset = static_cast<std::size_t>(-1);
// Is the fixed byte K of M (not the one at offset Skip) in `in` and wrong? Then e is its error.
template <class M, std::size_t Skip, std::size_t K>
ROBOWIRE_ALWAYS_INLINE constexpr bool fixed_wrong(in_bytes in, error& e) noexcept {
    constexpr auto fixed = table_v<M>.fixed[K];
    if constexpr (fixed.offset == Skip) {
        return false;
    } else {
        const bool wrong = fixed.offset < in.size() && in[fixed.offset] != fixed.value;
        if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {
            if (wrong) {
                e = {fixed.code, fixed.offset};
                return true;
            }
        } else if (wrong) [[unlikely]] {  // the error is set in the branch, not before the compare
            e = {fixed.code, fixed.offset};
            return true;
        }
        return false;
    }
}
// The first fixed byte of M among K... (but the one at offset Skip) that `in`
// has and gets wrong, as an error (code ok if none): codec::check_fixed.
template <class M, std::size_t Skip, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr error fixed_error(in_bytes in, std::index_sequence<K...>) noexcept {
    error e{};
    (void)(fixed_wrong<M, Skip, K>(in, e) || ...);
    return e;
}
}  // namespace robowire::detail::inline ROBOWIRE_MODE_NAMESPACE
