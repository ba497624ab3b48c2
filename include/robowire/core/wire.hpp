// robowire/core/wire.hpp - wire types: how a field looks on the wire
// (kind, width, bits), and the valid raw range of a field.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstdint>
#include <string_view>

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
struct text {
    static constexpr wire_kind kind = wire_kind::text;
};
// bytes<N> member: every byte from the offset to the end of the input.
struct tail {
    static constexpr wire_kind kind = wire_kind::tail;
};
// A struct member with a table of its own (no fixed bytes).
struct record {
    static constexpr wire_kind kind = wire_kind::record;
};
}  // namespace wire

// Valid raw range, inclusive.
struct range {
    std::int64_t min;
    std::int64_t max;
};

}  // namespace robowire
