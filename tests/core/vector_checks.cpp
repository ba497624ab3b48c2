// The range checks of one-byte fields made as one vector test (x86-64; the
// scalar checks elsewhere): every byte value of every such field, at run time,
// against ranges written out here by hand; and the first error in table
// order when a field the test covers and one it does not both fail.
#include <robowire/core.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <string>

namespace demo_vec {
enum class mode : std::uint8_t { slow = 1, normal = 2, fast = 3 };
constexpr auto enum_table_of(std::type_identity<mode>) {
    return std::array<robowire::enum_entry<mode>, 3>{{{mode::slow, "slow"}, {mode::normal, "normal"}, {mode::fast, "fast"}}};
}
// Members lie as the wire bytes, one byte on (the fixed byte 0 is not a member).
struct gauges {
    std::uint16_t id = 0;
    std::int8_t a = 0;
    std::uint8_t b = 5;
    demo_vec::mode c = mode::slow;
    std::array<std::int8_t, 4> d{};
    std::uint8_t e = 0, f = 0;
    std::int8_t g = 0;
    std::uint16_t h = 0;
    std::uint8_t k = 0;
    friend constexpr bool operator==(const gauges&, const gauges&) = default;
};
constexpr auto table_of(std::type_identity<gauges>) {
    using namespace robowire;
    return make_table<gauges>("gauges", {{0, 0xA5, errc::bad_header}}, field{"id", &gauges::id, 1, wire::u16le{}},
                              field{"a", &gauges::a, 3, wire::i8{}, range{-10, 10}},
                              field{"b", &gauges::b, 4, wire::u8{}, range{5, 200}}, field{"c", &gauges::c, 5, wire::u8{}},
                              field{"d", &gauges::d, 6, wire::i8{}, range{-127, 127}},
                              field{"e", &gauges::e, 10, wire::u8{}, range{0, 63}}, field{"f", &gauges::f, 11, wire::u8{}},
                              field{"g", &gauges::g, 12, wire::i8{}, range{-5, 5}},
                              field{"h", &gauges::h, 13, wire::u16le{}, range{0, 1000}},
                              field{"k", &gauges::k, 15, wire::u8{}, range{0, 9}});
}
// Two flag bytes and a sign bit tested as one word; a sparse enum.
enum class step : std::uint8_t { one = 1, four = 4, nine = 9 };
constexpr auto enum_table_of(std::type_identity<step>) {
    return std::array<robowire::enum_entry<step>, 3>{{{step::one, "one"}, {step::four, "four"}, {step::nine, "nine"}}};
}
struct pair {
    std::uint16_t id = 0;
    std::uint8_t a = 0, b = 0;
    demo_vec::step e = step::one;
    std::int8_t c = 0;
    friend constexpr bool operator==(const pair&, const pair&) = default;
};
constexpr auto table_of(std::type_identity<pair>) {
    using namespace robowire;
    return make_table<pair>("pair", {{0, 0x5A, errc::bad_header}}, field{"id", &pair::id, 1, wire::u16le{}},
                            field{"a", &pair::a, 3, wire::u8{}, range{0, 63}},
                            field{"b", &pair::b, 4, wire::u8{}, range{0, 63}}, field{"e", &pair::e, 5, wire::u8{}},
                            field{"c", &pair::c, 6, wire::i8{}, range{0, 127}});
}
// Four one-byte fields at the end of an 8-byte struct: an 8-byte load from
// the first of them would pass the struct's end.
struct tail8 {
    std::uint32_t big = 0;
    std::int8_t p0 = 0, p1 = 0;
    std::uint8_t f0 = 0, f1 = 0;
    friend constexpr bool operator==(const tail8&, const tail8&) = default;
};
constexpr auto table_of(std::type_identity<tail8>) {
    using namespace robowire;
    return make_table<tail8>("tail8", {{0, 0xC3, errc::bad_header}}, field{"big", &tail8::big, 1, wire::u32le{}},
                             field{"p0", &tail8::p0, 5, wire::i8{}, range{-127, 127}},
                             field{"p1", &tail8::p1, 6, wire::i8{}, range{-127, 127}},
                             field{"f0", &tail8::f0, 7, wire::u8{}, range{0, 63}},
                             field{"f1", &tail8::f1, 8, wire::u8{}, range{0, 63}});
}
// One-byte fields only, their members in wire order: encode builds the frame
// from the vector test's register. Fixed bytes before and after the fields.
struct tele17 {
    std::uint8_t a = 0;
    std::int8_t b = 0;
    demo_vec::mode c = mode::slow;
    std::uint8_t d = 0;
    std::int8_t e = 0;
    std::uint8_t f = 0, g = 0;
    std::int8_t h = 0;
    std::uint8_t i = 10, j = 0;
    std::int8_t k = 0;
    std::uint8_t l = 0;
    friend constexpr bool operator==(const tele17&, const tele17&) = default;
};
constexpr auto table_of(std::type_identity<tele17>) {
    using namespace robowire;
    auto t = make_table<tele17>(
        "tele17", {{0, 0x7E, errc::bad_header}, {1, 0x01, errc::bad_command}, {16, 0xE7, errc::bad_header}},
        field{"a", &tele17::a, 2, wire::u8{}, range{0, 10}}, field{"b", &tele17::b, 3, wire::i8{}, range{-50, 50}},
        field{"c", &tele17::c, 4, wire::u8{}}, field{"d", &tele17::d, 5, wire::u8{}},
        field{"e", &tele17::e, 6, wire::i8{}, range{-100, 100}}, field{"f", &tele17::f, 7, wire::u8{}, range{0, 200}},
        field{"g", &tele17::g, 8, wire::u8{}, range{0, 1}}, field{"h", &tele17::h, 9, wire::i8{}, range{-5, 5}},
        field{"i", &tele17::i, 10, wire::u8{}, range{10, 20}}, field{"j", &tele17::j, 11, wire::u8{}},
        field{"k", &tele17::k, 12, wire::i8{}, range{-1, 1}}, field{"l", &tele17::l, 13, wire::u8{}, range{0, 99}});
    t.declared_size = 17;
    return t;
}
// Eight fields (one 8-byte load) in a 24-byte frame: fixed bytes at both ends.
struct tele24 {
    std::uint8_t a = 0;
    std::int8_t b = 0;
    demo_vec::mode c = mode::slow;
    std::uint8_t d = 0, e = 0;
    std::int8_t f = 0;
    std::uint8_t g = 5;
    std::int8_t h = 0;
    friend constexpr bool operator==(const tele24&, const tele24&) = default;
};
constexpr auto table_of(std::type_identity<tele24>) {
    using namespace robowire;
    auto t = make_table<tele24>("tele24",
                                {{0, 0xAA, errc::bad_header},
                                 {1, 0xBB, errc::bad_header},
                                 {2, 0xCC, errc::bad_header},
                                 {3, 0xDD, errc::bad_header},
                                 {23, 0x99, errc::bad_header}},
                                field{"a", &tele24::a, 8, wire::u8{}, range{0, 63}},
                                field{"b", &tele24::b, 9, wire::i8{}, range{-127, 127}},
                                field{"c", &tele24::c, 10, wire::u8{}}, field{"d", &tele24::d, 11, wire::u8{}},
                                field{"e", &tele24::e, 12, wire::u8{}, range{0, 1}},
                                field{"f", &tele24::f, 13, wire::i8{}, range{0, 127}},
                                field{"g", &tele24::g, 14, wire::u8{}, range{5, 6}},
                                field{"h", &tele24::h, 15, wire::i8{}, range{-128, 0}});
    t.declared_size = 24;
    return t;
}
// 13 bytes of fields (an 8-byte load, then 8 more ending at the last byte,
// 3 of them dropped); 15 bytes.
struct tele13 {
    std::uint8_t a = 0;
    std::array<std::int8_t, 11> b{};
    std::uint8_t c = 1;
    friend constexpr bool operator==(const tele13&, const tele13&) = default;
};
constexpr auto table_of(std::type_identity<tele13>) {
    using namespace robowire;
    auto t = make_table<tele13>("tele13", {{0, 0x42, errc::bad_header}},
                                field{"a", &tele13::a, 1, wire::u8{}, range{0, 9}},
                                field{"b", &tele13::b, 2, wire::i8{}, range{-100, 100}},
                                field{"c", &tele13::c, 13, wire::u8{}, range{1, 255}});
    t.declared_size = 15;
    return t;
}
// 9 bytes of fields (an 8-byte load, then one byte); 15 bytes.
struct tele9 {
    std::uint8_t a = 0;
    std::array<std::uint8_t, 7> b{};
    std::int8_t c = 0;
    friend constexpr bool operator==(const tele9&, const tele9&) = default;
};
constexpr auto table_of(std::type_identity<tele9>) {
    using namespace robowire;
    auto t = make_table<tele9>("tele9",
                               {{0, 0x10, errc::bad_header}, {1, 0x20, errc::bad_header}, {2, 0x30, errc::bad_header}},
                               field{"a", &tele9::a, 3, wire::u8{}, range{0, 1}},
                               field{"b", &tele9::b, 4, wire::u8{}, range{0, 100}},
                               field{"c", &tele9::c, 11, wire::i8{}, range{-3, 3}});
    t.declared_size = 15;
    return t;
}
// One-byte fields whose members lie in the reverse order: neither the
// register image of decode nor encode's applies (their members are checked).
struct backwards {
    std::uint8_t c = 0;
    std::int8_t b = 0;
    std::uint8_t a = 0;
    friend constexpr bool operator==(const backwards&, const backwards&) = default;
};
constexpr auto table_of(std::type_identity<backwards>) {
    using namespace robowire;
    auto t = make_table<backwards>("backwards", {{0, 0x3C, errc::bad_header}},
                                   field{"a", &backwards::a, 1, wire::u8{}, range{0, 9}},
                                   field{"b", &backwards::b, 2, wire::i8{}, range{-9, 9}},
                                   field{"c", &backwards::c, 3, wire::u8{}, range{10, 19}});
    t.declared_size = 16;
    return t;
}
}  // namespace demo_vec

