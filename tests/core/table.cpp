// The generic table-driven codec, on a message made up for the test.
#include <robowire/core/decode.hpp>
#include <robowire/core/encode.hpp>
#include <robowire/core/table.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <optional>

#include "check.hpp"

namespace demo {
enum class mode : std::uint8_t { off = 0, slow = 0x10, fast = 0x14 };
constexpr auto enum_table_of(std::type_identity<mode>) {
    return std::array<robowire::enum_entry<mode>, 3>{{{mode::off, "off"}, {mode::slow, "slow"}, {mode::fast, "fast"}}};
}
struct pair {
    std::uint8_t kind{};
    std::int16_t where{};
    friend constexpr bool operator==(const pair&, const pair&) = default;
};
constexpr auto table_of(std::type_identity<pair>) {
    using namespace robowire;
    return make_record<pair>("pair", field{"kind", &pair::kind, 0, wire::u8{}},
                             field{"where", &pair::where, 1, wire::i16le{}, unit{"deg"}});
}
struct msg {
    std::array<std::int8_t, 2> power{};
    mode how{};
    std::array<pair, 2> pairs{};
    std::uint8_t low{};
    std::uint8_t high{};
    bool on{};
    std::optional<float> gain{};
    std::optional<std::uint8_t> extra{};
    friend constexpr bool operator==(const msg&, const msg&) = default;
};
// 0:0x30 | 1-2 power i8 -127..127 | 3 how | 4-9 2 x pair | 10 low bits 0-3, high bits 4-7 | 11 on | [12-15 gain f32] [16 extra]
constexpr auto table_of(std::type_identity<msg>) {
    using namespace robowire;
    return make_table<msg>("msg", {{0, 0x30, errc::bad_command}},
                           field{"power", &msg::power, 1, wire::i8{}, range{-127, 127}, unit{"%"}},
                           field{"how", &msg::how, 3, wire::u8{}}, field{"pairs", &msg::pairs, 4, wire::record{}},
                           field{"low", &msg::low, 10, wire::bits<0, 4>{}}, field{"high", &msg::high, 10, wire::bits<4, 4>{}},
                           field{"on", &msg::on, 11, wire::u8{}}, field{"gain", &msg::gain, 12, wire::f32le{}},
                           field{"extra", &msg::extra, 16, wire::u8{}, range{0, 9}});
}
// 0:0x40 | 1-4 name text<4> | 5 reserved | 6 x | 7 reserved (declared_size 8)
struct named {
    robowire::text<4> name{};
    std::uint8_t x{};
};
constexpr auto table_of(std::type_identity<named>) {
    using namespace robowire;
    auto t = make_table<named>("named", {{0, 0x40, errc::bad_command}}, field{"name", &named::name, 1, wire::text{}},
                               field{"x", &named::x, 6, wire::u8{}, range{0, 9}});
    t.declared_size = 8;
    return t;
}
}  // namespace demo

using namespace robowire;
using demo::msg;

namespace {
// power 5, -5 (0xFB); how fast (0x14); pairs {1, 0x1234} {2, -1}; low 5 high 0xA -> 0xA5; on
constexpr auto base = test::hex("30 05 FB 14 01 34 12 02 FF FF A5 01");
// ... + gain 0.6f (0x3F19999A little-endian) + extra 9
constexpr auto full = test::hex("30 05 FB 14 01 34 12 02 FF FF A5 01 9A 99 19 3F 09");
constexpr msg base_msg{{5, -5}, demo::mode::fast, {{{1, 0x1234}, {2, -1}}}, 5, 0xA, true, std::nullopt, std::nullopt};
constexpr msg full_msg{{5, -5}, demo::mode::fast, {{{1, 0x1234}, {2, -1}}}, 5, 0xA, true, 0.6f, std::uint8_t{9}};

template <std::size_t N>
constexpr bytes<N> with(bytes<N> b, std::size_t i, std::uint8_t v) {
    b[i] = v;
    return b;
}
constexpr error decode_error(std::span<const std::uint8_t> in) { return decode<msg>(in).error(); }
constexpr error encode_error(const msg& m) { return encode(m).error(); }
}  // namespace

