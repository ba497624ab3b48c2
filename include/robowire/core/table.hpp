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
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <tuple>
#include <utility>
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
    else if constexpr (W::kind == wire_kind::record) return table_v<E>.max_size();
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
    std::size_t declared_max_input = 0;  // longest accepted input; 0: max_size(). Longer is decoded, the rest ignored.
    std::size_t declared_size = 0;       // nonzero: the message is at least this long (reserved bytes after the last field)

    static constexpr std::size_t field_count = sizeof...(F);

    // Three sizes: min_size() <= max_size() <= max_input().
    // Longest frame: bytes up to the end of the last field (with every optional block).
    constexpr std::size_t max_size() const noexcept {
        std::size_t e = declared_size;
        for (const auto& b : fixed) e = b.offset + 1 > e ? b.offset + 1 : e;
        std::apply([&](const auto&... f) { ((e = f.end() > e ? f.end() : e), ...); }, fields);
        return e;
    }
    // Shortest valid input: fixed bytes and every non-optional field.
    constexpr std::size_t min_size() const noexcept {
        std::size_t e = declared_size;
        for (const auto& b : fixed) e = b.offset + 1 > e ? b.offset + 1 : e;
        auto req = [&](const auto& f) {
            const std::size_t end = f.kind == wire_kind::tail ? f.offset : f.end();
            if (!f.is_optional && end > e) e = end;
        };
        std::apply([&](const auto&... f) { (req(f), ...); }, fields);
        return e;
    }
    // Longest accepted input (longer than max_size(): the rest is ignored).
    constexpr std::size_t max_input() const noexcept { return declared_max_input ? declared_max_input : max_size(); }
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

#if defined(__GNUC__) || defined(__clang__)
#define ROBOWIRE_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define ROBOWIRE_ALWAYS_INLINE inline
#endif

template <class M>
concept reports_trailing = requires(M m) { m.ignored_trailing_bytes = std::size_t{}; };

// Field I of M's table, as a compile-time constant.
template <class M, std::size_t I>
inline constexpr const auto& field_v = std::get<I>(table_v<M>.fields);
template <class M>
inline constexpr std::size_t field_count_v = std::tuple_size_v<std::remove_cvref_t<decltype(table_v<M>.fields)>>;
template <class M, std::size_t I>
using field_t = std::remove_cvref_t<decltype(field_v<M, I>)>;

// ---- decode: every offset and range below is a template constant

template <class M, std::size_t I, std::size_t Off, class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_element(E& v, std::span<const std::uint8_t> in, error& err) noexcept;

template <class M, std::size_t Base, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_record(M& m, std::span<const std::uint8_t> in, error& err,
                                                    std::index_sequence<I...>) noexcept;

template <class M, std::size_t I, std::size_t Off, class V, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_array(V& v, std::span<const std::uint8_t> in, error& err,
                                                   std::index_sequence<K...>) noexcept {
    return (decode_element<M, I, Off + K * field_t<M, I>::element_size>(v[K], in, err) && ...);
}

// An array of bytes that needs no validation: copied whole (one memcpy at run time).
template <class M, std::size_t I>
inline constexpr bool plain_byte_array_v = [] {
    using F = field_t<M, I>;
    using E = typename F::element_type;
    if constexpr (!F::is_array || F::count < 4 || std::is_enum_v<E> || std::is_same_v<E, bool> || sizeof(E) != 1 ||
                  !std::is_integral_v<E>) {
        return false;
    } else if constexpr (F::kind != wire_kind::u8 && F::kind != wire_kind::i8) {
        return false;
    } else {
        return field_v<M, I>.valid.min == std::numeric_limits<E>::min() &&
               field_v<M, I>.valid.max == std::numeric_limits<E>::max();
    }
}();

template <class M, std::size_t I, std::size_t Off, class V>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_value(V& v, std::span<const std::uint8_t> in, error& err) noexcept {
    using F = field_t<M, I>;
    if constexpr (plain_byte_array_v<M, I>) {
        if (!std::is_constant_evaluated()) {
            std::memcpy(v.data(), in.data() + Off, F::count);
            return true;
        }
    }
    if constexpr (F::is_array) return decode_array<M, I, Off>(v, in, err, std::make_index_sequence<F::count>{});
    else return decode_element<M, I, Off>(v, in, err);
}

