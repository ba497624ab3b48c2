// robowire/core/decode.hpp - decode a message from bytes, driven by its table.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <utility>

#include "detail/decode.hpp"
#include "detail/encode.hpp"
#include "result.hpp"
#include "table.hpp"

namespace robowire {

// reserved_not_zero at the first reserved byte of `in` that is not zero.
template <class M>
[[nodiscard]] constexpr result<std::size_t> check_reserved(std::span<const std::uint8_t> in) noexcept {
    constexpr auto reserved = reserved_bytes<M>();
    for (std::size_t i = 0; i < in.size() && i < reserved.size(); ++i)
        if (reserved[i] && in[i] != 0) return fail(errc::reserved_not_zero, i);
    return in.size();
}

namespace codec::inline ROBOWIRE_MODE_NAMESPACE {
// The first fixed byte of M among K... (indices into table_v<M>.fixed) that
// `in` has and gets wrong, as an error (code ok if none); bytes past the end
// of `in` are not checked. Skip: the offset of a fixed byte not to check
// (matched by a dispatcher already).
template <class M, std::size_t Skip = detail::no_offset, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr error check_fixed(std::span<const std::uint8_t> in,
                                                   std::index_sequence<K...> fixed) noexcept {
    return detail::fixed_error<M, Skip>(in, fixed);
}

}  // namespace codec::inline ROBOWIRE_MODE_NAMESPACE

namespace detail::inline ROBOWIRE_MODE_NAMESPACE {
// too_short (at the input's end) or too_long (at the largest size); out of
// line, so that the good path sets up no error.
ROBOWIRE_COLD constexpr error length_error(std::size_t size, std::size_t min, std::size_t max) noexcept {
    return size < min ? codec::fail_at(errc::too_short, size) : codec::fail_at(errc::too_long, max);
}
// Where decode(), decode_into() and decode_variant() build the message, the
// faster way for each compiler (bench/run --instructions): in a local, copied
// out once decoded (no load waits behind a store to the output, which may
// alias the input, and no member initialiser is stored before a check), or
// in the output itself. clang++: a message in a local, a variant's
// alternative in place; g++ the other way round (it copies a whole message
// member by member). Through a local only if decoding writes every member
// (decode_writes_every_member_v; for an alternative, flat_record_v).
#if defined(__clang__)
inline constexpr bool message_via_local = !ROBOWIRE_COPY_RUNS, alternative_via_local = false;
#else
inline constexpr bool message_via_local = false, alternative_via_local = true;
#endif
// decode() under ROBOWIRE_OPTIMIZE_SIZE makes the message (its member
// initialisers) before decoding into it, unless the decode writes every
// member (optional blocks made as they are decoded).
template <class M, bool = ROBOWIRE_OPTIMIZE_SIZE != 0>
inline constexpr bool made_first_v = false;
template <class M>
inline constexpr bool made_first_v<M, true> = !flat_record<M, true>();
// M counts its trailing bytes (tail_block_v) and its last field is an
// optional block from min_size to max_size (BuWizz3's status).
template <class M, std::size_t Last = field_count_v<M> - 1>
constexpr bool tail_block() noexcept {
    if constexpr (field_count_v<M> == 0) return false;
    else if constexpr (!shape_t<M, Last>::is_optional) return false;
    else
        return field_v<M, Last>.offset == table_v<M>.min_size() &&
               field_v<M, Last>.offset + shape_t<M, Last>::size == table_v<M>.max_size();
}
template <class M, bool = reports_trailing<M>>  // worked out only for those
inline constexpr bool tail_block_v = false;
template <class M>
inline constexpr bool tail_block_v<M, true> = tail_block<M>();
// Such a message's fields: those before the block, then one length test finds
// the block and each branch stores its own trailing count, as a hand writes
// it (a count stored after the branches is tested again, or reached by a
// jump). `in` holds at least min_size bytes; Err prechecked (the write pass):
// min_size, or max_size or more (checked already).
template <class M, class Err>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_with_tail(M& out, in_bytes in, Err& err) noexcept {
    constexpr std::size_t min = table_v<M>.min_size(), max = table_v<M>.max_size(), last = field_count_v<M> - 1;
    constexpr auto& f = field_v<M, last>;
    using S = shape_t<M, last>;
    if (!decode_record<M>(out, in_bytes(in.data(), min), 0, err, std::make_index_sequence<last>{})) return false;
    if (in.size() > min) {  // the block, whole once checked
        if constexpr (checks_v<Err>) {
            if (in.size() < max) {
                err = codec::fail_at(errc::bad_length, min);
                return false;
            }
        }
        if (!decode_field<S, f.valid.min, f.valid.max>(out.*(f.member), in_bytes(in.data(), max), min, err))
            return false;
        out.ignored_trailing_bytes = in.size() - max;
    } else {  // no block
        (void)decode_field<S, f.valid.min, f.valid.max>(out.*(f.member), in_bytes(in.data(), min), min, err);
        out.ignored_trailing_bytes = 0;
    }
    return true;
}
// The write pass: M's fields from an input whose fixed bytes, length and
// fields are checked (check_record); no branch (but a tail block's length
// test: decode_with_tail), runs copied at once.
// P: prechecked, or prechecked_unset for unset storage.
template <class M, class P = prechecked>
ROBOWIRE_ALWAYS_INLINE constexpr void write_body(M& out, in_bytes in) noexcept {
    constexpr std::size_t extent = table_v<M>.max_size();
    P none{};
    if constexpr (tail_block_v<M>) {
        (void)decode_with_tail<M>(out, in, none);
    } else {
        (void)decode_record<M>(out, in.size() > extent ? in.first(extent) : in, 0, none,
                               std::make_index_sequence<field_count_v<M>>{});
        if constexpr (reports_trailing<M>) out.ignored_trailing_bytes = in.size() > extent ? in.size() - extent : 0;
    }
}
// The first field of `in` (fixed bytes and length checked) that fails its
// check, in table order (one does).
template <class M>
ROBOWIRE_COLD constexpr error input_field_error(const std::uint8_t* data, std::size_t size) noexcept {
    error err{};
    (void)check_record<M>(in_bytes(data, size), 0, err, std::make_index_sequence<field_count_v<M>>{});
    return err;
}
#if ROBOWIRE_SSE2
// decode<M> stores the message from its test's register (decoded_image_v).
template <class M>
constexpr bool decoded_image_ok() noexcept {
    if constexpr (!ROBOWIRE_OPTIMIZE_SIZE && field_count_v<M> >= lanes_min_fields && flat_record_v<M> &&
                  !reports_trailing<M>)
        return decoded_image_v<M> >= 0;
    return false;
}
// Do m's members lie in wire order from the first field's wire offset on
// (object offset = wire offset - that offset)? (A constant once inlined.)
template <class M>
ROBOWIRE_ALWAYS_INLINE bool members_from_first(const M& m) noexcept {
    constexpr std::size_t first = static_cast<std::size_t>(decoded_image_v<M>) + lanes_v<M, false>.win[0].at[0];
    return members_as_wire<M, ~std::uint64_t{0}>(m, std::size_t{0} - first,
                                                 std::make_index_sequence<field_count_v<M>>{});
}
#endif
// Whether check_input's vector test checks M's fixed bytes (none known), so
// that input_ok checks the length only.
template <std::size_t Known, class M>
constexpr bool fixed_in_lanes() noexcept {
#if ROBOWIRE_SSE2
    if constexpr (Known == no_offset && !ROBOWIRE_OPTIMIZE_SIZE && field_count_v<M> >= lanes_min_fields)
        return lanes_v<M, false>.use && lanes_v<M, false>.fixed_in;
#endif
    return false;
}
template <std::size_t Known, class M>
inline constexpr bool fixed_in_lanes_v = fixed_in_lanes<Known, M>();
// The first error of an input, for a message whose vector test holds its
// fixed bytes (fixed_in_lanes_v): a fixed byte's, the length's, else a
// field's. One cold function for both of its tests (input_ok's, check_input's).
template <class M>
ROBOWIRE_COLD constexpr error fixed_or_field_error(const std::uint8_t* data, std::size_t size) noexcept {
    const in_bytes in(data, size);
    if (const error e = fixed_error<M, no_offset>(in, std::make_index_sequence<fixed_count_v<M>>{}); e.code != errc::ok)
        return e;
    if (size < min_size_v<M> || size > table_v<M>.max_input())
        return length_error(size, min_size_v<M>, table_v<M>.max_input());
    return input_field_error<M>(data, size);
}
// The check pass: every field of `in` valid, else false with the first error
// in err. Speed: the checks as one yes/no, which one failed found out of line
// (no error code or offset set up on the good path).
template <class M, bool YesNo = true>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_input(in_bytes in, error& err) noexcept {
    constexpr auto fields = std::make_index_sequence<field_count_v<M>>{};
    if constexpr (unchecked_record<M>(fields)) {
        (void)in, (void)err;
        return true;
    } else if constexpr (ROBOWIRE_OPTIMIZE_SIZE || !YesNo) {
        return check_record<M>(in, 0, err, fields);
    } else {
        error unread{};  // its stores are dead: dropped
#if ROBOWIRE_SSE2
        if constexpr (field_count_v<M> >= lanes_min_fields) {
            if constexpr (lanes_v<M, false>.use) {  // the one-byte fields' ranges as one vector test (lanes.hpp)
                if (!ROBOWIRE_CONSTANT_EVALUATED()) {
                    constexpr const lane_plan& p = lanes_v<M, false>;  // `in` holds min_size_v<M> bytes
                    if (plan_valid<p>(in.data(), 0) &&
                        check_record<M>(in, 0, unread, kept_fields_t<lanes_v<M, false>.covered, field_count_v<M>>{}))
                        [[likely]]
                        return true;
                    if constexpr (p.fixed_in) err = fixed_or_field_error<M>(in.data(), in.size());
                    else err = input_field_error<M>(in.data(), in.size());
                    return false;
                }
            }
        }
#endif
        if (check_record<M>(in, 0, unread, fields)) [[likely]]
            return true;
        err = input_field_error<M>(in.data(), in.size());
        return false;
    }
}
// The fields of M, from an input whose fixed bytes and length are checked.
// OnePass false: every field is checked before the first is written, so on
// an error `out` is left as it was, and runs of fields are copied at once.
// OnePass true: each field checked as it is written (less code), for an
// output that is discarded on an error (a local, a result being built).
// Fresh (with OnePass): `out` was made just before (made_first_v), so absent
// optional blocks are empty already, or its storage is unset.
// YesNo: see check_input (the dispatchers pass false: fewer instructions there).
template <class M, bool OnePass = false, bool Fresh = false, bool YesNo = true>
ROBOWIRE_ALWAYS_INLINE constexpr error decode_body(M& out, in_bytes in) noexcept {
    constexpr std::size_t extent = table_v<M>.max_size();
    constexpr auto fields = std::make_index_sequence<field_count_v<M>>{};
    std::conditional_t<OnePass && Fresh, std::conditional_t<made_first_v<M>, fresh, unset>, error> err{};
    if constexpr (OnePass && copy_then_check_v<M>) {  // every field copied, then checked as encode checks
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            write_body<M, prechecked_t<decltype(err)>>(out, in);
            return check_members(out);
        }
    }
    if constexpr (OnePass && tail_block_v<M>) {
        if (!decode_with_tail<M>(out, in, err)) return err;
        return {};
    }
    if constexpr (OnePass) {
        const auto known = in.size() > extent ? in.first(extent) : in;
        if (!decode_record<M>(out, known, 0, err, fields)) return err;
        if constexpr (reports_trailing<M>) out.ignored_trailing_bytes = in.size() - known.size();
        return {};  // a constant, not err: compilers then build no error on the good path
    }
    if (!check_input<M, YesNo>(in, err)) return err;  // reads the first `extent` bytes only
    write_body(out, in);
    return {};
}
}  // namespace detail::inline ROBOWIRE_MODE_NAMESPACE

