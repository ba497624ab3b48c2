#include <robowire/osp/decode.hpp>
#include <robowire/osp/scanner.hpp>

#include <catch2/catch.hpp>
#include <string>

#include "check.hpp"
#include "round_trips.hpp"

using namespace robowire;
using namespace robowire::osp;

TEST_CASE("osp::decode dispatches on DEV and CMD", "[osp]") {
    STATIC_REQUIRE(std::get<obp1::status>(*osp::decode(test::hex("FF AA 02 14 03 05 00 00 55 77"))) ==
                   obp1::status{obp1::state::charging, 5});
    STATIC_REQUIRE(std::get<obp1::current>(*osp::decode(test::hex("FF AA 02 13 24 FA 00 00 55 77"))).milliamps == -1500);
    STATIC_REQUIRE(std::holds_alternative<generic::request_device_type>(
        *osp::decode(test::hex("FF AA 00 01 00 00 00 00 55 77"))));
    const auto a = osp::decode(test::hex("FF AA 01 02 03 34 12 00 55 77"));
    REQUIRE(a);
    CHECK(std::get<arm1::set_angle>(*a) == arm1::set_angle{3, 0x1234});
}

TEST_CASE("osp::decode: unknown messages still show DEV, CMD and parameters", "[osp]") {
    const auto r = osp::decode(test::hex("FF AA 03 01 0A 0B 0C 0D 55 77"));
    REQUIRE_FALSE(r);
    CHECK(r.error() == error{errc::unknown_message, 2});
    REQUIRE(r.frame());
    CHECK(r.frame()->device == 0x03);
    CHECK(r.frame()->command == 0x01);
    CHECK(r.frame()->params == std::array<std::uint8_t, 4>{0x0A, 0x0B, 0x0C, 0x0D});
    // a field error also keeps the frame; a marker error has none
    const auto bad_enum = osp::decode(test::hex("FF AA 02 14 09 00 00 00 55 77"));
    CHECK(bad_enum.error() == error{errc::invalid_enum, 4});
    CHECK(bad_enum.frame().has_value());
    const auto bad_end = osp::decode(test::hex("FF AA 02 14 01 00 00 00 55 00"));
    CHECK(bad_end.error() == error{errc::bad_trailer, 9});
    CHECK_FALSE(bad_end.frame().has_value());
}

TEST_CASE("osp: every message round trips through the variant", "[osp]") {
    STATIC_REQUIRE(std::variant_size_v<message> >= 11);
    test::check_each_round_trips<message>([](const message& m) { return osp::encode(m); },
                                          [](std::span<const std::uint8_t> in) { return osp::decode(in); });
    robowire::for_each_alternative<message>(
        [](auto t) { CHECK(osp::encode(typename decltype(t)::type{})->size() == frame_size); });
}

// Encoding a temporary variant at namespace scope, in a constant expression
// (g++ 12 cannot evaluate std::get_if on such a temporary there): voltage
// 16.50 V is FF AA 02 12 72 06 00 00 55 77.
static_assert(osp::encode(message{obp1::voltage{1650}})->span()[4] == 0x72);
static_assert(robowire::encode(message{obp1::voltage{1650}})->span()[5] == 0x06);
static_assert(osp::encode(message{obp1::request_soc{}})->span()[3] == 0x01);

namespace {
// A battery pack's firmware: answers what it knows, ignores set_angle, and
// takes requests it only sometimes answers.
struct battery {
    int requests = 0;
    bool have_status = false;
    obp1::soc operator()(const obp1::request_soc&) { ++requests; return {52428}; }  // 80 %
    obp1::voltage operator()(const obp1::request_voltage&) { ++requests; return {1650}; }
    generic::device_type operator()(const generic::request_device_type&) { return {device_type::obp1}; }
    std::optional<obp1::status> operator()(const obp1::request_status&) {
        if (!have_status) return std::nullopt;
        return obp1::status{obp1::state::discharging, 0};
    }
    void operator()(const obp1::request_current&) { ++requests; }
};
}  // namespace