template <class M, std::size_t I, std::size_t Base>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_field(M& m, std::span<const std::uint8_t> in, error& err) noexcept {
    constexpr const auto& f = field_v<M, I>;
    using F = field_t<M, I>;
    constexpr std::size_t off = Base + f.offset;
    constexpr auto member_ptr = f.member;
    auto& member = m.*member_ptr;
    if constexpr (F::is_optional) {
        if (in.size() <= off) { member.reset(); return true; }  // absent
        if (in.size() < off + F::size) { err = {errc::bad_length, off}; return false; }
        value_t<typename F::member_type> tmp{};  // stored whole once decoded
        if (!decode_value<M, I, off>(tmp, in, err)) return false;
        member = tmp;
        return true;
    } else {
        return decode_value<M, I, off>(member, in, err);
    }
}

template <class M, std::size_t Base, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_record(M& m, std::span<const std::uint8_t> in, error& err,
                                                    std::index_sequence<I...>) noexcept {
    (void)m, (void)in, (void)err;  // messages without fields
    return (decode_field<M, I, Base>(m, in, err) && ...);
}

template <class M, std::size_t I, std::size_t Off, class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool decode_element(E& v, std::span<const std::uint8_t> in, error& err) noexcept {
    constexpr const auto& f = field_v<M, I>;
    using F = field_t<M, I>;
    using W = typename F::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        // Decoded into a local, then stored whole: the loads are not ordered
        // behind byte stores that might alias the input, so they merge.
        E tmp{};
        if (!decode_record<E, Off>(tmp, in, err, std::make_index_sequence<field_count_v<E>>{})) return false;
        v = tmp;
        return true;
    } else if constexpr (W::kind == wire_kind::text) {
        constexpr std::size_t n = text_traits<E>::size;
        std::size_t len = 0;
        while (len < n && in[Off + len] != 0) ++len;
        for (std::size_t i = len; i < n; ++i)
            if (in[Off + i] != 0) { err = {errc::bad_padding, Off + i}; return false; }
        std::array<char, n> chars{};
        for (std::size_t i = 0; i < len; ++i) chars[i] = static_cast<char>(in[Off + i]);
        v.assign(std::string_view(chars.data(), len));
        return true;
    } else if constexpr (W::kind == wire_kind::tail) {
        const std::size_t end = in.size() < Off + F::size ? in.size() : Off + F::size;
        v.clear();
        (void)v.append(in.subspan(Off, end > Off ? end - Off : 0));
        return true;
    } else if constexpr (W::kind == wire_kind::f32le) {
        v = load_le<float>(in.data() + Off);
        return true;
    } else {
        std::int64_t raw = 0;
        if constexpr (W::kind == wire_kind::bits) raw = get_bits(in[Off], W::lo, W::width);
        else raw = load_le<typename W::raw_type>(in.data() + Off);
        if constexpr (std::is_enum_v<E>) {
            const auto e = static_cast<E>(raw);
            if (!is_valid_enum(e)) { err = {errc::invalid_enum, Off}; return false; }
            v = e;
        } else {
            constexpr range valid = f.valid;
            constexpr range full = [] {  // what the wire bytes can hold
                if constexpr (W::kind == wire_kind::bits) return range{0, low_mask(W::width)};
                else return range{std::numeric_limits<typename W::raw_type>::min(), std::numeric_limits<typename W::raw_type>::max()};
            }();
            if constexpr (valid.min > full.min || valid.max < full.max) {
                if (raw < valid.min || raw > valid.max) { err = {errc::value_out_of_range, Off}; return false; }
            }
            if constexpr (std::is_same_v<E, bool>) v = raw != 0;
            else v = static_cast<E>(raw);
        }
        return true;
    }
}

// ---- encode, in two passes: check every field (the first error wins), then
// write them all without a branch, so that the stores can merge.

template <class M, std::size_t I, std::size_t Off, class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_element(const E& v, error& err) noexcept;

template <class M, std::size_t Base, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_record(const M& m, error& err, std::index_sequence<I...>) noexcept;