namespace codec::inline ROBOWIRE_MODE_NAMESPACE {
// M's fields from `in`, without the fixed-byte and length checks: for
// dispatchers that have checked both already (`in` holds at least
// max_size_v<M> bytes). Returns the first field error, or errc::ok.
// On an error, nothing is written to `out` (under ROBOWIRE_OPTIMIZE_SIZE, in
// one pass with less code, fields may be: for an output that is discarded on
// an error, such as a dispatcher's result).
template <described M>
ROBOWIRE_ALWAYS_INLINE constexpr error decode_fields(M& out, std::span<const std::uint8_t> in) noexcept {
    return detail::decode_body<M, ROBOWIRE_OPTIMIZE_SIZE, false, false>(out,
                                                                        detail::in_bytes(in.data(), max_size_v<M>));
}
// Tag of decode_fields' form for an output discarded on an error.
struct discarded_on_error_t {
    explicit discarded_on_error_t() = default;
};
inline constexpr discarded_on_error_t discarded_on_error{};
// As decode_fields, for an output discarded on an error (a dispatcher's
// result): on an error `out` may hold some fields. Less code to compile: a
// message whose fields take every value of their wire bytes is written in
// one pass, with no check; under ROBOWIRE_OPTIMIZE_SIZE, every message.
template <described M>
ROBOWIRE_ALWAYS_INLINE constexpr error decode_fields(M& out, std::span<const std::uint8_t> in,
                                                     discarded_on_error_t) noexcept {
    const detail::in_bytes known(in.data(), max_size_v<M>);
    constexpr auto fields = std::make_index_sequence<detail::field_count_v<M>>{};
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {
        return detail::decode_body<M, true, false, false>(out, known);
    } else if constexpr (!detail::reports_trailing<M> && detail::unchecked_record<M>(fields)) {
        detail::prechecked none{};
        (void)detail::decode_record<M>(out, known, 0, none, fields);
        return {};
    } else {
        return detail::decode_body<M, false, false, false>(out, known);
    }
}
}  // namespace codec::inline ROBOWIRE_MODE_NAMESPACE

