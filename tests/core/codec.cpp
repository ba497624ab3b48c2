// robowire::codec, the steps a protocol's own dispatcher and encoder use, on
// messages made up for the test (frames A5 CMD ...).
#include <robowire/core/dispatch.hpp>
#include <robowire/core/uuid.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <utility>
#include <variant>

#include "check.hpp"

namespace demo3 {
struct ping {
    std::uint8_t seq{};
    friend constexpr bool operator==(const ping&, const ping&) = default;
};
struct pong {
    std::int16_t seq{};
    friend constexpr bool operator==(const pong&, const pong&) = default;
};
constexpr auto table_of(std::type_identity<ping>) {
    using namespace robowire;
    return make_table<ping>("ping", {{0, 0xA5, errc::bad_header}, {1, 0x01, errc::bad_command}},
                            field{"seq", &ping::seq, 2, wire::u8{}, range{0, 99}});
}
constexpr auto table_of(std::type_identity<pong>) {
    using namespace robowire;
    return make_table<pong>("pong", {{0, 0xA5, errc::bad_header}, {1, 0x02, errc::bad_command}},
                            field{"seq", &pong::seq, 2, wire::i16le{}, range{-1000, 1000}});
}
using any = std::variant<ping, pong>;
}  // namespace demo3

using namespace robowire;

namespace {
constexpr error fixed_error(std::span<const std::uint8_t> in) {
    return codec::check_fixed<demo3::pong>(in, std::make_index_sequence<2>{});
}
constexpr std::int16_t fields_of(std::span<const std::uint8_t> in, error& e) {
    demo3::pong p{};
    e = codec::decode_fields(p, in);
    return p.seq;
}
// decode_fields for an output discarded on an error: the same fields and errors.
constexpr std::int16_t fields_once(std::span<const std::uint8_t> in, error& e) {
    demo3::pong p{};
    e = codec::decode_fields(p, in, codec::discarded_on_error);
    return e.code == errc::ok ? p.seq : std::int16_t{-1};
}
// A dispatcher's result holding alternative 0, its flag set: alternative 1
// made in its place, the flag kept.
constexpr result<demo3::any> remade(std::int16_t seq) {
    result<demo3::any> r = demo3::any{demo3::ping{7}};
    codec::make_alternative_keep_flag<1>(r).seq = seq;
    return r;
}
// check_fields, then store_fields into a frame of zeros; the error, if any.
constexpr result<bytes<4>> store(const demo3::pong& p) {
    auto b = bytes<4>::zeros(4);
    error err{};
    if (!codec::check_fields(p, err)) return err;
    codec::store_fields(p, b.span());
    return b;
}
// The index and sequence number of the alternative v holds, through visit_held.
constexpr int held(const demo3::any& v) {
    int out = -1;
    codec::visit_held(v, [&](const auto& m) { out = static_cast<int>(v.index()) * 1000 + m.seq; });
    return out;
}
constexpr demo3::any built(std::int16_t seq) {
    demo3::any v;
    codec::emplace_alternative<1>(v).seq = seq;
    return v;
}
constexpr result<bytes<4>> unset_then_sized() {
    result<bytes<4>> r{std::in_place, codec::unset_t{}};
    auto& b = codec::unchecked_value(r);
    const std::array<std::uint8_t, 4> src{0xA5, 0x01, 0x07, 0x00};  // every byte, unused capacity zero
    codec::copy_small(b.data(), src.data(), src.size());
    codec::set_written_size(b, 3);
    return r;
}
}  // namespace

TEST_CASE("codec: fixed bytes and fields, as a dispatcher checks and decodes them", "[core][codec]") {
    STATIC_REQUIRE(fixed_error(test::hex("A5 02 34 12")) == error{});
    STATIC_REQUIRE(fixed_error(test::hex("A5 01 34 12")) == error{errc::bad_command, 1});
    STATIC_REQUIRE(fixed_error(test::hex("A4 01")) == error{errc::bad_header, 0});
    STATIC_REQUIRE(fixed_error(test::hex("A5")) == error{});  // bytes past the input are not checked
    STATIC_REQUIRE(codec::key_of<demo3::pong>(1) == 0x02);
    STATIC_REQUIRE(codec::key_of<demo3::pong>(3) == -1);
    error e{};
    CHECK(fields_of(test::hex("00 00 E8 03"), e) == 1000);  // fixed bytes not checked: the caller's
    CHECK(e == error{});
    CHECK(fields_of(test::hex("A5 02 E9 03"), e) == 0);
    CHECK(e == error{errc::value_out_of_range, 2});
    STATIC_REQUIRE([] {
        error err{};
        return fields_of(test::hex("A5 02 18 FC"), err) == -1000 && err == error{};
    }());
    CHECK(fields_once(test::hex("00 00 E8 03"), e) == 1000);
    CHECK(e == error{});
    CHECK(fields_once(test::hex("A5 02 18 FC"), e) == -1000);
    CHECK(fields_once(test::hex("A5 02 E9 03"), e) == -1);
    CHECK(e == error{errc::value_out_of_range, 2});
    STATIC_REQUIRE([] {
        error err{};
        return fields_once(test::hex("A5 02 17 FC"), err) == -1 && err == error{errc::value_out_of_range, 2};
    }());
    STATIC_REQUIRE(remade(-5).value() == demo3::any{demo3::pong{-5}});
    CHECK(remade(300).value() == demo3::any{demo3::pong{300}});
}

