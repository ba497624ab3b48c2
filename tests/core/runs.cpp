// Runs of fields copied at once (ROBOWIRE_COPY_RUNS): a short run may be
// copied wider, into padding or into the next run's memory, but never over a
// member written before it. Layouts made up for the test; the expected
// values come from the input bytes, by hand.
#include <robowire/core.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>

namespace demo_runs {
// 9 bytes, padding, then a 4-byte run: the first run may be copied as 16 bytes.
struct padded {
    std::array<std::uint8_t, 9> a{};
    std::uint32_t b = 0, c = 0;
    friend constexpr bool operator==(const padded&, const padded&) = default;
};
constexpr auto table_of(std::type_identity<padded>) {
    using namespace robowire;
    return make_table<padded>("padded", {{0, 0xA5, errc::bad_header}}, field{"a", &padded::a, 1, wire::u8{}},
                              field{"b", &padded::b, 10, wire::u32le{}}, field{"c", &padded::c, 14, wire::u32le{}});
}
// x is first on the wire but after a in memory: a's run (9 bytes, then a
// 4-byte run at b) must not be copied wider, over x, written before it.
struct crossed {
    std::array<std::uint8_t, 9> a{};
    std::uint8_t x = 0;
    std::uint32_t b = 0, c = 0;
    friend constexpr bool operator==(const crossed&, const crossed&) = default;
};
constexpr auto table_of(std::type_identity<crossed>) {
    using namespace robowire;
    return make_table<crossed>("crossed", {{0, 0xA5, errc::bad_header}}, field{"x", &crossed::x, 1, wire::u8{}},
                               field{"a", &crossed::a, 2, wire::u8{}}, field{"b", &crossed::b, 11, wire::u32le{}},
                               field{"c", &crossed::c, 15, wire::u32le{}});
}
// 12 bytes (a 16-byte copy's reach), then a 2-byte field: its run of 12 is
// followed by 2 bytes of padding and the next run.
struct twelve {
    std::array<std::uint8_t, 12> a{};
    std::uint16_t pad_before_b = 0;  // on the wire too: keeps the layout of the case below
    std::uint32_t b = 0;
    friend constexpr bool operator==(const twelve&, const twelve&) = default;
};
constexpr auto table_of(std::type_identity<twelve>) {
    using namespace robowire;
    return make_table<twelve>("twelve", {{0, 0xA5, errc::bad_header}}, field{"a", &twelve::a, 1, wire::u8{}},
                              field{"pad_before_b", &twelve::pad_before_b, 13, wire::u16le{}},
                              field{"b", &twelve::b, 15, wire::u32le{}});
}
}  // namespace demo_runs

using namespace robowire;

TEST_CASE("runs: a short run copied wider lands in padding or the next run, never on an earlier field",
          "[core][runs]") {
    const std::array<std::uint8_t, 18> p{0xA5, 1, 2, 3, 4, 5, 6, 7, 8, 9, 0x44, 0x55, 0x66, 0x77, 0xEF, 0xBE, 0xAD, 0xDE};
    const demo_runs::padded pw{{1, 2, 3, 4, 5, 6, 7, 8, 9}, 0x77665544u, 0xDEADBEEFu};
    const auto pd = decode<demo_runs::padded>(p);
    REQUIRE(pd.has_value());
    CHECK(*pd == pw);
    demo_runs::padded into{};
    CHECK(decode_into(into, p) == error{});
    CHECK(into == pw);

    constexpr std::array<std::uint8_t, 19> c{0xA5, 0xA0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 0x34, 0x12, 0, 0, 1, 0, 0, 0};
    const demo_runs::crossed cw{{1, 2, 3, 4, 5, 6, 7, 8, 9}, 0xA0, 0x1234, 1};
    const auto cr = decode<demo_runs::crossed>(c);
    REQUIRE(cr.has_value());
    CHECK(cr->x == 0xA0);  // not the wire byte 11 (0x34) that a 16-byte copy of a would put there
    CHECK(*cr == cw);
    demo_runs::crossed cinto{};
    CHECK(decode_into(cinto, c) == error{});
    CHECK(cinto == cw);

    const std::array<std::uint8_t, 19> t{0xA5, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0xCD, 0xAB, 0x78, 0x56, 0x34, 0x12};
    const auto tw = decode<demo_runs::twelve>(t);
    REQUIRE(tw.has_value());
    CHECK(*tw == demo_runs::twelve{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}, 0xABCD, 0x12345678u});
    STATIC_REQUIRE(decode<demo_runs::crossed>(c)->x == 0xA0);
}