namespace detail::inline ROBOWIRE_MODE_NAMESPACE {
// The error of an input that fails input_ok's test: the first wrong fixed
// byte `in` has, else the length's. Out of line (the good path sets up no error).
template <std::size_t Known, class M>
ROBOWIRE_COLD constexpr error input_error(const std::uint8_t* data, std::size_t size) noexcept {
    const in_bytes in(data, size);
    if (const error e = fixed_error<M, Known>(in, std::make_index_sequence<fixed_count_v<M>>{}); e.code != errc::ok)
        return e;
    constexpr std::size_t max = table_v<M>.max_input();
    return length_error(size, min_size_v<M>, max);
}
// Whether every fixed byte of M but the one at offset Known lies within the
// shortest input: then one test of the length and the bytes finds every error.
constexpr bool fixed_within(const fixed_byte* fixed, std::size_t n, std::size_t known, std::size_t min) noexcept {
    for (std::size_t i = 0; i < n; ++i)
        if (fixed[i].offset != known && fixed[i].offset >= min) return false;
    return true;
}
template <std::size_t Known, class M>
inline constexpr bool fixed_within_min_v = fixed_within(table_v<M>.fixed.data(), fixed_count_v<M>, Known,
                                                        table_v<M>.min_size());
// The fixed bytes of M but the one at offset Known, as words of the shortest
// input (ROBOWIRE_COPY_RUNS targets), each compared on its own as a careful
// hand-written decoder compares its markers: a word of fixed bytes only is
// one compare with memory (x86-64: `cmp $imm, mem`), others are masked. As few
// words as cover the bytes, each narrowed to the bytes it covers (OSP's
// voltage: FF AA 02 12 as 4 bytes, 55 77 as 2).
// Worked out by plain functions (one definition for every message: cheaper
// to compile than a lambda and a local type per message).
struct fixed_word {
    std::size_t start = 0, width = 0;
    std::uint64_t mask = 0, value = 0;
};
inline constexpr std::size_t max_fixed_words = 16;  // messages with more fixed bytes compare them one by one
struct fixed_words {
    fixed_word w[max_fixed_words]{};
    std::size_t count = 0;
};
// Words of up to `width` bytes covering fixed[0..n) but the byte at offset
// `known`, each within the first `min` bytes and narrowed to the bytes it covers.
constexpr fixed_words cover_fixed(const fixed_byte* fixed, std::size_t n, std::size_t known, std::size_t min,
                                  std::size_t width) noexcept {
    fixed_words r{};
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t at = fixed[i].offset;
        if (at == known) continue;
        bool covered = false;
        for (std::size_t k = 0; k < r.count; ++k)
            covered = covered || (at >= r.w[k].start && at < r.w[k].start + width);
        if (!covered) r.w[r.count++].start = at + width <= min ? at : min - width;
    }
    for (std::size_t k = 0; k < r.count; ++k) {
        // Narrowed to the fixed bytes it covers (a whole word compares with memory).
        std::size_t lo = min, hi = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t at = fixed[i].offset;
            if (at != known && at >= r.w[k].start && at < r.w[k].start + width) {
                lo = at < lo ? at : lo;
                hi = at > hi ? at : hi;
            }
        }
        std::size_t w = 1;
        while (w < hi - lo + 1) w *= 2;
        r.w[k].width = w;
        r.w[k].start = lo + w <= min ? lo : min - w;
    }
    for (std::size_t k = 0; k < r.count; ++k)
        for (std::size_t i = 0; i < n; ++i)
            if (fixed[i].offset != known && fixed[i].offset >= r.w[k].start &&
                fixed[i].offset < r.w[k].start + r.w[k].width) {
                const auto shift = 8 * (fixed[i].offset - r.w[k].start);
                r.w[k].mask |= std::uint64_t{0xFF} << shift;
                r.w[k].value |= std::uint64_t{fixed[i].value} << shift;
            }
    return r;
}
constexpr fixed_words make_fixed_words(const fixed_byte* fixed, std::size_t n, std::size_t known,
                                       std::size_t min) noexcept {
    const std::size_t widest = min >= 8 ? 8 : min >= 4 ? 4 : min >= 2 ? 2 : 1;
    const std::size_t most = cover_fixed(fixed, n, known, min, widest).count;
    std::size_t width = widest;
    for (std::size_t w = widest / 2; w >= 1 && cover_fixed(fixed, n, known, min, w).count == most; w /= 2) width = w;
    return cover_fixed(fixed, n, known, min, width);
}
template <std::size_t Known, class M>
inline constexpr fixed_words fixed_words_v = make_fixed_words(table_v<M>.fixed.data(), fixed_count_v<M>, Known,
                                                              table_v<M>.min_size());