using namespace robowire;

namespace {
// A valid frame, by hand: id 0x1234, a -3, b 100, c fast, d {1, -1, 127, -127},
// e 63, f 0xEE, g 5, h 1000, k 9.
constexpr std::array<std::uint8_t, 16> good_frame{0xA5, 0x34, 0x12, 0xFD, 100, 3,    1,    0xFF,
                                                  127,  0x81, 63,   0xEE, 5,   0xE8, 0x03, 9};
const demo_vec::gauges good_value{0x1234, -3, 100, demo_vec::mode::fast, {1, -1, 127, -127}, 63, 0xEE, 5, 1000, 9};

// Is byte v valid at wire offset `off` (one of the one-byte fields)?
bool valid_byte(std::size_t off, std::uint8_t v) {
    const auto s = static_cast<std::int8_t>(v);
    switch (off) {
    case 3: return s >= -10 && s <= 10;
    case 4: return v >= 5 && v <= 200;
    case 5: return v >= 1 && v <= 3;
    case 6: case 7: case 8: case 9: return s != -128;
    case 10: return v <= 63;
    case 11: return true;
    case 12: return s >= -5 && s <= 5;
    case 15: return v <= 9;
    default: return false;
    }
}
errc code_at(std::size_t off) { return off == 5 ? errc::invalid_enum : errc::value_out_of_range; }
}  // namespace