// decode_at<M>(pointer, size): decode<M> of the same bytes, errors included;
// only `size` bytes are read (the byte after them is not part of the input).
TEST_CASE("codec::decode_at decodes pointer and size as decode does a span", "[core][codec]") {
    constexpr std::array<std::uint8_t, 5> in{0xA5, 0x02, 0x18, 0xFC, 0x99};  // pong -1000, then a byte not passed
    STATIC_REQUIRE(codec::decode_at<demo3::pong>(in.data(), 4).value() == demo3::pong{-1000});
    STATIC_REQUIRE(codec::decode_at<demo3::pong>(in.data(), 3).error() == error{errc::too_short, 3});
    STATIC_REQUIRE(codec::decode_at<demo3::pong>(in.data(), 5).error() == error{errc::too_long, 4});
    STATIC_REQUIRE(codec::decode_at<demo3::ping>(in.data(), 3).error() == error{errc::bad_command, 1});
    const auto bad = test::hex("A5 02 E9 03");  // 1001: out of range
    CHECK(codec::decode_at<demo3::pong>(bad.data(), bad.size()).error() == error{errc::value_out_of_range, 2});
    CHECK(codec::decode_at<demo3::pong>(bad.data(), bad.size()).error() ==
          decode<demo3::pong>(std::span(bad)).error());
    CHECK(codec::decode_at<demo3::pong>(in.data(), 4).value() == demo3::pong{-1000});
}

TEST_CASE("codec: check_fields then store_fields, as an encoder writes a frame", "[core][codec]") {
    STATIC_REQUIRE(store(demo3::pong{-2}).value() == test::hex("00 00 FE FF"));
    STATIC_REQUIRE(store(demo3::pong{1001}).error() == error{errc::value_out_of_range, 2});
    CHECK(store(demo3::pong{0x0102}).value() == test::hex("00 00 02 01"));
    CHECK(store(demo3::pong{-1001}).error() == error{errc::value_out_of_range, 2});
}

TEST_CASE("codec: variant, result and bytes helpers", "[core][codec]") {
    STATIC_REQUIRE(held(demo3::any{demo3::ping{7}}) == 7);
    STATIC_REQUIRE(held(built(12)) == 1012);
    CHECK(held(built(-3)) == 997);
    STATIC_REQUIRE(unset_then_sized().value() == test::hex("A5 01 07"));
    CHECK(unset_then_sized().value() == test::hex("A5 01 07"));
    constexpr result<int> failed = codec::fail_at(errc::too_long, 70000);  // no clamp: the caller's offset
    STATIC_REQUIRE(codec::unchecked_error(failed) == error{errc::too_long, static_cast<std::uint16_t>(70000)});
    STATIC_REQUIRE(fail(errc::too_long, 70000).offset == 0xFFFF);
    STATIC_REQUIRE(&codec::deferred<void>(failed) == &failed);
    constexpr uuid128 u = uuid_literal("6e400011-b5a3-f393-e0a9-e50e24dcca9e");
    STATIC_REQUIRE(u.value[0] == 0x6E);
    STATIC_REQUIRE(u.value[15] == 0x9E);
}

namespace {
// copy_small of n bytes into the middle of a zeroed buffer: exactly n bytes change.
constexpr bool copies_exactly(std::size_t n) {
    std::array<std::uint8_t, 16> from{};
    for (std::size_t i = 0; i < from.size(); ++i) from[i] = static_cast<std::uint8_t>(0xB0 + i);
    std::array<std::uint8_t, 18> to{};
    codec::copy_small(to.data() + 1, from.data(), n);
    for (std::size_t i = 0; i < to.size(); ++i)
        if (to[i] != (i >= 1 && i <= n ? from[i - 1] : 0)) return false;
    return true;
}
constexpr bool copies_0_to_16() {
    for (std::size_t n = 0; n <= 16; ++n)
        if (!copies_exactly(n)) return false;
    return true;
}
}  // namespace

TEST_CASE("codec::copy_small copies 0 to 16 bytes, no more", "[core][codec]") {
    STATIC_REQUIRE(copies_0_to_16());
    for (std::size_t n = 0; n <= 16; ++n) {
        INFO("n = " << n);
        CHECK(copies_exactly(n));
    }
}