// Word K of fixed_words_v<Known, M> matches `in`: one compare, with memory
// where the word is whole (x86-64: an immediate operand).
template <std::size_t Known, class M, std::size_t K>
ROBOWIRE_ALWAYS_INLINE bool fixed_word_match(const std::uint8_t* in) noexcept {
    constexpr auto& word_k = fixed_words_v<Known, M>.w[K];
    using word = typename uint_of_size<word_k.width>::type;
    word w = 0;
    std::memcpy(&w, in + word_k.start, word_k.width);
    constexpr auto mask = static_cast<word>(word_k.mask), value = static_cast<word>(word_k.value);
    if constexpr (mask == static_cast<word>(~word{0})) return w == value;
    else return static_cast<word>(w & mask) == value;
}
template <std::size_t Known, class M, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE bool fixed_words_match(const std::uint8_t* in, std::index_sequence<K...>) noexcept {
    (void)in;  // no fixed byte left to compare
    return (fixed_word_match<Known, M, K>(in) && ...);
}
// The fixed bytes of M but the one at offset Known, all compared: as words where the target loads them
// (fixed_words_match), else byte by byte with no branch between them; `in` holds them all.
template <std::size_t Known, class M, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr bool fixed_match(in_bytes in, std::index_sequence<K...>) noexcept {
    if constexpr (ROBOWIRE_COPY_RUNS && std::endian::native == std::endian::little &&
                  fixed_count_v<M> < max_fixed_words) {
        if (!ROBOWIRE_CONSTANT_EVALUATED())
            return fixed_words_match<Known, M>(in.data(), std::make_index_sequence<fixed_words_v<Known, M>.count>{});
    }
    unsigned diff = 0;
    ((diff |=
      table_v<M>.fixed[K].offset == Known ? 0u : unsigned(in[table_v<M>.fixed[K].offset] ^ table_v<M>.fixed[K].value)),
     ...);
    return diff == 0;
}
// M's fixed bytes but the one at offset Known, which a dispatcher has matched
// already (no_offset: every fixed byte is checked), then the input's length.
// On a failure makes r (an error, or a result) hold the error and returns false.
template <std::size_t Known, class M, class R>
ROBOWIRE_ALWAYS_INLINE constexpr bool input_ok(R& r, in_bytes in) noexcept {
    constexpr std::size_t min = table_v<M>.min_size(), max = table_v<M>.max_input();
    constexpr bool in_lanes = fixed_in_lanes_v<Known, M>;
    if constexpr (in_lanes) {  // the fixed bytes in check_input's vector test (at run time)
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            if (in.size() - min <= max - min) [[likely]]
                return true;
            r = fixed_or_field_error<M>(in.data(), in.size());
            return false;
        }
    }
    if constexpr (!in_lanes && fixed_within_min_v<Known, M> &&
                  !ROBOWIRE_OPTIMIZE_SIZE) {  // size: no cold function per message
        if (in.size() - min <= max - min && fixed_match<Known, M>(in, std::make_index_sequence<fixed_count_v<M>>{}))
            [[likely]]
            return true;
        r = input_error<Known, M>(in.data(), in.size());
        return false;
    } else {
        if (const error e = fixed_error<M, Known>(in, std::make_index_sequence<fixed_count_v<M>>{});
            e.code != errc::ok) {
            r = e;
            return false;
        }
        if (in.size() < min || in.size() > max) [[unlikely]] {
            r = length_error(in.size(), min, max);
            return false;
        }
        return true;
    }
}
// decode_into without the check of the fixed byte at offset Known.
template <std::size_t Known, class M, bool Keep = true>
ROBOWIRE_ALWAYS_INLINE constexpr error decode_checked(M& out, in_bytes in) noexcept {
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {  // no call, each error returned as found: smaller code
        constexpr std::size_t min = table_v<M>.min_size(), max = table_v<M>.max_input();
        if (const error e = fixed_error<M, Known>(in, std::make_index_sequence<fixed_count_v<M>>{}); e.code != errc::ok)
            return e;
        if (in.size() < min) return codec::fail_at(errc::too_short, in.size());
        if (in.size() > max) return codec::fail_at(errc::too_long, max);
    } else if (error e{}; !input_ok<Known, M>(e, in)) {
        return e;
    }
    return decode_body < M, ROBOWIRE_OPTIMIZE_SIZE && !Keep, !Keep > (out, in);
}
// decode_into's work, out of line: the input as pointer and size (a span that an
// inlined caller passes on by value is copied through the stack first). Keep:
// `out` is left as it was on an error (decode_into; decode() builds a result).
template <class M, bool Keep = true>
constexpr error decode_raw(M& out, const std::uint8_t* data, std::size_t size) noexcept {
    if constexpr (message_via_local && !ROBOWIRE_OPTIMIZE_SIZE && decode_writes_every_member_v<M>) {
        M local{};
        const error e = decode_checked<no_offset>(local, in_bytes(data, size));
        if (e.code == errc::ok) out = local;
        return e;
    } else {
        return decode_checked<no_offset, M, Keep>(out, in_bytes(data, size));
    }
}
}  // namespace detail::inline ROBOWIRE_MODE_NAMESPACE