namespace {
// encode_to into a buffer of n bytes filled with 0x5A: the frame `want`
// (empty: the error e) and nothing written past it, or on an error.
template <class M, std::size_t N>
void check_encode_to(const M& m, const std::array<std::uint8_t, N>& want, bool ok, error e) {
    for (const std::size_t n : {N - 1, N, N + 3}) {
        std::array<std::uint8_t, N + 3> out{};
        out.fill(0x5A);
        const auto r = encode_to(m, std::span(out).first(n));
        if (!ok) {
            CHECK(r.error() == e);
        } else if (n < N) {
            CHECK(r.error() == error{errc::buffer_too_small, static_cast<std::uint16_t>(N)});
        } else {
            REQUIRE(r.has_value());
            CHECK(*r == N);
            CHECK(std::equal(want.begin(), want.end(), out.begin()));
        }
        for (std::size_t k = ok && n >= N ? N : 0; k < out.size(); ++k) CHECK(out[k] == 0x5A);
    }
}
// Every value of the byte at each offset in `offs` (a member `delta` bytes
// before it), decoded and encoded, against valid(off, byte) and the error
// code at off.
template <class M, std::size_t N, class Valid, class Code>
void every_byte(const std::array<std::uint8_t, N>& good, const M& value, std::initializer_list<std::size_t> offs,
                Valid valid, Code code, std::size_t delta = 1) {
    REQUIRE(decode<M>(good).value() == value);
    REQUIRE(encode(value).value() == bytes<N>::from(good).value());
    check_encode_to(value, good, true, error{});
    for (const std::size_t off : offs) {
        for (unsigned v = 0; v < 256; ++v) {
            INFO("offset " << off << " byte " << v);
            auto in = good;
            in[off] = static_cast<std::uint8_t>(v);
            const bool ok = valid(off, static_cast<std::uint8_t>(v));
            const auto r = decode<M>(in);
            REQUIRE(r.has_value() == ok);
            if (!ok) CHECK(r.error() == error{code(off), static_cast<std::uint16_t>(off)});
            auto m = value;
            std::memcpy(reinterpret_cast<unsigned char*>(&m) + off - delta, &in[off], 1);
            const auto e = encode(m);
            REQUIRE(e.has_value() == ok);
            if (ok) CHECK(*e == bytes<N>::from(in).value());
            else CHECK(e.error() == error{code(off), static_cast<std::uint16_t>(off)});
            if (v % 16 == 0 || !ok) check_encode_to(m, in, ok, error{code(off), static_cast<std::uint16_t>(off)});
        }
    }
}
}  // namespace