template <class M, std::size_t I, std::size_t Off, class V, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_array(const V& v, error& err, std::index_sequence<K...>) noexcept {
    return (check_element<M, I, Off + K * field_t<M, I>::element_size>(v[K], err) && ...);
}

template <class M, std::size_t I, std::size_t Base>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_field(const M& m, error& err) noexcept {
    using F = field_t<M, I>;
    constexpr std::size_t off = Base + field_v<M, I>.offset;
    constexpr auto member_ptr = field_v<M, I>.member;
    const auto& member = m.*member_ptr;
    auto value = [&](const auto& v) {
        if constexpr (F::is_array) return check_array<M, I, off>(v, err, std::make_index_sequence<F::count>{});
        else return check_element<M, I, off>(v, err);
    };
    if constexpr (F::is_optional) return !member || value(*member);
    else return value(member);
}

template <class M, std::size_t Base, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_record(const M& m, error& err, std::index_sequence<I...>) noexcept {
    (void)m, (void)err;  // messages without fields
    return (check_field<M, I, Base>(m, err) && ...);
}

template <class M, std::size_t I, std::size_t Off, class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_element(const E& v, error& err) noexcept {
    using W = typename field_t<M, I>::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        return check_record<E, Off>(v, err, std::make_index_sequence<field_count_v<E>>{});
    } else if constexpr (W::kind == wire_kind::text) {
        const auto s = v.view();
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s[i] == '\0') { err = {errc::value_out_of_range, Off + i}; return false; }
        return true;
    } else if constexpr (W::kind == wire_kind::tail || W::kind == wire_kind::f32le) {
        return true;
    } else if constexpr (std::is_enum_v<E>) {
        if (!is_valid_enum(v)) { err = {errc::invalid_enum, Off}; return false; }
        return true;
    } else {
        constexpr range valid = field_v<M, I>.valid;
        if constexpr (W::kind == wire_kind::bits || std::is_same_v<E, bool> ||
                      valid.min > std::int64_t{std::numeric_limits<E>::min()} ||
                      valid.max < std::int64_t{std::numeric_limits<E>::max()}) {
            const auto raw = static_cast<std::int64_t>(v);
            if (raw < valid.min || raw > valid.max) { err = {errc::value_out_of_range, Off}; return false; }
        }
        return true;
    }
}

template <class M, std::size_t I, std::size_t Off, class E>
ROBOWIRE_ALWAYS_INLINE constexpr void store_element(const E& v, std::span<std::uint8_t> out) noexcept;

template <class M, std::size_t Base, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void store_record(const M& m, std::span<std::uint8_t> out,
                                                   std::index_sequence<I...>) noexcept;

template <class M, std::size_t I, std::size_t Off, class V, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr void store_array(const V& v, std::span<std::uint8_t> out,
                                                  std::index_sequence<K...>) noexcept {
    (store_element<M, I, Off + K * field_t<M, I>::element_size>(v[K], out), ...);
}

template <class M, std::size_t I, std::size_t Off, class V>
ROBOWIRE_ALWAYS_INLINE constexpr void store_value(const V& v, std::span<std::uint8_t> out) noexcept {
    using F = field_t<M, I>;
    if constexpr (plain_byte_array_v<M, I>) {
        if (!std::is_constant_evaluated()) {
            std::memcpy(out.data() + Off, v.data(), F::count);
            return;
        }
    }
    if constexpr (F::is_array) store_array<M, I, Off>(v, out, std::make_index_sequence<F::count>{});
    else store_element<M, I, Off>(v, out);
}

template <class M, std::size_t I, std::size_t Base>
ROBOWIRE_ALWAYS_INLINE constexpr void store_field(const M& m, std::span<std::uint8_t> out) noexcept {
    constexpr std::size_t off = Base + field_v<M, I>.offset;
    constexpr auto member_ptr = field_v<M, I>.member;
    const auto& member = m.*member_ptr;
    if constexpr (field_t<M, I>::is_optional) {
        if (member) store_value<M, I, off>(*member, out);
    } else {
        store_value<M, I, off>(member, out);
    }
}

template <class M, std::size_t Base, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void store_record(const M& m, std::span<std::uint8_t> out,
                                                   std::index_sequence<I...>) noexcept {
    (void)m, (void)out;  // messages without fields
    (store_field<M, I, Base>(m, out), ...);
}