namespace codec::inline ROBOWIRE_MODE_NAMESPACE {
// Every fixed byte of M is right in `in` (which holds at least
// table_v<M>.min_size() bytes): the bytes as words, one compare each, where
// the target loads unaligned little-endian words (ROBOWIRE_COPY_RUNS).
template <described M>
ROBOWIRE_ALWAYS_INLINE constexpr bool fixed_bytes_match(std::span<const std::uint8_t> in) noexcept {
    return detail::fixed_match<detail::no_offset, M>(in, std::make_index_sequence<detail::fixed_count_v<M>>{});
}
}  // namespace codec::inline ROBOWIRE_MODE_NAMESPACE

inline namespace ROBOWIRE_MODE_NAMESPACE {

// Decodes `in` into `out` (an existing object, e.g. one refreshed 20 times a
// second): the same checks as decode(); returns errc::ok or the error. On an
// error, `out` is left exactly as it was.
template <described M>
[[nodiscard]] ROBOWIRE_ALWAYS_INLINE constexpr error decode_into(M& out, std::span<const std::uint8_t> in) noexcept {
    return detail::decode_raw(out, in.data(), in.size());
}

// Decodes a message of type M from `in`; every length, fixed byte, range and
// enum is checked, and the error says what and at which byte offset.
template <described M>
[[nodiscard]] constexpr result<M> decode(std::span<const std::uint8_t> in) noexcept {
    // Built in place: every return returns r, declared here (from an inner
    // scope g++ 12 copies it out). Speed: the message is made once the input
    // passed its checks, so that the fields' stores overwrite its member
    // initialisers with no branch between and the compiler drops them.
    // Size: decode_into's code, into a message made first (with no
    // initialiser stored where the decode writes every member).
    constexpr bool made = detail::made_first_v<M>;
    result<M> r = made ? detail::in_place_result<M>() : result<M>(codec::unset_t{});
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {
        M& v = made ? codec::unchecked_value(r) : detail::build_unset(r);
        if (const error e = detail::decode_raw<M, false>(v, in.data(), in.size()); e.code != errc::ok) r = e;
        return r;
    } else {
        if (!detail::input_ok<detail::no_offset, M>(r, in)) return r;
        if (error e{}; !detail::check_input<M>(in, e)) {
            r = e;  // checked before the message is made: nothing to undo
            return r;
        }
#if ROBOWIRE_SSE2 && UINTPTR_MAX > 0xFFFFFFFFu
        if constexpr (detail::decoded_image_ok<M>()) {  // the message from the test's register
            if (!ROBOWIRE_CONSTANT_EVALUATED()) {
                M& v = detail::build_unset(r);
                if (detail::members_from_first(v)) {
                    // r's storage (its first member) is 16 bytes or more on a 64-bit host (result.hpp)
                    detail::store_decoded<M>(reinterpret_cast<unsigned char*>(&r), in.data(),
                                             std::make_index_sequence<16>{});
                    return r;
                }
                detail::write_body(v, in);
                return r;
            }
        }
#endif
        if constexpr (detail::message_via_local && detail::decode_writes_every_member_v<M>) {
            M local{};
            detail::write_body(local, in);
            detail::build_value(r, local);
        } else if constexpr (detail::flat_record_v<M>) {  // every member written: no initialiser stored first
            detail::write_body(detail::build_unset(r), in);
        } else {
            detail::write_body(detail::build_default(r), in);
        }
        return r;
    }
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

namespace codec::inline ROBOWIRE_MODE_NAMESPACE {
// decode<M>, with the input as pointer and size: for a codec that calls a
// decode from several places, so that where the compiler keeps it out of line
// its callers pass two registers (a span passed by value is copied through
// the stack first).
template <described M>
[[nodiscard]] constexpr result<M> decode_at(const std::uint8_t* data, std::size_t size) noexcept {
    return robowire::decode<M>(std::span<const std::uint8_t>(data, size));
}
}  // namespace codec::inline ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire
