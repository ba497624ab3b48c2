// robowire/core/detail/encode.hpp - internal: the table-driven encoder, in
// two passes (check every field, then store them all).
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
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

// ---- encode, in two passes: check every field (the first error wins), then
// write them all without a branch, so that the stores can merge.

// Checks and stores of a number, enum, bool or float of wire type W, valid in
// [Min, Max]: shared by every field of the same kind and range.
template <class W, std::int64_t Min, std::int64_t Max, class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_scalar(const E& v, std::size_t off, auto& err) noexcept {
    if constexpr (W::kind == wire_kind::f32le) {
        return true;
    } else if constexpr (std::is_enum_v<E>) {
        if (!valid_enum(v)) [[unlikely]] {
            err = codec::fail_at(errc::invalid_enum, off);
            return false;
        }
        return true;
    } else {
        if constexpr (W::kind == wire_kind::bits || std::is_same_v<E, bool> ||
                      Min > std::int64_t{std::numeric_limits<E>::min()} ||
                      Max < std::int64_t{std::numeric_limits<E>::max()}) {
            constexpr std::int64_t lo = std::numeric_limits<E>::min(), hi = std::numeric_limits<E>::max();
            bool valid = true;
            if constexpr (Max >= hi) valid = static_cast<std::int64_t>(v) >= Min;  // one bound: one compare
            else if constexpr (Min <= lo) valid = static_cast<std::int64_t>(v) <= Max;
            else valid = in_range<Min, Max, lo, hi>(static_cast<std::int64_t>(v));
            if (!valid) [[unlikely]] {
                err = codec::fail_at(errc::value_out_of_range, off);
                return false;
            }
        }
        return true;
    }
}
template <class W, class E>
ROBOWIRE_ALWAYS_INLINE constexpr void store_scalar(const E& v, out_bytes out, std::size_t off) noexcept {
    if constexpr (W::kind == wire_kind::f32le) {
        store_le<float>(out.data() + off, v);
    } else {
        std::uint64_t raw = 0;
        if constexpr (std::is_enum_v<E>) raw = static_cast<std::uint64_t>(static_cast<std::underlying_type_t<E>>(v));
        else raw = static_cast<std::uint64_t>(v);
        if constexpr (W::kind == wire_kind::bits) {
            constexpr auto mask = static_cast<unsigned>(low_mask(W::width) << W::lo);
            out[off] = static_cast<std::uint8_t>((static_cast<unsigned>(out[off]) & ~mask) |
                                                 ((static_cast<unsigned>(raw) << W::lo) & mask));
        } else {
            store_le<typename W::raw_type>(out.data() + off, static_cast<typename W::raw_type>(raw));
        }
    }
}

// Each step below is instantiated per field shape S (member and wire type:
// table.hpp) and valid range [Min, Max] (checks) or way of storing (stores),
// not per field. `off` is the field's byte offset in the output.
template <class S, std::int64_t Min, std::int64_t Max, class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_element(const E& v, std::size_t off, auto& err) noexcept;

template <class M, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_record(const M& m, std::size_t base, auto& err,
                                                   std::index_sequence<I...>) noexcept;

template <class S, std::int64_t Min, std::int64_t Max, class V, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_array(const V& v, std::size_t off, auto& err,
                                                  std::index_sequence<K...>) noexcept {
    constexpr std::size_t es = S::element_size;
    if constexpr (encode_in_loop<S>()) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            ROBOWIRE_NO_UNROLL
            for (std::size_t k = 0; k < sizeof...(K); ++k)
                if (!check_element<S, Min, Max>(v[k], off + k * es, err)) return false;
            return true;
        }
    }
    return (check_element<S, Min, Max>(v[K], off + K * es, err) && ...);
}

template <class S, std::int64_t Min, std::int64_t Max, class V>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_value(const V& v, std::size_t off, auto& err) noexcept {
    if constexpr (S::is_array) return check_array<S, Min, Max>(v, off, err, std::make_index_sequence<S::count>{});
    else return check_element<S, Min, Max>(v, off, err);
}

