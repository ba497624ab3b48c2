// decode_variant / encode(variant) on messages made up for the test.
#include <robowire/core/dispatch.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"

namespace demo2 {
struct ping {
    std::uint8_t seq{};
    friend constexpr bool operator==(const ping&, const ping&) = default;
};
struct pong {
    std::uint16_t seq{};
    friend constexpr bool operator==(const pong&, const pong&) = default;
};
constexpr auto table_of(std::type_identity<ping>) {
    using namespace robowire;
    return make_table<ping>("ping", {{0, 0xA5, errc::bad_header}, {1, 0x01, errc::bad_command}}, field{"seq", &ping::seq, 2, wire::u8{}, range{0, 99}});
}
constexpr auto table_of(std::type_identity<pong>) {
    using namespace robowire;
    return make_table<pong>("pong", {{0, 0xA5, errc::bad_header}, {1, 0x02, errc::bad_command}}, field{"seq", &pong::seq, 2, wire::u16le{}});
}
using any = std::variant<ping, pong>;
}  // namespace demo2

using namespace robowire;

TEST_CASE("decode_variant picks the alternative by its key byte", "[core][dispatch]") {
    STATIC_REQUIRE(std::get<demo2::ping>(decode_variant<demo2::any, 1>(test::hex("A5 01 07")).value()).seq == 7);
    STATIC_REQUIRE(std::get<demo2::pong>(decode_variant<demo2::any, 1>(test::hex("A5 02 34 12")).value()).seq == 0x1234);
    STATIC_REQUIRE(decode_variant<demo2::any, 1>(test::hex("A5 03 00")).error() == error{errc::unknown_message, 1});
    STATIC_REQUIRE(decode_variant<demo2::any, 1>(test::hex("A5")).error() == error{errc::too_short, 1});
    STATIC_REQUIRE(decode_variant<demo2::any, 1>(test::hex("A4 01 07")).error() == error{errc::bad_header, 0});
    STATIC_REQUIRE(decode_variant<demo2::any, 1>(test::hex("A5 01 64")).error() == error{errc::value_out_of_range, 2});
    STATIC_REQUIRE(variant_max_size_v<demo2::any> == 4);
    STATIC_REQUIRE(robowire::encode(demo2::any{demo2::pong{0x1234}}).value() == test::hex("A5 02 34 12"));
    STATIC_REQUIRE(robowire::encode(demo2::any{demo2::ping{100}}).error() == error{errc::value_out_of_range, 2});
    CHECK(robowire::encode(demo2::any{demo2::ping{5}}).value() == test::hex("A5 01 05"));
}

#if defined(__cpp_exceptions)
namespace demo2 {
// A message whose converting constructor throws: emplacing it leaves a variant
// valueless (a user-written copy keeps the standard library from avoiding that).
struct boom {
    std::uint8_t seq{};
    boom() = default;
    boom(const boom& o) : seq(o.seq) {}
    boom& operator=(const boom& o) { seq = o.seq; return *this; }
    explicit boom(int) { throw 1; }
    friend constexpr bool operator==(const boom&, const boom&) = default;
};
constexpr auto table_of(std::type_identity<boom>) {
    using namespace robowire;
    return make_table<boom>("boom", {{0, 0xA5, errc::bad_header}, {1, 0x03, errc::bad_command}}, field{"seq", &boom::seq, 2, wire::u8{}});
}
}  // namespace demo2

TEST_CASE("encode(variant) of a variant left valueless by an exception is an error", "[core][dispatch]") {
    std::variant<demo2::ping, demo2::boom> v{demo2::ping{1}};
    try {
        v.emplace<demo2::boom>(1);
    } catch (int) {
    }
    REQUIRE(v.valueless_by_exception());
    CHECK(robowire::encode(v).error() == error{errc::unknown_message, 0});
}
#endif