TEST_CASE("table sizes come from the fields", "[core][table]") {
    STATIC_REQUIRE(min_size_v<msg> == 12);
    STATIC_REQUIRE(max_size_v<msg> == 17);
    STATIC_REQUIRE(table_v<demo::pair>.max_size() == 3);
    STATIC_REQUIRE(table_v<msg>.field_count == 8);
    STATIC_REQUIRE(table_v<msg>.fields.get<2>().count == 2);
    STATIC_REQUIRE(table_v<msg>.fields.get<2>().size == 6);
}

TEST_CASE("table-driven decode", "[core][table]") {
    STATIC_REQUIRE(decode<msg>(base).value() == base_msg);
    STATIC_REQUIRE(decode<msg>(full).value() == full_msg);
    CHECK(decode<msg>(base).value() == base_msg);
    CHECK(decode<msg>(full).value() == full_msg);
}

TEST_CASE("table-driven encode", "[core][table]") {
    STATIC_REQUIRE(encode(base_msg).value() == base);
    STATIC_REQUIRE(encode(full_msg).value() == full);
    CHECK(encode(full_msg).value() == full);
    std::array<std::uint8_t, 17> out{};
    CHECK(encode_to(full_msg, out).value() == 17);
    CHECK(test::same(out, full));
    std::array<std::uint8_t, 16> small{};
    CHECK(encode_to(full_msg, small).error() == error{errc::buffer_too_small, 17});
}

TEST_CASE("decode_into refreshes an existing object", "[core][table]") {
    msg m = full_msg;
    REQUIRE(decode_into(m, base) == error{});
    CHECK(m == base_msg);  // the optional blocks absent again
    REQUIRE(decode_into(m, full) == error{});
    CHECK(m == full_msg);
    CHECK(decode_into(m, base.span().first(5)) == error{errc::too_short, 5});
}

TEST_CASE("table-driven decode errors name the byte", "[core][table]") {
    STATIC_REQUIRE(decode_error(with(base, 0, 0x31)) == error{errc::bad_command, 0});
    STATIC_REQUIRE(decode_error(base.span().first(11)) == error{errc::too_short, 11});
    STATIC_REQUIRE(decode_error(base.span().first(1).subspan(1)) == error{errc::too_short, 0});
    STATIC_REQUIRE(decode_error(full.span().first(14)) == error{errc::bad_length, 12});  // truncated gain
    STATIC_REQUIRE(decode_error(with(full, 16, 10)) == error{errc::value_out_of_range, 16});
    STATIC_REQUIRE(decode_error(with(base, 2, 0x80)) == error{errc::value_out_of_range, 2});  // -128
    STATIC_REQUIRE(decode_error(with(base, 3, 0x11)) == error{errc::invalid_enum, 3});
    STATIC_REQUIRE(decode_error(with(base, 11, 2)) == error{errc::value_out_of_range, 11});  // bool
    auto longer = full;
    REQUIRE(longer.push_back(0));
    CHECK(decode_error(longer) == error{errc::too_long, 17});
}

TEST_CASE("table-driven encode rejects what it cannot send", "[core][table]") {
    constexpr auto m = [](auto change) { msg x = full_msg; change(x); return x; };
    STATIC_REQUIRE(encode_error(m([](msg& x) { x.power[1] = -128; })) == error{errc::value_out_of_range, 2});
    STATIC_REQUIRE(encode_error(m([](msg& x) { x.how = demo::mode{3}; })) == error{errc::invalid_enum, 3});
    STATIC_REQUIRE(encode_error(m([](msg& x) { x.high = 16; })) == error{errc::value_out_of_range, 10});
    STATIC_REQUIRE(encode_error(m([](msg& x) { x.extra = 10; })) == error{errc::value_out_of_range, 16});
    constexpr auto extra_without_gain = [] { msg x = base_msg; x.extra = 1; return x; }();
    STATIC_REQUIRE(encode_error(extra_without_gain) == error{errc::missing_field, 12});
}