TEST_CASE("vector checks: every byte value of every one-byte field, decode and encode", "[core][vector]") {
    static_assert(sizeof(demo_vec::gauges) == 16);
#if ROBOWIRE_SSE2 && !ROBOWIRE_OPTIMIZE_SIZE
    // The layout above has the vector test (decode and encode), else this file tests nothing new.
    static_assert(detail::lanes_v<demo_vec::gauges, false>.use && detail::lanes_v<demo_vec::gauges, true>.use);
#endif
    // (members lie as the wire bytes, one on)
    every_byte(good_frame, good_value, {3u, 4u, 5u, 6u, 7u, 8u, 9u, 10u, 11u, 12u, 15u}, valid_byte, code_at);
}

TEST_CASE("vector checks: the first error in table order wins", "[core][vector]") {
    // h (not in the vector test) fails before k (in it)
    auto in = good_frame;
    in[13] = 0xE9;  // h 1001
    in[15] = 10;    // k 10
    CHECK(decode<demo_vec::gauges>(in).error() == error{errc::value_out_of_range, 13});
    // b (in it) fails before h
    in[4] = 4;
    CHECK(decode<demo_vec::gauges>(in).error() == error{errc::value_out_of_range, 4});
    // k alone
    in = good_frame;
    in[15] = 200;
    CHECK(decode<demo_vec::gauges>(in).error() == error{errc::value_out_of_range, 15});

    // the fixed byte (in the same vector test) before every field; the length before both
#if ROBOWIRE_SSE2 && !ROBOWIRE_OPTIMIZE_SIZE
    static_assert(detail::lanes_v<demo_vec::gauges, false>.fixed_in);
#endif
    in = good_frame;
    in[0] = 0xA4;
    CHECK(decode<demo_vec::gauges>(in).error() == error{errc::bad_header, 0});
    in[4] = 201;  // b
    CHECK(decode<demo_vec::gauges>(in).error() == error{errc::bad_header, 0});
    CHECK(decode<demo_vec::gauges>(std::span(in).first(15)).error() == error{errc::bad_header, 0});
    in[0] = 0xA5;
    CHECK(decode<demo_vec::gauges>(in).error() == error{errc::value_out_of_range, 4});
    CHECK(decode<demo_vec::gauges>(std::span(in).first(15)).error() == error{errc::too_short, 15});
    for (unsigned v = 0; v < 256; ++v) {  // every value of the fixed byte
        auto f = good_frame;
        f[0] = static_cast<std::uint8_t>(v);
        demo_vec::gauges into{};
        const error e = decode_into(into, f);
        CHECK(e == (v == 0xA5 ? error{} : error{errc::bad_header, 0}));
        CHECK(decode<demo_vec::gauges>(f).has_value() == (v == 0xA5));
    }

    auto m = good_value;
    m.h = 1001;
    m.k = 10;
    CHECK(encode(m).error() == error{errc::value_out_of_range, 13});
    m.a = 11;
    CHECK(encode(m).error() == error{errc::value_out_of_range, 3});
    // nothing written on an error
    std::array<std::uint8_t, 16> out{};
    out.fill(0x5A);
    CHECK(!encode_to(m, out).has_value());
    for (const auto b : out) CHECK(b == 0x5A);
}

// The same answers in a constant expression (the scalar checks).
static_assert(decode<demo_vec::gauges>(good_frame).has_value());
static_assert([] {
    auto in = good_frame;
    in[9] = 0x80;  // d[3] = -128
    return decode<demo_vec::gauges>(in).error() == error{errc::value_out_of_range, 9};
}());