// Writes one checked element.
template <class M, std::size_t I, std::size_t Off, class E>
ROBOWIRE_ALWAYS_INLINE constexpr void store_element(const E& v, std::span<std::uint8_t> out) noexcept {
    using W = typename field_t<M, I>::wire_type;
    if constexpr (W::kind == wire_kind::record) {
        store_record<E, Off>(v, out, std::make_index_sequence<field_count_v<E>>{});
    } else if constexpr (W::kind == wire_kind::text) {
        const auto s = v.view();
        for (std::size_t i = 0; i < s.size(); ++i) out[Off + i] = static_cast<std::uint8_t>(s[i]);
        for (std::size_t i = s.size(); i < text_traits<E>::size; ++i) out[Off + i] = 0;  // padding
    } else if constexpr (W::kind == wire_kind::tail) {
        for (std::size_t i = 0; i < v.size(); ++i) out[Off + i] = v[i];
    } else if constexpr (W::kind == wire_kind::f32le) {
        store_le<float>(out.data() + Off, v);
    } else {
        std::uint64_t raw = 0;
        if constexpr (std::is_enum_v<E>) raw = static_cast<std::uint64_t>(static_cast<std::underlying_type_t<E>>(v));
        else raw = static_cast<std::uint64_t>(v);
        if constexpr (W::kind == wire_kind::bits) {
            constexpr auto mask = static_cast<unsigned>(low_mask(W::width) << W::lo);
            out[Off] = static_cast<std::uint8_t>((static_cast<unsigned>(out[Off]) & ~mask) |
                                                 ((static_cast<unsigned>(raw) << W::lo) & mask));
        } else {
            store_le<typename W::raw_type>(out.data() + Off, static_cast<typename W::raw_type>(raw));
        }
    }
}

// Bytes the encoding of m takes (optional blocks present, tail length), or
// missing_field when an optional block is present but an earlier one is not.
template <class M, std::size_t... I>
constexpr result<std::size_t> encoded_size(const M& m, std::index_sequence<I...>) noexcept {
    std::size_t size = table_v<M>.min_size();
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
                if (!absent_seen) { absent_seen = true; first_absent = f.offset; }
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

// The first fixed byte of M that `in` has and gets wrong, as an error (code ok if none).
template <class M, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr error check_fixed(std::span<const std::uint8_t> in, std::index_sequence<K...>) noexcept {
    error e{};
    (void)((((table_v<M>.fixed[K].offset < in.size()) &&
             in[table_v<M>.fixed[K].offset] != table_v<M>.fixed[K].value)
                ? (e = {table_v<M>.fixed[K].code, table_v<M>.fixed[K].offset}, true)
                : false) ||
           ...);
    return e;
}
template <class M, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE constexpr void write_fixed(std::span<std::uint8_t> out, std::index_sequence<K...>) noexcept {
    ((out[table_v<M>.fixed[K].offset] = table_v<M>.fixed[K].value), ...);
}
template <class M>
inline constexpr std::size_t fixed_count_v = table_v<M>.fixed.size();

// Bytes that encoding sets to zero before writing the fields: reserved bytes
// and bytes holding bit fields (those are or-ed in).
template <class M>
constexpr std::array<bool, max_size_v<M>> cleared_bytes() noexcept {
    auto clear = reserved_bytes<M>();
    auto bits = [&](const auto& self, const auto& f, std::size_t base) -> void {
        using F = std::remove_cvref_t<decltype(f)>;
        for (std::size_t k = 0; k < F::count; ++k) {
            if constexpr (F::kind == wire_kind::bits) clear[base + f.offset + k * F::element_size] = true;
            else if constexpr (F::kind == wire_kind::record) {
                using E = typename F::element_type;
                std::apply([&](const auto&... g) { (self(self, g, base + f.offset + k * F::element_size), ...); },
                           table_v<E>.fields);
            }
        }
    };
    for_each_field<M>([&](const auto& f) { bits(bits, f, 0); });
    return clear;
}
template <class M>
inline constexpr auto cleared_bytes_v = cleared_bytes<M>();

template <class M, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void clear_bytes(std::span<std::uint8_t> out, std::index_sequence<I...>) noexcept {
    (void)out;
    auto one = [&](auto index) {
        constexpr std::size_t i = decltype(index)::value;
        if constexpr (cleared_bytes_v<M>[i]) {
            if (i < out.size()) out[i] = 0;
        }
    };
    (one(std::integral_constant<std::size_t, I>{}), ...);
    (void)one;
}

}  // namespace detail

