#include <robowire/core/bytes.hpp>

#include <array>
#include <string>
#include <catch2/catch.hpp>
#include <string_view>

using namespace robowire;

namespace {
constexpr std::array<std::uint8_t, 3> abc{0x01, 0x5C, 0xFF};

constexpr bool hex_is(std::span<const std::uint8_t> in, std::string_view want, char sep = ' ') {
    std::array<char, 64> buf{};
    const auto n = to_hex(in, buf, sep);
    return n && std::string_view(buf.data(), *n) == want;
}
}  // namespace

TEST_CASE("bytes<N> holds up to N bytes", "[core][bytes]") {
    constexpr bytes<4> b{0x01, 0x5C, 0xFF};
    STATIC_REQUIRE(b.size() == 3);
    STATIC_REQUIRE(b.capacity() == 4);
    STATIC_REQUIRE(b[1] == 0x5C);
    STATIC_REQUIRE(b == std::span<const std::uint8_t>(abc));
    STATIC_REQUIRE(b != bytes<4>{0x01, 0x5C});
    STATIC_REQUIRE(bytes<4>::zeros(2) == bytes<4>{0, 0});
    STATIC_REQUIRE(bytes<2>::from(abc).code() == errc::capacity_exceeded);

    bytes<4> r;
    CHECK(r.empty());
    CHECK(r.push_back(1));
    CHECK(r.append(std::array<std::uint8_t, 3>{2, 3, 4}));
    CHECK_FALSE(r.push_back(5));
    CHECK_FALSE(r.append(std::array<std::uint8_t, 1>{5}));
    CHECK(r.size() == 4);
    int sum = 0;
    for (auto x : r) sum += x;
    CHECK(sum == 10);
    r.resize(1);
    CHECK(r == bytes<4>{1});
    r.resize(3);
    CHECK(r == bytes<4>{1, 0, 0});  // grown bytes are zero
}

namespace {
// An error of every code and some offsets survives a round trip through
// result<bytes<N>>, which keeps it inside the bytes; a value then replaces it.
template <std::size_t N>
constexpr bool errors_round_trip() {
    for (int c = 0; c <= static_cast<int>(errc::bad_json); ++c)
        for (const int at : {0, 1, 0x1234, 0xFFFF}) {
            const error e{static_cast<errc>(c), static_cast<std::uint16_t>(at)};
            result<bytes<N>> r = e;
            if (c == 0) continue;  // errc::ok: not an error a codec returns
            if (r.has_value() || r.error() != e || r.code() != e.code) return false;
            r = bytes<N>::zeros(N);  // full: size N is a value, never the error mark
            if (!r.has_value() || r->size() != N || r.code() != errc::ok) return false;
            r = e;
            if (r || r.error() != e) return false;
            if (r.value_or(bytes<N>{7}) != bytes<N>{7}) return false;
        }
    return true;
}
}  // namespace

TEST_CASE("result<bytes<N>> keeps its error inside the bytes", "[core][bytes]") {
    // the size takes the smallest type that also holds one value more than N
    STATIC_REQUIRE(sizeof(bytes<9>) == 10);
    STATIC_REQUIRE(sizeof(bytes<254>) == 255);
    STATIC_REQUIRE(sizeof(bytes<302>) == 304);
    STATIC_REQUIRE(sizeof(result<bytes<302>>) == 304);  // no flag beside the bytes (else 308)
    STATIC_REQUIRE(errors_round_trip<3>());  // too small for an error: a flag beside it
    STATIC_REQUIRE(errors_round_trip<4>());
    STATIC_REQUIRE(errors_round_trip<254>());
    STATIC_REQUIRE(errors_round_trip<255>());
    STATIC_REQUIRE(errors_round_trip<300>());
    CHECK(errors_round_trip<4>());  // the run-time paths (no whole-object copies)
    CHECK(errors_round_trip<254>());
    CHECK(errors_round_trip<255>());
    CHECK(errors_round_trip<300>());
}

TEST_CASE("hex formatting into a caller's buffer", "[core][bytes]") {
    STATIC_REQUIRE(hex_is(abc, "01 5C FF"));
    STATIC_REQUIRE(hex_is(abc, "015CFF", '\0'));
    STATIC_REQUIRE(hex_is(abc, "01:5C:FF", ':'));
    STATIC_REQUIRE(hex_is({}, ""));
    STATIC_REQUIRE(hex_size(3) == 8);
    // At run time to_hex reads a table of digit pairs: the same texts, and
    // every byte value's two digits (high nibble, then low).
    CHECK(hex_is(abc, "01 5C FF"));
    CHECK(hex_is(abc, "015CFF", '\0'));
    CHECK(hex_is(abc, "01:5C:FF", ':'));
    constexpr std::string_view digits = "0123456789ABCDEF";
    for (unsigned v = 0; v < 256; ++v) {
        const std::array<std::uint8_t, 2> two{static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(255 - v)};
        const std::array<char, 5> want{digits[v >> 4], digits[v & 15], '-', digits[(255 - v) >> 4],
                                       digits[(255 - v) & 15]};
        CHECK(hex_is(two, std::string_view(want.data(), want.size()), '-'));
    }
    // With the space: eight bytes a step, then the rest; every length up to 20 and
    // every byte value, nothing written past the text.
    for (std::size_t n = 0; n <= 20; ++n) {
        for (unsigned start = 0; start < 256; start += 7) {
            std::array<std::uint8_t, 20> in{};
            std::string want;
            for (std::size_t i = 0; i < n; ++i) {
                in[i] = static_cast<std::uint8_t>(start + 13 * i);
                if (i != 0) want += ' ';
                want += digits[in[i] >> 4];
                want += digits[in[i] & 15];
            }
            std::array<char, 64> buf{};
            buf.fill('#');
            const auto w = to_hex(std::span(in).first(n), std::span(buf).first(want.size()));
            INFO("n " << n << " start " << start);
            REQUIRE(w.has_value());
            CHECK(std::string_view(buf.data(), *w) == want);
            CHECK(buf[want.size()] == '#');
        }
    }
    std::array<char, 7> small{};
    const auto r = to_hex(abc, small);
    REQUIRE_FALSE(r);
    CHECK(r.error() == error{errc::buffer_too_small, 8});
}

TEST_CASE("hex parsing accepts common spellings", "[core][bytes]") {
    STATIC_REQUIRE(parse_hex<8>("01 5C FF").value() == std::span<const std::uint8_t>(abc));
    STATIC_REQUIRE(parse_hex<8>("015cff").value() == std::span<const std::uint8_t>(abc));
    STATIC_REQUIRE(parse_hex<8>("0x01,0x5C,0xFF").value() == std::span<const std::uint8_t>(abc));
    STATIC_REQUIRE(parse_hex<8>("01-5C-FF").value() == std::span<const std::uint8_t>(abc));
    STATIC_REQUIRE(parse_hex<8>("").value().empty());
    CHECK(parse_hex<8>("01 5G").error() == error{errc::bad_length, 3});
    CHECK(parse_hex<8>("01 Z5").error() == error{errc::value_out_of_range, 3});
    CHECK(parse_hex<8>("015").error() == error{errc::bad_length, 2});
    CHECK(parse_hex<2>("01 02 03").error() == error{errc::capacity_exceeded, 6});
}