template <class S, std::int64_t Min, std::int64_t Max>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_field(const typename S::member_type& member, std::size_t off,
                                                  auto& err) noexcept {
    if constexpr (S::is_optional) return !member || check_value<S, Min, Max>(*member, off, err);
    else if constexpr (!S::is_array && scalar_wire_v<typename S::wire_type>)
        return check_scalar<typename S::wire_type, Min, Max>(member, off, err);
    else return check_value<S, Min, Max>(member, off, err);
}

template <class M, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_record(const M& m, std::size_t base, auto& err,
                                                   std::index_sequence<I...>) noexcept {
    (void)m, (void)base, (void)err;  // messages without fields
    return (check_field<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>(
                m.*(field_v<M, I>.member), base + field_v<M, I>.offset, err) &&
            ...);
}

template <class S, std::int64_t Min, std::int64_t Max, class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_element(const E& v, std::size_t off, auto& err) noexcept {
    using W = typename S::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        return check_record<E>(v, off, err, std::make_index_sequence<field_count_v<E>>{});
    } else if constexpr (W::kind == wire_kind::text) {
        const auto s = v.view();
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s[i] == '\0') {
                err = codec::fail_at(errc::value_out_of_range, off + i);
                return false;
            }
        return true;
    } else if constexpr (W::kind == wire_kind::tail) {
        return true;
    } else {
        return check_scalar<W, Min, Max>(v, off, err);
    }
}

#if ROBOWIRE_SSE2
// Do the members of the fields in Mask (bit I: field I, below 64) lie as
// their wire bytes, `base` bytes on (object offset = base + wire offset,
// modulo 2^N)? (A constant once inlined.)
template <class M, std::uint64_t Mask, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE bool members_as_wire(const M& m, std::size_t base, std::index_sequence<I...>) noexcept {
    const auto obj = reinterpret_cast<const unsigned char*>(&m);
    return ((I >= 64 || (Mask >> (I % 64) & 1) == 0 ||
             offset_in(obj, &(m.*(field_v<M, I>.member))) == base + field_v<M, I>.offset) &&
            ...);
}
#endif
// M's fields in m checked, in table order: the first error, or errc::ok. Out
// of line under ROBOWIRE_OPTIMIZE_SIZE: decode (copy_then_check_v) and encode
// of a message share it.
template <class M>
ROBOWIRE_SIZE_NOINLINE constexpr error check_members(const M& m) noexcept {
    error err{};
    (void)check_record<M>(m, 0, err, std::make_index_sequence<field_count_v<M>>{});
    return err;
}

// Whether a checked array of shape S valid in [Min, Max] is stored whole,
// unless it would be a memcpy call under ROBOWIRE_OPTIMIZE_SIZE.
template <class S, std::int64_t Min, std::int64_t Max>
inline constexpr bool store_whole_v = plain_byte_array_v<S, Min, Max> || (!ROBOWIRE_OPTIMIZE_SIZE && byte_array_v<S>);

template <class S, class E>
ROBOWIRE_ALWAYS_INLINE constexpr void store_element(const E& v, out_bytes out, std::size_t off) noexcept;

template <class M, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void store_record(const M& m, out_bytes out, std::size_t base,
                                                   std::index_sequence<I...>) noexcept;

template <class S, class V, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr void store_array(const V& v, out_bytes out, std::size_t off,
                                                  std::index_sequence<K...>) noexcept {
    constexpr std::size_t es = S::element_size;
    if constexpr (encode_in_loop<S>()) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            ROBOWIRE_NO_UNROLL
            for (std::size_t k = 0; k < sizeof...(K); ++k) store_element<S>(v[k], out, off + k * es);
            return;
        }
    }
    (store_element<S>(v[K], out, off + K * es), ...);
}

template <class S, bool Whole, class V>
ROBOWIRE_ALWAYS_INLINE constexpr void store_value(const V& v, out_bytes out, std::size_t off) noexcept {
    if constexpr (Whole) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            std::memcpy(out.data() + off, v.data(), S::count);
            return;
        }
    }
    if constexpr (S::is_array) store_array<S>(v, out, off, std::make_index_sequence<S::count>{});
    else store_element<S>(v, out, off);
}