// Decodes `in` into `out` (an existing object, e.g. one refreshed 20 times a
// second): the same checks as decode(); returns errc::ok or the error. On an
// error, `out`'s fields are unspecified.
template <described M>
[[nodiscard]] constexpr error decode_into(M& out, std::span<const std::uint8_t> in) noexcept {
    constexpr std::size_t min = table_v<M>.min_size(), max = table_v<M>.max_input(), extent = table_v<M>.max_size();
    if (const error e = detail::check_fixed<M>(in, std::make_index_sequence<detail::fixed_count_v<M>>{}); e.code != errc::ok)
        return e;
    if (in.size() < min) return fail(errc::too_short, in.size());
    if (in.size() > max) return fail(errc::too_long, max);
    error err{};
    const auto known = in.size() > extent ? in.first(extent) : in;
    if (!detail::decode_record<M, 0>(out, known, err, std::make_index_sequence<detail::field_count_v<M>>{})) return err;
    if constexpr (detail::reports_trailing<M>) out.ignored_trailing_bytes = in.size() - known.size();
    return err;
}

namespace detail {
// Fields only, no fixed-byte or length checks: for dispatchers that have
// checked both already (`in` holds at least max_size() bytes).
template <described M>
ROBOWIRE_ALWAYS_INLINE constexpr error decode_fields(M& out, std::span<const std::uint8_t> in) noexcept {
    error err{};
    (void)decode_record<M, 0>(out, in.first(table_v<M>.max_size()), err,
                              std::make_index_sequence<field_count_v<M>>{});
    return err;
}
}  // namespace detail

// Decodes a message of type M from `in`; every length, fixed byte, range and
// enum is checked, and the error says what and at which byte offset.
template <described M>
[[nodiscard]] constexpr result<M> decode(std::span<const std::uint8_t> in) noexcept {
    result<M> r{std::in_place};  // built in place: every return below returns r
    if (const error e = decode_into(*r, in); e.code != errc::ok) r = e;
    return r;
}

// Encodes m into a caller's buffer (e.g. the radio's transmit buffer);
// returns the number of bytes written. Errors as for encode(), then
// buffer_too_small; on an error `out` is unchanged.
template <described M>
[[nodiscard]] constexpr result<std::size_t> encode_to(const M& m, std::span<std::uint8_t> out) noexcept {
    constexpr auto fields = std::make_index_sequence<detail::field_count_v<M>>{};
    const auto size = detail::encoded_size(m, fields);
    if (!size) return size.error();
    error err{};
    if (!detail::check_record<M, 0>(m, err, fields)) return err;
    if (*size > out.size()) return fail(errc::buffer_too_small, *size);
    const auto dst = out.first(*size);
    detail::clear_bytes<M>(dst, std::make_index_sequence<max_size_v<M>>{});
    detail::write_fixed<M>(dst, std::make_index_sequence<detail::fixed_count_v<M>>{});
    if constexpr (sizeof(M) > 16) {
        const M copy = m;  // a local cannot alias `out`: its loads need not wait behind byte stores, so wide fields merge
        detail::store_record<M, 0>(copy, dst, fields);
    } else {
        detail::store_record<M, 0>(m, dst, fields);  // a few bytes: copied as they are
    }
    return *size;
}

// Encodes m; out-of-range values and invalid enums are errors (never truncated).
template <described M>
[[nodiscard]] constexpr result<bytes<max_size_v<M>>> encode(const M& m) noexcept {
    result<bytes<max_size_v<M>>> r{std::in_place};
    const auto n = encode_to(m, std::span<std::uint8_t>(r->data(), max_size_v<M>));
    if (!n) { r = n.error(); return r; }
    r->resize(*n);
    return r;
}

}  // namespace robowire