TEST_CASE("round trip keeps NaN payloads", "[core][table]") {
    msg x = full_msg;
    x.gain = robowire::detail::builtin_bit_cast<float>(0x7FC01234u);
    const auto wire = encode(x).value();
    const auto back = decode<msg>(wire).value();
    CHECK(robowire::detail::builtin_bit_cast<std::uint32_t>(*back.gain) == 0x7FC01234u);
    CHECK(encode(back).value() == wire);
}

namespace {
// encode_to over a buffer full of 0xEE; returns the buffer (or the error's offset in byte 0, 0xEE elsewhere).
template <class M>
constexpr bytes<20> encode_over_dirty(const M& m, std::size_t room) {
    bytes<20> buf = bytes<20>::zeros(20);
    for (auto& b : buf) b = 0xEE;
    const auto n = encode_to(m, buf.span().first(room));
    if (!n) buf[0] = static_cast<std::uint8_t>(n.error().offset);
    return buf;
}
}  // namespace

TEST_CASE("encode_to writes every byte of the message into a used buffer", "[core][table]") {
    // Bit fields (byte 10) are cleared before they are or-ed in; bytes after the message stay.
    STATIC_REQUIRE(encode_over_dirty(full_msg, 20) ==
                   test::hex("30 05 FB 14 01 34 12 02 FF FF A5 01 9A 99 19 3F 09 EE EE EE"));
    STATIC_REQUIRE(encode_over_dirty(base_msg, 20) ==
                   test::hex("30 05 FB 14 01 34 12 02 FF FF A5 01 EE EE EE EE EE EE EE EE"));
    // Text padding and reserved bytes (5, 7) are written as zero.
    STATIC_REQUIRE(encode_over_dirty(demo::named{"AB", 7}, 20) ==
                   test::hex("40 41 42 00 00 00 07 00 EE EE EE EE EE EE EE EE EE EE EE EE"));
    CHECK(encode_over_dirty(demo::named{"AB", 7}, 20) ==
          test::hex("40 41 42 00 00 00 07 00 EE EE EE EE EE EE EE EE EE EE EE EE"));
    CHECK(encode_over_dirty(full_msg, 20) == test::hex("30 05 FB 14 01 34 12 02 FF FF A5 01 9A 99 19 3F 09 EE EE EE"));
}

TEST_CASE("encode_to leaves the buffer alone on an error", "[core][table]") {
    // Range error at byte 6 (x = 10 > 9): nothing written; the error's offset lands in byte 0 only.
    STATIC_REQUIRE(encode_over_dirty(demo::named{"AB", 10}, 20) ==
                   test::hex("06 EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE"));
    // Too small a buffer: buffer_too_small with the size needed (8), nothing written.
    STATIC_REQUIRE(encode_over_dirty(demo::named{"AB", 7}, 7) ==
                   test::hex("08 EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE EE"));
    std::array<std::uint8_t, 8> out{};
    out.fill(0xEE);
    CHECK(encode_to(demo::named{"AB", 10}, out).error() == error{errc::value_out_of_range, 6});
    CHECK(encode_to(demo::named{"AB", 7}, std::span(out).first(7)).error() == error{errc::buffer_too_small, 8});
    for (auto b : out) CHECK(b == 0xEE);
}

namespace enums {
// Three shapes of code set, each checked its own way: a run (one range
// compare), codes with gaps below 32 (a bit set), a code of 32 or more (the table).
enum class run : std::int8_t { a = -1, b = 0, c = 1, d = 2 };
enum class gaps : std::uint8_t { a = 1, b = 4, c = 31 };
enum class big : std::uint8_t { a = 0, b = 32, c = 200 };
constexpr auto enum_table_of(std::type_identity<run>) {
    return std::array<enum_entry<run>, 4>{{{run::a, "a"}, {run::b, "b"}, {run::c, "c"}, {run::d, "d"}}};
}
constexpr auto enum_table_of(std::type_identity<gaps>) {
    return std::array<enum_entry<gaps>, 3>{{{gaps::a, "a"}, {gaps::b, "b"}, {gaps::c, "c"}}};
}
constexpr auto enum_table_of(std::type_identity<big>) {
    return std::array<enum_entry<big>, 3>{{{big::a, "a"}, {big::b, "b"}, {big::c, "c"}}};
}
// Number of codes in [lo, hi] that is_valid_enum accepts.
template <class E>
constexpr int accepted(int lo, int hi) {
    int n = 0;
    for (int v = lo; v <= hi; ++v) n += is_valid_enum(static_cast<E>(v));
    return n;
}
}  // namespace enums

