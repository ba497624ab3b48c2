// robowire/core/table.hpp - field tables and the generic table-driven codec.
//
// A message is a plain struct of raw wire values plus one constexpr table,
// found by ADL:   constexpr auto table_of(std::type_identity<Msg>);
// The table lists fixed bytes (command, markers) and fields (name, member,
// offset, wire type, valid range, unit). robowire::encode / decode are driven
// by it, so codec and table cannot disagree; tools read the same table.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "bits.hpp"
#include "bytes.hpp"
#include "endian.hpp"
#include "result.hpp"
#include "text.hpp"

namespace robowire {

// What a field looks like on the wire.
enum class wire_kind : std::uint8_t { u8, i8, u16le, i16le, u32le, i32le, f32le, bits, text, tail, record };

constexpr std::string_view to_string(wire_kind k) noexcept {
    switch (k) {
    case wire_kind::u8: return "u8";
    case wire_kind::i8: return "i8";
    case wire_kind::u16le: return "u16le";
    case wire_kind::i16le: return "i16le";
    case wire_kind::u32le: return "u32le";
    case wire_kind::i32le: return "i32le";
    case wire_kind::f32le: return "f32le";
    case wire_kind::bits: return "bits";
    case wire_kind::text: return "text";
    case wire_kind::tail: return "tail";
    case wire_kind::record: return "record";
    }
    return "?";
}

// Wire type tags used in tables.
namespace wire {
template <class Raw, wire_kind K>
struct scalar {
    using raw_type = Raw;
    static constexpr wire_kind kind = K;
};
using u8 = scalar<std::uint8_t, wire_kind::u8>;
using i8 = scalar<std::int8_t, wire_kind::i8>;
using u16le = scalar<std::uint16_t, wire_kind::u16le>;
using i16le = scalar<std::int16_t, wire_kind::i16le>;
using u32le = scalar<std::uint32_t, wire_kind::u32le>;
using i32le = scalar<std::int32_t, wire_kind::i32le>;
using f32le = scalar<float, wire_kind::f32le>;
// Bits [Lo, Lo+Width) of one byte; several bits fields may share a byte.
template <unsigned Lo, unsigned Width>
struct bits {
    static_assert(Width >= 1 && Lo + Width <= 8);
    static constexpr wire_kind kind = wire_kind::bits;
    static constexpr unsigned lo = Lo, width = Width;
};
// text<N> member: N bytes, NUL-padded.
struct text { static constexpr wire_kind kind = wire_kind::text; };
// bytes<N> member: every byte from the offset to the end of the input.
struct tail { static constexpr wire_kind kind = wire_kind::tail; };
// A struct member with a table of its own (no fixed bytes).
struct record { static constexpr wire_kind kind = wire_kind::record; };
}  // namespace wire

// Valid raw range, inclusive.
struct range {
    std::int64_t min;
    std::int64_t max;
};

// Physical unit: physical = raw * scale + offset. Empty name: no unit.
struct unit {
    std::string_view name{};
    double scale = 1.0;
    double offset = 0.0;
};

// A byte every instance of a message has (command, marker); `code` is the
// error reported when it differs.
struct fixed_byte {
    std::size_t offset;
    std::uint8_t value;
    errc code;
};

// Enumerations: tables found by ADL, constexpr auto enum_table_of(std::type_identity<E>)
// returning std::array<enum_entry<E>, K>.
template <class E>
struct enum_entry {
    E value;
    std::string_view name;
};
template <class E>
inline constexpr auto enum_table_v = enum_table_of(std::type_identity<E>{});

template <class E>
[[nodiscard]] constexpr bool is_valid_enum(E e) noexcept {
    for (const auto& entry : enum_table_v<E>)
        if (entry.value == e) return true;
    return false;
}
// Name of an enumerator ("" if not a valid code).
template <class E>
[[nodiscard]] constexpr std::string_view enum_name(E e) noexcept {
    for (const auto& entry : enum_table_v<E>)
        if (entry.value == e) return entry.name;
    return {};
}
template <class E>
[[nodiscard]] constexpr std::optional<E> enum_from_name(std::string_view name) noexcept {
    for (const auto& entry : enum_table_v<E>)
        if (entry.name == name) return entry.value;
    return std::nullopt;
}

// A type with a field table (found by ADL: table_of(std::type_identity<M>)).
template <class M>
concept described = requires { table_of(std::type_identity<M>{}); };

// The table of a message or record type.
template <described M>
inline constexpr auto table_v = table_of(std::type_identity<M>{});

namespace detail {
template <class T> struct optional_traits { static constexpr bool value = false; using type = T; };
template <class T> struct optional_traits<std::optional<T>> { static constexpr bool value = true; using type = T; };
template <class T> struct array_traits { static constexpr std::size_t count = 1; using element = T; static constexpr bool value = false; };
template <class T, std::size_t N> struct array_traits<std::array<T, N>> { static constexpr std::size_t count = N; using element = T; static constexpr bool value = true; };
template <class T> struct text_traits { static constexpr std::size_t size = 0; };
template <std::size_t N> struct text_traits<robowire::text<N>> { static constexpr std::size_t size = N; };
template <class T> struct bytes_traits { static constexpr std::size_t size = 0; };
template <std::size_t N> struct bytes_traits<robowire::bytes<N>> { static constexpr std::size_t size = N; };

template <class T> using value_t = typename optional_traits<T>::type;          // optional<X> -> X
template <class T> using element_t = typename array_traits<value_t<T>>::element;  // array<E,N> -> E

template <class W, class E>
constexpr std::size_t element_size() noexcept {
    if constexpr (W::kind == wire_kind::bits) return 1;
    else if constexpr (W::kind == wire_kind::text) return text_traits<E>::size;
    else if constexpr (W::kind == wire_kind::tail) return 0;
    else if constexpr (W::kind == wire_kind::record) return table_v<E>.extent();
    else return sizeof(typename W::raw_type);
}

template <class W, class E>
constexpr range default_range() noexcept {
    if constexpr (std::is_same_v<E, bool>) return {0, 1};
    else if constexpr (W::kind == wire_kind::bits) return {0, low_mask(W::width)};
    else if constexpr (W::kind == wire_kind::text || W::kind == wire_kind::tail || W::kind == wire_kind::record ||
                       W::kind == wire_kind::f32le)
        return {0, 0};
    else {
        using R = typename W::raw_type;
        return {std::numeric_limits<R>::min(), std::numeric_limits<R>::max()};
    }
}

template <class W, class E>
constexpr bool wire_fits() noexcept {
    if constexpr (W::kind == wire_kind::text) return text_traits<E>::size > 0;
    else if constexpr (W::kind == wire_kind::tail) return bytes_traits<E>::size > 0;
    else if constexpr (W::kind == wire_kind::record) return std::is_class_v<E>;
    else if constexpr (W::kind == wire_kind::bits) return std::is_enum_v<E> || std::is_unsigned_v<E>;
    else if constexpr (W::kind == wire_kind::f32le) return std::is_same_v<E, float>;
    else if constexpr (std::is_enum_v<E> || std::is_same_v<E, bool>) return sizeof(typename W::raw_type) == 1;
    else return std::is_integral_v<E> && std::is_signed_v<E> == std::is_signed_v<typename W::raw_type> &&
                sizeof(E) >= sizeof(typename W::raw_type);
}
}  // namespace detail

// One field: name, member, byte offset, wire type, valid raw range, unit.
// The member may be a scalar, an enum, bool, text<N>, bytes<N> (tail), a
// record struct, a std::array of those, or a std::optional of any of them
// (an optional block: present when the input is long enough).
template <class M, class T, class W>
struct field {
    using message_type = M;
    using member_type = T;
    using wire_type = W;
    using element_type = detail::element_t<T>;
    static_assert(detail::wire_fits<W, element_type>(), "field: member type does not fit the wire type");