TEST_CASE("vector checks: flag bytes as one word, a sparse enum, a load that ends at the struct's end",
          "[core][vector]") {
    static_assert(sizeof(demo_vec::pair) == 6 && sizeof(demo_vec::tail8) == 8);
#if ROBOWIRE_SSE2 && !ROBOWIRE_OPTIMIZE_SIZE
    static_assert(detail::lanes_v<demo_vec::pair, false>.words == 1 && detail::lanes_v<demo_vec::pair, true>.words == 1);
    static_assert(detail::lanes_v<demo_vec::tail8, true>.win[0].loads == 1 && detail::lanes_v<demo_vec::tail8, true>.win[0].at[0] == 1);
#endif
    // id 0xBEEF, a 63, b 0, e nine, c 127
    every_byte(std::array<std::uint8_t, 7>{0x5A, 0xEF, 0xBE, 63, 0, 9, 127},
               demo_vec::pair{0xBEEF, 63, 0, demo_vec::step::nine, 127}, {3, 4, 5, 6},
               [](std::size_t off, std::uint8_t v) {
                   if (off == 5) return v == 1 || v == 4 || v == 9;
                   return off == 6 ? v <= 127 : v <= 63;
               },
               [](std::size_t off) { return off == 5 ? errc::invalid_enum : errc::value_out_of_range; });
    // big 0x01020304, p0 -127, p1 127, f0 0, f1 63
    every_byte(std::array<std::uint8_t, 9>{0xC3, 4, 3, 2, 1, 0x81, 0x7F, 0, 63},
               demo_vec::tail8{0x01020304, -127, 127, 0, 63}, {5, 6, 7, 8},
               [](std::size_t off, std::uint8_t v) { return off <= 6 ? v != 0x80 : v <= 63; },
               [](std::size_t) { return errc::value_out_of_range; });
}