TEST_CASE("is_valid_enum: runs, codes with gaps, large codes", "[core]") {
    using namespace enums;
    STATIC_REQUIRE(accepted<run>(-128, 127) == 4);
    STATIC_REQUIRE((is_valid_enum(run::a) && is_valid_enum(run::d) && !is_valid_enum(static_cast<run>(3)) &&
                   !is_valid_enum(static_cast<run>(-2))));
    STATIC_REQUIRE(accepted<gaps>(0, 255) == 3);
    STATIC_REQUIRE((is_valid_enum(gaps::c) && !is_valid_enum(static_cast<gaps>(0)) && !is_valid_enum(static_cast<gaps>(5)) &&
                   !is_valid_enum(static_cast<gaps>(32)) && !is_valid_enum(static_cast<gaps>(255))));
    STATIC_REQUIRE(accepted<big>(0, 255) == 3);
    STATIC_REQUIRE((is_valid_enum(big::c) && !is_valid_enum(static_cast<big>(1)) && !is_valid_enum(static_cast<big>(33))));
    // the same at run time (a volatile bound keeps the loops from folding)
    volatile int top = 255;
    CHECK(accepted<run>(-128, top - 128) == 4);
    CHECK(accepted<gaps>(0, top) == 3);
    CHECK(accepted<big>(0, top) == 3);
}

TEST_CASE("detail::in_range: bounds clamped to what the wire holds, 32- and 64-bit forms", "[core]") {
    using robowire::detail::in_range;
    // i8 wire, valid -100..100
    STATIC_REQUIRE((in_range<-100, 100, -128, 127>(-100) && in_range<-100, 100, -128, 127>(100)));
    STATIC_REQUIRE((!in_range<-100, 100, -128, 127>(-101) && !in_range<-100, 100, -128, 127>(101)));
    // valid range wider than the wire on one side
    STATIC_REQUIRE((in_range<-1000, 5, -128, 127>(-128) && !in_range<-1000, 5, -128, 127>(6)));
    // no wire value valid
    STATIC_REQUIRE((!in_range<200, 300, -128, 127>(127) && !in_range<200, 300, -128, 127>(-128)));
    // u32 wire (unsigned 32-bit form)
    STATIC_REQUIRE((in_range<10, 4000000000, 0, 4294967295>(4000000000) &&
                   !in_range<10, 4000000000, 0, 4294967295>(4000000001) && !in_range<10, 4000000000, 0, 4294967295>(9)));
    // u32 wire bounded below only (BuWizz3 0x21 idle timeout >= 10): the top of the wire range is valid
    STATIC_REQUIRE((in_range<10, 4294967295, 0, 4294967295>(4294967295) && in_range<10, 4294967295, 0, 4294967295>(10) &&
                   !in_range<10, 4294967295, 0, 4294967295>(9) && !in_range<10, 4294967295, 0, 4294967295>(0)));
    // a range wider than 32 bits (64-bit form)
    STATIC_REQUIRE((in_range<-5000000000, 5000000000, -10000000000, 10000000000>(-5000000000) &&
                   !in_range<-5000000000, 5000000000, -10000000000, 10000000000>(5000000001) &&
                   !in_range<-5000000000, 5000000000, -10000000000, 10000000000>(-5000000001)));
    volatile std::int64_t v = -101;  // and at run time
    CHECK(!in_range<-100, 100, -128, 127>(v));
    v = 0;
    CHECK(in_range<-100, 100, -128, 127>(v));
    v = 4294967295;
    CHECK(in_range<10, 4294967295, 0, 4294967295>(v));
    v = 9;
    CHECK(!in_range<10, 4294967295, 0, 4294967295>(v));
}