    std::string_view name;
    T M::*member;
    std::size_t offset;
    robowire::range valid = detail::default_range<W, element_type>();
    robowire::unit unit{};

    constexpr field(std::string_view n, T M::*m, std::size_t off, W, robowire::range r, robowire::unit u = {}) noexcept
        : name(n), member(m), offset(off), valid(r), unit(u) {}
    constexpr field(std::string_view n, T M::*m, std::size_t off, W, robowire::unit u = {}) noexcept
        : name(n), member(m), offset(off), unit(u) {}

    static constexpr wire_kind kind = W::kind;
    static constexpr bool is_optional = detail::optional_traits<T>::value;
    static constexpr bool is_array = detail::array_traits<detail::value_t<T>>::value;
    static constexpr bool is_enum = std::is_enum_v<element_type>;
    static constexpr std::size_t count = detail::array_traits<detail::value_t<T>>::count;
    static constexpr std::size_t element_size = detail::element_size<W, element_type>();
    // Bytes the field occupies (a tail: its capacity).
    static constexpr std::size_t size =
        W::kind == wire_kind::tail ? detail::bytes_traits<element_type>::size : count * element_size;
    constexpr std::size_t end() const noexcept { return offset + size; }
};

// A message (or record) table.
template <class M, std::size_t K, class... F>
struct message_table {
    using message_type = M;
    std::string_view name;
    std::array<fixed_byte, K> fixed;
    std::tuple<F...> fields;
    std::size_t max_input = 0;  // longest accepted input; 0: extent(). Longer is decoded, the rest ignored.
    std::size_t wire_size = 0;  // nonzero: the message is at least this long (reserved bytes after the last field)