template <class S, bool Whole>
ROBOWIRE_ALWAYS_INLINE constexpr void store_field(const typename S::member_type& member, out_bytes out,
                                                  std::size_t off) noexcept {
    if constexpr (S::is_optional) {
        if (member) store_value<S, Whole>(*member, out, off);
    } else if constexpr (!S::is_array && scalar_wire_v<typename S::wire_type>) {
        store_scalar<typename S::wire_type>(member, out, off);
    } else {
        store_value<S, Whole>(member, out, off);
    }
}

// ---- runs (ROBOWIRE_COPY_RUNS; access.hpp), the encode side: a run is
// copied from the object at `obj` into the output.
ROBOWIRE_ALWAYS_INLINE void store_run(const unsigned char* obj, out_bytes out, const run& r) noexcept {
    if (r.size != 0) copy_run(out.data() + r.wire, obj + r.mem, r.size);
}
// A field at byte `wire`: joins the current run, starts one, or is stored on its own.
template <class S, bool Whole>
ROBOWIRE_ALWAYS_INLINE void copy_or_store(const unsigned char* obj, const typename S::member_type& member,
                                          out_bytes out, std::size_t wire, run& r) noexcept {
    const std::size_t size = copy_size<S>(member);
    if (size != 0) {
        const std::size_t mem = offset_in(obj, &member);
        if (r.size != 0 && r.wire + r.size == wire && r.mem + r.size == mem) {
            r.size += size;
        } else {
            store_run(obj, out, r);
            r = {wire, mem, size};
        }
    } else {
        store_run(obj, out, r);
        r = {};
        store_field<S, Whole>(member, out, wire);
    }
}

template <class M, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void store_record(const M& m, out_bytes out, std::size_t base,
                                                   std::index_sequence<I...>) noexcept {
    (void)m, (void)out, (void)base;  // messages without fields
    if constexpr (ROBOWIRE_COPY_RUNS) {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            const auto obj = reinterpret_cast<const unsigned char*>(&m);
            run r{};
            (copy_or_store<shape_t<M, I>,
                           store_whole_v<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>>(
                 obj, m.*(field_v<M, I>.member), out, base + field_v<M, I>.offset, r),
             ...);
            store_run(obj, out, r);
            return;
        }
    }
    (store_field<shape_t<M, I>, store_whole_v<shape_t<M, I>, field_v<M, I>.valid.min, field_v<M, I>.valid.max>>(
         m.*(field_v<M, I>.member), out, base + field_v<M, I>.offset),
     ...);
}

// Writes one checked element.
template <class S, class E>
ROBOWIRE_ALWAYS_INLINE constexpr void store_element(const E& v, out_bytes out, std::size_t off) noexcept {
    using W = typename S::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        store_record<E>(v, out, off, std::make_index_sequence<field_count_v<E>>{});
    } else if constexpr (W::kind == wire_kind::text) {
        const auto s = v.view();
        for (std::size_t i = 0; i < s.size(); ++i) out[off + i] = static_cast<std::uint8_t>(s[i]);
        for (std::size_t i = s.size(); i < text_traits<E>::size; ++i) out[off + i] = 0;  // padding
    } else if constexpr (W::kind == wire_kind::tail) {
        for (std::size_t i = 0; i < v.size(); ++i) out[off + i] = v[i];
    } else {
        store_scalar<W>(v, out, off);
    }
}