TEST_CASE("osp::serve answers requests on a device", "[osp]") {
    battery b;
    auto r = serve(test::hex("FF AA 02 01 00 00 00 00 55 77"), b);
    REQUIRE(r);
    REQUIRE(r->has_value());
    CHECK(**r == test::hex("FF AA 02 11 CC CC 00 00 55 77"));  // 52428 = 0xCCCC
    r = serve(test::hex("FF AA 00 01 00 00 00 00 55 77"), b);
    CHECK(**r == test::hex("FF AA 00 11 02 00 00 00 55 77"));
    r = serve(test::hex("FF AA 02 04 00 00 00 00 55 77"), b);  // optional: nothing yet
    REQUIRE(r);
    CHECK_FALSE(r->has_value());
    b.have_status = true;
    r = serve(test::hex("FF AA 02 04 00 00 00 00 55 77"), b);
    CHECK(**r == test::hex("FF AA 02 14 02 00 00 00 55 77"));
    r = serve(test::hex("FF AA 02 03 00 00 00 00 55 77"), b);  // void: handled, no answer
    REQUIRE(r);
    CHECK_FALSE(r->has_value());
    CHECK(b.requests == 2);
    r = serve(test::hex("FF AA 01 02 00 00 00 00 55 77"), b);  // a valid set_angle: not handled
    CHECK(r.error() == error{errc::not_handled, 2});
    r = serve(test::hex("FF AA 03 01 00 00 00 00 55 77"), b);  // no message has DEV 3 CMD 1
    CHECK(r.error() == error{errc::unknown_message, 2});
    r = serve(test::hex("FF AA 02 01 00 00 00 00 55"), b);
    CHECK(r.error() == error{errc::too_short, 9});
}

namespace {
// A board's transmit buffer: 16 bytes, filled with 0xEE to see what is written.
struct tx_buffer {
    std::array<std::uint8_t, 16> bytes{};
    constexpr tx_buffer() { bytes.fill(0xEE); }
    constexpr bool untouched() const {
        for (auto x : bytes)
            if (x != 0xEE) return false;
        return true;
    }
    constexpr std::span<const std::uint8_t> first(std::size_t n) const { return std::span(bytes).first(n); }
};
// Answers request_status with an invalid state (9): its answer cannot be encoded.
struct bad_status {
    obp1::status operator()(const obp1::request_status&) const { return {static_cast<obp1::state>(9), 0}; }
};
constexpr auto served_voltage = [] {
    tx_buffer tx;
    const auto n = serve_to([](const obp1::request_voltage&) { return obp1::voltage{1260}; },
                            test::hex("FF AA 02 02 00 00 00 00 55 77"), tx.bytes);
    return std::pair{n.value(), tx.bytes};
}();
}  // namespace

TEST_CASE("osp::serve_to writes the answer into the caller's buffer", "[osp]") {
    // 1260 = 0x04EC (12.60 V), little-endian in P1 P2; in a constant expression too
    STATIC_REQUIRE(served_voltage.first == 10);
    STATIC_REQUIRE(std::span(served_voltage.second).first(10) == test::hex("FF AA 02 12 EC 04 00 00 55 77"));
    STATIC_REQUIRE(served_voltage.second[10] == 0xEE);
    battery b;
    tx_buffer tx;
    auto n = serve_to(b, test::hex("FF AA 02 02 00 00 00 00 55 77"), tx.bytes);
    REQUIRE(n);
    CHECK(*n == 10);
    CHECK(tx.first(10) == test::hex("FF AA 02 12 72 06 00 00 55 77"));  // 1650 = 0x0672
    CHECK(tx.bytes[10] == 0xEE);                                          // nothing past the frame
    n = serve_to(b, test::hex("FF AA 02 01 00 00 00 00 55 77"), tx.bytes);
    CHECK(*n == 10);
    CHECK(tx.first(10) == test::hex("FF AA 02 11 CC CC 00 00 55 77"));  // 52428 = 0xCCCC
    n = serve_to(b, test::hex("FF AA 00 01 00 00 00 00 55 77"), std::span(tx.bytes).first(10));  // exactly 10
    CHECK(*n == 10);
    CHECK(tx.first(10) == test::hex("FF AA 00 11 02 00 00 00 55 77"));  // device type obp1 = 2
    CHECK(b.requests == 2);
}