    static constexpr std::size_t field_count = sizeof...(F);

    // Bytes up to the end of the last field (with every optional block).
    constexpr std::size_t extent() const noexcept {
        std::size_t e = wire_size;
        for (const auto& b : fixed) e = b.offset + 1 > e ? b.offset + 1 : e;
        std::apply([&](const auto&... f) { ((e = f.end() > e ? f.end() : e), ...); }, fields);
        return e;
    }
    // Shortest valid input: fixed bytes and every non-optional field.
    constexpr std::size_t min_size() const noexcept {
        std::size_t e = wire_size;
        for (const auto& b : fixed) e = b.offset + 1 > e ? b.offset + 1 : e;
        auto req = [&](const auto& f) {
            const std::size_t end = f.kind == wire_kind::tail ? f.offset : f.end();
            if (!f.is_optional && end > e) e = end;
        };
        std::apply([&](const auto&... f) { (req(f), ...); }, fields);
        return e;
    }
    constexpr std::size_t max_size() const noexcept { return extent(); }
    constexpr std::size_t accepted_max() const noexcept { return max_input ? max_input : extent(); }
};

// Builds a message table: name, fixed bytes, fields in offset order.
template <class M, std::size_t K, class... F>
constexpr auto make_table(std::string_view name, const fixed_byte (&fixed)[K], F... fields) noexcept {
    message_table<M, K, F...> t{name, {}, std::tuple<F...>{fields...}};
    for (std::size_t i = 0; i < K; ++i) t.fixed[i] = fixed[i];
    return t;
}
template <class M, std::size_t K, class... F>
constexpr auto make_table(std::string_view name, const std::array<fixed_byte, K>& fixed, F... fields) noexcept {
    return message_table<M, K, F...>{name, fixed, std::tuple<F...>{fields...}};
}
// Builds a record table (a struct nested in messages; no fixed bytes).
template <class M, class... F>
constexpr auto make_record(std::string_view name, F... fields) noexcept {
    return message_table<M, 0, F...>{name, {}, std::tuple<F...>{fields...}};
}

// Size limits of a message's encoding.
template <described M> inline constexpr std::size_t min_size_v = table_v<M>.min_size();
template <described M> inline constexpr std::size_t max_size_v = table_v<M>.max_size();

// Calls fn(field) for each field of M's table, in table order.
template <class M, class Fn>
constexpr void for_each_field(Fn&& fn) {
    std::apply([&](const auto&... f) { (fn(f), ...); }, table_v<M>.fields);
}

// Bytes of M's encoding that no fixed byte and no field covers (reserved bytes).
template <class M>
constexpr std::array<bool, max_size_v<M>> reserved_bytes() noexcept {
    std::array<bool, max_size_v<M>> reserved{};
    reserved.fill(true);
    for (const auto& b : table_v<M>.fixed) reserved[b.offset] = false;
    for_each_field<M>([&](const auto& f) {
        for (std::size_t i = f.offset; i < f.end(); ++i) reserved[i] = false;
    });
    return reserved;
}

// reserved_not_zero at the first reserved byte of `in` that is not zero.
template <class M>
[[nodiscard]] constexpr result<std::size_t> check_reserved(std::span<const std::uint8_t> in) noexcept {
    constexpr auto reserved = reserved_bytes<M>();
    for (std::size_t i = 0; i < in.size() && i < reserved.size(); ++i)
        if (reserved[i] && in[i] != 0) return fail(errc::reserved_not_zero, i);
    return in.size();
}

namespace detail {

template <class M>
concept reports_trailing = requires(M m) { m.ignored_trailing_bytes = std::size_t{}; };

template <class F, class E>
constexpr bool decode_element(const F& f, E& v, std::span<const std::uint8_t> in, std::size_t off, error& err) noexcept;

template <class Table, class M>
constexpr bool decode_fields(const Table& t, M& m, std::span<const std::uint8_t> in, std::size_t base, error& err) noexcept {
    return std::apply(
        [&](const auto&... f) {
            auto one = [&](const auto& fd) -> bool {
                using FD = std::remove_cvref_t<decltype(fd)>;
                const std::size_t off = base + fd.offset;
                auto& member = m.*fd.member;
                if constexpr (FD::is_optional) {
                    if (in.size() <= off) return true;  // absent: stays nullopt
                    if (in.size() < off + FD::size) { err = {errc::bad_length, off}; return false; }
                    auto& value = member.emplace();
                    if constexpr (FD::is_array) {
                        for (std::size_t i = 0; i < FD::count; ++i)
                            if (!decode_element(fd, value[i], in, off + i * FD::element_size, err)) return false;
                        return true;
                    } else {
                        return decode_element(fd, value, in, off, err);
                    }
                } else if constexpr (FD::is_array) {
                    for (std::size_t i = 0; i < FD::count; ++i)
                        if (!decode_element(fd, member[i], in, off + i * FD::element_size, err)) return false;
                    return true;
                } else {
                    return decode_element(fd, member, in, off, err);
                }
            };
            (void)one;  // unused for messages without fields
            return (one(f) && ...);
        },
        t.fields);
}

template <class F, class E>
constexpr bool decode_element(const F& f, E& v, std::span<const std::uint8_t> in, std::size_t off, error& err) noexcept {
    using W = typename F::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        return decode_fields(table_v<E>, v, in, off, err);
    } else if constexpr (W::kind == wire_kind::text) {
        constexpr std::size_t n = text_traits<E>::size;
        std::size_t len = 0;
        while (len < n && in[off + len] != 0) ++len;
        for (std::size_t i = len; i < n; ++i)
            if (in[off + i] != 0) { err = {errc::bad_padding, off + i}; return false; }
        std::array<char, n> chars{};
        for (std::size_t i = 0; i < len; ++i) chars[i] = static_cast<char>(in[off + i]);
        v.assign(std::string_view(chars.data(), len));
        return true;
    } else if constexpr (W::kind == wire_kind::tail) {
        const std::size_t end = in.size() < off + F::size ? in.size() : off + F::size;
        v.clear();
        (void)v.append(in.subspan(off, end > off ? end - off : 0));
        return true;
    } else {
        std::int64_t raw = 0;
        if constexpr (W::kind == wire_kind::bits) {
            raw = get_bits(in[off], W::lo, W::width);
        } else if constexpr (W::kind == wire_kind::f32le) {
            v = load_le<float>(in.data() + off);
            return true;
        } else {
            raw = load_le<typename W::raw_type>(in.data() + off);
        }
        if constexpr (std::is_enum_v<E>) {
            const auto e = static_cast<E>(raw);
            if (!is_valid_enum(e)) { err = {errc::invalid_enum, off}; return false; }
            v = e;
        } else {
            if (raw < f.valid.min || raw > f.valid.max) { err = {errc::value_out_of_range, off}; return false; }
            if constexpr (std::is_same_v<E, bool>) v = raw != 0;
            else v = static_cast<E>(raw);
        }
        return true;
    }
}

template <class F, class E>
constexpr bool encode_element(const F& f, const E& v, std::span<std::uint8_t> out, std::size_t off, error& err) noexcept;

template <class Table, class M>
constexpr bool encode_fields(const Table& t, const M& m, std::span<std::uint8_t> out, std::size_t base, error& err) noexcept {
    return std::apply(
        [&](const auto&... f) {
            auto one = [&](const auto& fd) -> bool {
                using FD = std::remove_cvref_t<decltype(fd)>;
                const std::size_t off = base + fd.offset;
                const auto& member = m.*fd.member;
                if constexpr (FD::is_optional) {
                    if (!member) return true;
                    const auto& value = *member;
                    if constexpr (FD::is_array) {
                        for (std::size_t i = 0; i < FD::count; ++i)
                            if (!encode_element(fd, value[i], out, off + i * FD::element_size, err)) return false;
                        return true;
                    } else {
                        return encode_element(fd, value, out, off, err);
                    }
                } else if constexpr (FD::is_array) {
                    for (std::size_t i = 0; i < FD::count; ++i)
                        if (!encode_element(fd, member[i], out, off + i * FD::element_size, err)) return false;
                    return true;
                } else {
                    return encode_element(fd, member, out, off, err);
                }
            };
            (void)one;  // unused for messages without fields
            return (one(f) && ...);
        },
        t.fields);
}

template <class F, class E>
constexpr bool encode_element(const F& f, const E& v, std::span<std::uint8_t> out, std::size_t off, error& err) noexcept {
    using W = typename F::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        return encode_fields(table_v<E>, v, out, off, err);
    } else if constexpr (W::kind == wire_kind::text) {
        const auto s = v.view();
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (s[i] == '\0') { err = {errc::value_out_of_range, off + i}; return false; }
            out[off + i] = static_cast<std::uint8_t>(s[i]);
        }
        return true;
    } else if constexpr (W::kind == wire_kind::tail) {
        for (std::size_t i = 0; i < v.size(); ++i) out[off + i] = v[i];
        return true;
    } else if constexpr (W::kind == wire_kind::f32le) {
        store_le<float>(out.data() + off, v);
        return true;
    } else {
        std::int64_t raw = 0;
        if constexpr (std::is_enum_v<E>) {
            if (!is_valid_enum(v)) { err = {errc::invalid_enum, off}; return false; }
            raw = static_cast<std::int64_t>(static_cast<std::underlying_type_t<E>>(v));
        } else {
            raw = static_cast<std::int64_t>(v);
            if (raw < f.valid.min || raw > f.valid.max) { err = {errc::value_out_of_range, off}; return false; }
        }
        if constexpr (W::kind == wire_kind::bits) {
            const auto mask = static_cast<std::uint8_t>(low_mask(W::width) << W::lo);
            out[off] = static_cast<std::uint8_t>((static_cast<unsigned>(out[off]) & ~static_cast<unsigned>(mask)) |
                                                 ((static_cast<unsigned>(raw) << W::lo) & mask));
        } else {
            store_le<typename W::raw_type>(out.data() + off, static_cast<typename W::raw_type>(raw));
        }
        return true;
    }
}

