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

// Members that no field covers: kept by the application, never touched by a decode.
namespace app {
struct counted {
    std::uint8_t speed = 0;
    std::uint32_t received = 0;  // not on the wire
};
struct bare {  // no member initialisers: value-initialised in a decoded variant
    std::uint8_t speed;
    std::uint32_t app;  // not on the wire
};
struct other {
    std::uint8_t x = 0;
};
constexpr auto table_of(std::type_identity<counted>) {
    using namespace robowire;
    auto t = make_table<counted>("counted", {{0, 0x30, errc::bad_command}}, field{"speed", &counted::speed, 1, wire::u8{}});
    t.members_not_on_wire = 1;
    return t;
}
constexpr auto table_of(std::type_identity<bare>) {
    using namespace robowire;
    auto t = make_table<bare>("bare", {{0, 0x30, errc::bad_command}}, field{"speed", &bare::speed, 1, wire::u8{}});
    t.members_not_on_wire = 1;
    return t;
}
constexpr auto table_of(std::type_identity<other>) {
    using namespace robowire;
    return make_table<other>("other", {{0, 0x31, errc::bad_command}}, field{"x", &other::x, 1, wire::u8{}});
}
using any = std::variant<bare, other>;
// Tables whose member count check cannot see a member left out: a decode
// must keep its member initialiser, as for a member outside the table.
struct with_ctor {  // not an aggregate: the member count is not checked
    std::uint8_t speed = 0;
    std::uint8_t retries = 3;  // no field
    constexpr with_ctor() = default;
    constexpr explicit with_ctor(std::uint8_t s) : speed(s) {}
};
struct named_twice {  // two fields, two members, one of them never written
    std::uint8_t lo = 0;
    std::uint8_t mode = 9;
};
struct header {
    std::uint8_t channel = 0;
    std::uint8_t retries = 3;  // no field
};
struct derived : header {  // the base counts as one member
    std::uint8_t speed = 0;
};
constexpr auto table_of(std::type_identity<with_ctor>) {
    using namespace robowire;
    return make_table<with_ctor>("with_ctor", {{0, 0xA5, errc::bad_header}},
                                 field{"speed", &with_ctor::speed, 1, wire::u8{}});
}
constexpr auto table_of(std::type_identity<named_twice>) {
    using namespace robowire;
    return make_table<named_twice>("named_twice", {{0, 0xA6, errc::bad_header}},
                                   field{"lo", &named_twice::lo, 1, wire::u8{}},
                                   field{"lo_again", &named_twice::lo, 2, wire::u8{}});
}
constexpr auto table_of(std::type_identity<derived>) {
    using namespace robowire;
    return make_table<derived>("derived", {{0, 0xA7, errc::bad_header}}, field{"channel", &derived::channel, 1, wire::u8{}},
                               field{"speed", &derived::speed, 2, wire::u8{}});
}
constexpr std::uint8_t with_ctor_in[] = {0xA5, 42}, named_twice_in[] = {0xA6, 5, 5}, derived_in[] = {0xA7, 1, 42};

// decode_into refreshes the fields and leaves the rest as it was.
constexpr bool keeps_what_is_not_on_the_wire() {
    counted m;
    m.received = 41;
    const std::uint8_t in[] = {0x30, 7};
    return robowire::decode_into(m, in).code == robowire::errc::ok && m.speed == 7 && m.received == 41;
}
// decode_variant makes the alternative as std::variant(std::in_place_index<I>) does.
constexpr bool value_initialises_what_is_not_on_the_wire() {
    const std::uint8_t in[] = {0x30, 7};
    const auto r = robowire::decode_variant<any>(in);
    return r && std::get<bare>(*r).speed == 7 && std::get<bare>(*r).app == 0;
}
}  // namespace app

using namespace robowire;

TEST_CASE("a decode leaves members that are not on the wire alone", "[core][dispatch]") {
    // only a message whose every member a decode writes may skip its initialisers or go through a local
    STATIC_REQUIRE(!robowire::detail::flat_record_v<app::counted>);
    STATIC_REQUIRE(!robowire::detail::flat_record_v<app::bare>);
    STATIC_REQUIRE(robowire::detail::flat_record_v<app::other>);
    STATIC_REQUIRE(!robowire::detail::flat_record_v<app::with_ctor>);
    STATIC_REQUIRE(!robowire::detail::flat_record_v<app::named_twice>);
    STATIC_REQUIRE(!robowire::detail::flat_record_v<app::derived>);
    STATIC_REQUIRE(robowire::decode<app::with_ctor>(app::with_ctor_in)->retries == 3);
    STATIC_REQUIRE(robowire::decode<app::named_twice>(app::named_twice_in)->mode == 9);
    STATIC_REQUIRE(robowire::decode<app::derived>(app::derived_in)->retries == 3);
    CHECK(robowire::decode<app::with_ctor>(app::with_ctor_in)->retries == 3);
    CHECK(robowire::decode<app::named_twice>(app::named_twice_in)->mode == 9);
    CHECK(robowire::decode<app::derived>(app::derived_in)->retries == 3);
    STATIC_REQUIRE(app::keeps_what_is_not_on_the_wire());
    CHECK(app::keeps_what_is_not_on_the_wire());
    STATIC_REQUIRE(app::value_initialises_what_is_not_on_the_wire());
    CHECK(app::value_initialises_what_is_not_on_the_wire());
}

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