// Bytes the encoding of m takes (optional blocks present, tail length), or
// missing_field when an optional block is present but an earlier one is not.
template <class M, std::size_t... I>
constexpr result<std::size_t> encoded_size(const M& m, std::index_sequence<I...>) noexcept {
    if constexpr (!((field_t<M, I>::is_optional || field_t<M, I>::kind == wire_kind::tail) || ... || false)) {
        (void)m;
        return min_size_v<M>;  // every field always there: one size
    } else {
        std::size_t size = min_size_v<M>;
        std::size_t first_absent = 0;
        bool absent_seen = false;
        bool missing = false;
        auto one = [&](auto index) {
            constexpr std::size_t i = decltype(index)::value;
            constexpr const auto& f = field_v<M, i>;
            using F = field_t<M, i>;
            constexpr auto member_ptr = f.member;
            if constexpr (F::is_optional) {
                if (!(m.*member_ptr)) {
                    if (!absent_seen) {
                        absent_seen = true;
                        first_absent = f.offset;
                    }
                } else if (absent_seen) {
                    missing = true;
                } else if (f.end() > size) {
                    size = f.end();
                }
            } else if constexpr (F::kind == wire_kind::tail) {
                const std::size_t end = f.offset + (m.*member_ptr).size();
                if (end > size) size = end;
            }
        };
        (one(std::integral_constant<std::size_t, I>{}), ...);
        (void)one;
        if (missing) return fail(errc::missing_field, first_absent);
        return size;
    }
}

template <class M, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr void write_fixed(out_bytes out, std::index_sequence<K...>) noexcept {
    ((out[table_v<M>.fixed[K].offset] = table_v<M>.fixed[K].value), ...);
}

// Bytes that encoding sets to zero before writing the fields: reserved bytes
// and bytes holding bit fields (those are or-ed in). A fold per message and
// a step per field shape (no function per field type).
template <class M, std::size_t... I>
constexpr void mark_bit_bytes(bool* clear, std::size_t base, std::index_sequence<I...>) noexcept;
template <class S>
constexpr void mark_bit_bytes(bool* clear, std::size_t at) noexcept {
    if constexpr (S::kind == wire_kind::bits) {
        for (std::size_t k = 0; k < S::count; ++k) clear[at + k * S::element_size] = true;
    } else if constexpr (S::kind == wire_kind::record) {
        using E = typename S::element_type;
        for (std::size_t k = 0; k < S::count; ++k)
            mark_bit_bytes<E>(clear, at + k * S::element_size, std::make_index_sequence<field_count_v<E>>{});
    } else {
        (void)clear, (void)at;
    }
}
template <class M, std::size_t... I>
constexpr void mark_bit_bytes(bool* clear, std::size_t base, std::index_sequence<I...>) noexcept {
    (void)clear, (void)base;
    (mark_bit_bytes<shape_t<M, I>>(clear, base + field_v<M, I>.offset), ...);
}
template <class M>
constexpr std::array<bool, max_size_v<M>> cleared_bytes() noexcept {
    auto clear = reserved_bytes<M>();
    mark_bit_bytes<M>(clear.data(), 0, std::make_index_sequence<field_count_v<M>>{});
    return clear;
}
template <class M>
inline constexpr auto cleared_bytes_v = cleared_bytes<M>();

// The offsets of those bytes, in order.
template <class M>
inline constexpr auto cleared_offsets_v = [] {
    constexpr std::size_t n = [] {
        std::size_t k = 0;
        for (bool c : cleared_bytes_v<M>) k += c;
        return k;
    }();
    std::array<std::size_t, n> offsets{};
    std::size_t k = 0;
    for (std::size_t i = 0; i < cleared_bytes_v<M>.size(); ++i)
        if (cleared_bytes_v<M>[i]) offsets[k++] = i;
    return offsets;
}();

// Zeroes the cleared bytes that `out` has (one store per byte).
template <class M, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr void clear_bytes(out_bytes out, std::index_sequence<K...>) noexcept {
    (void)out;
    ((cleared_offsets_v<M>[K] < out.size() ? (void)(out[cleared_offsets_v<M>[K]] = 0) : void()), ...);
}
template <class M>
ROBOWIRE_ALWAYS_INLINE constexpr void clear_bytes(out_bytes out) noexcept {
    clear_bytes<M>(out, std::make_index_sequence<cleared_offsets_v<M>.size()>{});
}

}  // namespace robowire::detail::inline ROBOWIRE_MODE_NAMESPACE