TEST_CASE("vector checks: the frame built from the test's register", "[core][vector]") {
    static_assert(sizeof(demo_vec::tele17) == 12 && sizeof(demo_vec::tele24) == 8);
    static_assert(sizeof(demo_vec::tele13) == 13 && sizeof(demo_vec::tele9) == 9);
#if ROBOWIRE_SSE2 && !ROBOWIRE_OPTIMIZE_SIZE
    // else this case tests nothing new: the image (bytes<N>, then a caller's buffer), its loads
    static_assert(detail::image_v<demo_vec::tele17, 0, 1>.use && detail::image_v<demo_vec::tele17, 0, 1>.add);
    static_assert(detail::image_v<demo_vec::tele17, 0, 0>.use && detail::lanes_v<demo_vec::tele17, true>.win[0].tail == 4);
    static_assert(detail::image_v<demo_vec::tele24, 0, 1>.use && !detail::image_v<demo_vec::tele24, 0, 1>.add &&
                  detail::image_v<demo_vec::tele24, 0, 1>.words == 2);
    static_assert(detail::image_v<demo_vec::tele24, 0, 0>.use && !detail::image_v<demo_vec::tele24, 0, 0>.add);
    static_assert(detail::image_v<demo_vec::tele13, 0, 1>.use && detail::lanes_v<demo_vec::tele13, true>.win[0].tail == 8);
    static_assert(detail::image_v<demo_vec::tele9, 0, 1>.use && detail::lanes_v<demo_vec::tele9, true>.win[0].tail == 1);
    // decode of 15 bytes: the same two loads
    static_assert(detail::lanes_v<demo_vec::tele13, false>.win[0].tail == 8);
    static_assert(detail::lanes_v<demo_vec::tele9, false>.win[0].tail == 1);
#endif
    const auto oor = [](std::size_t) { return errc::value_out_of_range; };
    // a 10, b -50, c fast, d 0xEE, e 100, f 200, g 1, h -5, i 20, j 0, k -1, l 99
    every_byte(std::array<std::uint8_t, 17>{0x7E, 0x01, 10, 0xCE, 3, 0xEE, 100, 200, 1, 0xFB, 20, 0, 0xFF, 99, 0, 0, 0xE7},
               demo_vec::tele17{10, -50, demo_vec::mode::fast, 0xEE, 100, 200, 1, -5, 20, 0, -1, 99},
               {2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13},
               [](std::size_t off, std::uint8_t v) {
                   const auto s = static_cast<std::int8_t>(v);
                   switch (off) {
                   case 2: return v <= 10;
                   case 3: return s >= -50 && s <= 50;
                   case 4: return v >= 1 && v <= 3;
                   case 6: return s >= -100 && s <= 100;
                   case 7: return v <= 200;
                   case 8: return v <= 1;
                   case 9: return s >= -5 && s <= 5;
                   case 10: return v >= 10 && v <= 20;
                   case 12: return s >= -1 && s <= 1;
                   case 13: return v <= 99;
                   default: return true;  // d, j
                   }
               },
               [](std::size_t off) { return off == 4 ? errc::invalid_enum : errc::value_out_of_range; }, 2);
    // a 63, b -127, c slow, d 0x80, e 0, f 127, g 6, h -128
    every_byte(std::array<std::uint8_t, 24>{0xAA, 0xBB, 0xCC, 0xDD, 0, 0, 0, 0, 63, 0x81, 1, 0x80, 0, 127, 6, 0x80,
                                            0, 0, 0, 0, 0, 0, 0, 0x99},
               demo_vec::tele24{63, -127, demo_vec::mode::slow, 0x80, 0, 127, 6, -128}, {8, 9, 10, 11, 12, 13, 14, 15},
               [](std::size_t off, std::uint8_t v) {
                   switch (off) {
                   case 8: return v <= 63;
                   case 9: return v != 0x80;
                   case 10: return v >= 1 && v <= 3;
                   case 12: return v <= 1;
                   case 13: return v <= 127;
                   case 14: return v == 5 || v == 6;
                   case 15: return v == 0 || v >= 0x80;
                   default: return true;  // d
                   }
               },
               [](std::size_t off) { return off == 10 ? errc::invalid_enum : errc::value_out_of_range; }, 8);
    // a 9, b {-100, 100, 0, 1, -1, 50, -50, 99, -99, 7, -7}, c 255
    every_byte(std::array<std::uint8_t, 15>{0x42, 9, 0x9C, 100, 0, 1, 0xFF, 50, 0xCE, 99, 0x9D, 7, 0xF9, 255, 0},
               demo_vec::tele13{9, {-100, 100, 0, 1, -1, 50, -50, 99, -99, 7, -7}, 255},
               {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13},
               [](std::size_t off, std::uint8_t v) {
                   const auto s = static_cast<std::int8_t>(v);
                   return off == 1 ? v <= 9 : off == 13 ? v >= 1 : s >= -100 && s <= 100;
               },
               oor, 1);
    // a 1, b {0, 100, 50, 25, 12, 6, 3}, c -3
    every_byte(std::array<std::uint8_t, 15>{0x10, 0x20, 0x30, 1, 0, 100, 50, 25, 12, 6, 3, 0xFD, 0, 0, 0},
               demo_vec::tele9{1, {0, 100, 50, 25, 12, 6, 3}, -3}, {3, 4, 5, 6, 7, 8, 9, 10, 11},
               [](std::size_t off, std::uint8_t v) {
                   const auto s = static_cast<std::int8_t>(v);
                   return off == 3 ? v <= 1 : off == 11 ? s >= -3 && s <= 3 : v <= 100;
               },
               oor, 3);
    // the first error in table order, two fields failing
    demo_vec::tele17 m{10, -50, demo_vec::mode::fast, 0xEE, 100, 200, 1, -5, 20, 0, -1, 99};
    m.l = 100;
    m.e = -101;
    CHECK(encode(m).error() == error{errc::value_out_of_range, 6});
}

TEST_CASE("vector checks: members in another order than the wire's", "[core][vector]") {
#if ROBOWIRE_SSE2 && !ROBOWIRE_OPTIMIZE_SIZE
    static_assert(detail::decoded_image_ok<demo_vec::backwards>());  // tried, and turned down at run time
#endif
    // a 9, b -9, c 19
    const std::array<std::uint8_t, 16> frame{0x3C, 9, 0xF7, 19};
    const demo_vec::backwards value{19, -9, 9};
    CHECK(decode<demo_vec::backwards>(frame).value() == value);
    CHECK(encode(value).value() == bytes<16>::from(frame).value());
    auto in = frame;
    in[3] = 20;
    CHECK(decode<demo_vec::backwards>(in).error() == error{errc::value_out_of_range, 3});
    in[2] = 0xF6;
    CHECK(decode<demo_vec::backwards>(in).error() == error{errc::value_out_of_range, 2});
    auto m = value;
    m.a = 10;
    CHECK(encode(m).error() == error{errc::value_out_of_range, 1});
}