// Bytes the encoding of m takes (optional blocks present, tail length), or
// missing_field when an optional block is present but an earlier one is not.
template <class M>
constexpr result<std::size_t> encoded_size(const M& m) noexcept {
    constexpr const auto& t = table_v<M>;
    std::size_t size = t.min_size();
    std::size_t first_absent = 0;
    bool absent_seen = false;
    error err{};
    auto one = [&](const auto& fd) -> bool {
        using FD = std::remove_cvref_t<decltype(fd)>;
        if constexpr (FD::is_optional) {
            if (!(m.*fd.member)) {
                if (!absent_seen) { absent_seen = true; first_absent = fd.offset; }
                return true;
            }
            if (absent_seen) { err = {errc::missing_field, first_absent}; return false; }
            if (fd.end() > size) size = fd.end();
        } else if constexpr (FD::kind == wire_kind::tail) {
            const std::size_t end = fd.offset + (m.*fd.member).size();
            if (end > size) size = end;
        }
        return true;
    };
    (void)one;
    const bool ok = std::apply([&](const auto&... f) { return (one(f) && ...); }, t.fields);
    if (!ok) return err;
    return size;
}

}  // namespace detail

// Decodes a message of type M from `in`; every length, fixed byte, range and
// enum is checked, and the error says what and at which byte offset.
template <described M>
[[nodiscard]] constexpr result<M> decode(std::span<const std::uint8_t> in) noexcept {
    constexpr const auto& t = table_v<M>;
    for (const auto& b : t.fixed)
        if (b.offset < in.size() && in[b.offset] != b.value) return fail(b.code, b.offset);
    if (in.size() < t.min_size()) return fail(errc::too_short, in.size());
    if (in.size() > t.accepted_max()) return fail(errc::too_long, t.accepted_max());
    M m{};
    error err{};
    const auto known = in.size() > t.extent() ? in.first(t.extent()) : in;
    if (!detail::decode_fields(t, m, known, 0, err)) return err;
    if constexpr (detail::reports_trailing<M>) m.ignored_trailing_bytes = in.size() - known.size();
    return m;
}

// Encodes m; out-of-range values and invalid enums are errors (never truncated).
template <described M>
[[nodiscard]] constexpr result<bytes<max_size_v<M>>> encode(const M& m) noexcept {
    constexpr const auto& t = table_v<M>;
    const auto size = detail::encoded_size(m);
    if (!size) return size.error();
    auto out = bytes<max_size_v<M>>::zeros(*size);
    for (const auto& b : t.fixed) out[b.offset] = b.value;
    error err{};
    if (!detail::encode_fields(t, m, out.span(), 0, err)) return err;
    return out;
}

// Encodes m into a caller's buffer; returns the number of bytes written.
template <described M>
[[nodiscard]] constexpr result<std::size_t> encode_to(const M& m, std::span<std::uint8_t> out) noexcept {
    const auto r = encode(m);
    if (!r) return r.error();
    if (r->size() > out.size()) return fail(errc::buffer_too_small, r->size());
    for (std::size_t i = 0; i < r->size(); ++i) out[i] = (*r)[i];
    return r->size();
}

}  // namespace robowire