TEST_CASE("osp::serve_to: nothing to send, not handled and errors leave the buffer as it was", "[osp]") {
    battery b;
    tx_buffer tx;
    auto n = serve_to(b, test::hex("FF AA 02 04 00 00 00 00 55 77"), tx.bytes);  // optional: no status yet
    CHECK(n.value() == 0);
    n = serve_to(b, test::hex("FF AA 02 03 00 00 00 00 55 77"), tx.bytes);  // void: handled, no answer
    CHECK(n.value() == 0);
    CHECK(b.requests == 1);
    CHECK(tx.untouched());
    // valid frames the battery takes no overload for: another device's command, and
    // another device's answer on a shared bus
    n = serve_to(b, test::hex("FF AA 01 02 00 00 00 00 55 77"), tx.bytes);
    CHECK(n.error() == error{errc::not_handled, 2});
    n = serve_to(b, test::hex("FF AA 02 12 72 06 00 00 55 77"), tx.bytes);
    CHECK(n.error() == error{errc::not_handled, 2});
    // not a message at all: unknown_message, distinct from not_handled
    n = serve_to(b, test::hex("FF AA 03 01 00 00 00 00 55 77"), tx.bytes);
    CHECK(n.error() == error{errc::unknown_message, 2});
    n = serve_to(b, test::hex("FF AA 02 01 00 00 00 00 55"), tx.bytes);
    CHECK(n.error() == error{errc::too_short, 9});
    n = serve_to(b, test::hex("FF AA 02 01 00 00 00 00 55 78"), tx.bytes);
    CHECK(n.error() == error{errc::bad_trailer, 9});
    // an answer that cannot be encoded: its field error, nothing written
    n = serve_to(bad_status{}, test::hex("FF AA 02 04 00 00 00 00 55 77"), tx.bytes);
    CHECK(n.error() == error{errc::invalid_enum, 4});
    CHECK(tx.untouched());
    // a buffer shorter than a frame: refused before the handler runs
    n = serve_to(b, test::hex("FF AA 02 02 00 00 00 00 55 77"), std::span(tx.bytes).first(9));
    CHECK(n.error() == error{errc::buffer_too_small, 10});
    CHECK(b.requests == 1);
    CHECK(tx.untouched());
}

TEST_CASE("osp::describe_error names the message that DEV and CMD name", "[osp]") {
    std::array<char, 96> buf{};
    const auto unknown = test::hex("FF AA 03 01 0A 0B 0C 0D 55 77");
    CHECK(describe_error(osp::decode(unknown), buf) == "unknown key 0x03 0x01 at byte 2");
    CHECK(describe_error(error{errc::unknown_message, 2}, unknown, buf) == "unknown key 0x03 0x01 at byte 2");
    // an unknown DEV/CMD pair and a broken trailer: both said, the error's offset last
    const auto unknown_cut = test::hex("FF AA 03 01 01 00 00 00 55 76");
    CHECK(osp::decode(unknown_cut).error() == error{errc::bad_trailer, 9});
    CHECK(describe_error(osp::decode(unknown_cut).error(), unknown_cut, buf) ==
          "unknown key 0x03 0x01: bad trailer byte at byte 9");
    CHECK(describe_error(osp::decode(test::hex("FF AA 02 14 09 00 00 00 55 77")), buf) ==
          "status.state: value is not a valid code at byte 4");
    // markers or length wrong: the decode result keeps no DEV/CMD, the input still has them
    const auto cut = test::hex("FF AA 02 12 72 06 00 00 55");
    CHECK(describe_error(osp::decode(cut), buf) == "frame: input too short (10 bytes) at byte 9");
    CHECK(describe_error(error{errc::too_short, 9}, cut, buf) == "voltage: input too short (10 bytes) at byte 9");
    CHECK(describe_error(osp::decode(test::hex("FF AA 02 14 01 00 00 00 55 00")), buf) ==
          "frame: bad trailer byte at byte 9");
    CHECK(describe_error(error{errc::too_short, 3}, test::hex("FF AA 02"), buf) ==
          "frame: input too short (10 bytes) at byte 3");
    // serve_to's not_handled, for a frame found by the scanner among noise
    battery b;
    tx_buffer tx;
    osp::scanner scanner;
    std::string line;
    scanner.feed(test::hex("00 FF 13 FF AA 01 02 03 34 12 00 55 77"), [&](osp::scanner::frame_bytes f) {
        const auto sent = serve_to(b, f, tx.bytes);
        REQUIRE(sent.error() == error{errc::not_handled, 2});
        line = describe_error(sent.error(), f, buf);
    });
    CHECK(line == "set_angle: message not handled at byte 2");
}
