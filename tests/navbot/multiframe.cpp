#include <robowire/navbot/multiframe.hpp>

#include <catch2/catch.hpp>
#include <vector>

#include "check.hpp"

using namespace robowire;
using namespace robowire::navbot;

namespace {
std::vector<std::uint8_t> counting(std::size_t n) {
    std::vector<std::uint8_t> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>(i + 1);
    return v;
}
frame make_frame(std::uint8_t cmd, std::uint8_t remaining, std::uint8_t fill) {
    frame f{cmd, remaining, {}};
    f.payload.fill(fill);
    return f;
}
constexpr std::size_t frames_of_json(std::string_view text) {
    const auto f = json_frames(text);
    return f ? f->size() : 0;
}
}  // namespace

TEST_CASE("navbot: fragmenter golden frames", "[navbot][multiframe]") {
    // 16 payload bytes 01..10 -> two frames: remaining 1 then 0, the last zero-padded.
    const auto payload = counting(16);
    const auto frames = make_frames(command::json, payload).value();
    REQUIRE(frames.size() == 2);
    CHECK(frames[0] == test::hex("55 AA 02 01 00 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E 0F"));
    CHECK(frames[1] == test::hex("55 AA 02 00 00 10 00 00 00 00 00 00 00 00 00 00 00 00 00 00"));
    // an empty payload is one zero frame
    const auto empty = make_frames(command::wifi, {}).value();
    REQUIRE(empty.size() == 1);
    CHECK(empty[0] == test::hex("55 AA 01 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE(frames_of_json(R"({"type":"get_device_info"})") == 2);  // 26 chars
    STATIC_REQUIRE(json_frames(R"({"a":1})").value()[0] ==
                   test::hex("55 AA 02 00 00 7B 22 61 22 3A 31 7D 00 00 00 00 00 00 00 00"));
    STATIC_REQUIRE((frames_for(0) == 1 && frames_for(15) == 1 && frames_for(16) == 2 && frames_for(3840) == 256));
    std::vector<std::uint8_t> too_big(max_payload + 1);
    CHECK(make_frames(command::wifi, too_big).error() == error{errc::capacity_exceeded, max_payload});
}

TEST_CASE("navbot: fragment then reassemble, many lengths", "[navbot][multiframe]") {
    for (std::size_t n : {0u, 1u, 14u, 15u, 16u, 30u, 31u, 200u, 3840u}) {
        INFO("payload " << n);
        const auto payload = counting(n);
        const auto frames = make_frames(0x02, payload).value();
        CHECK(frames.size() == frames_for(n));
        reassembler<max_payload> r;
        std::size_t i = 0;
        for (const auto& f : frames) {
            CHECK(f[3] == frames.size() - 1 - i);  // remaining counts down to 0
            const auto st = r.push(f);
            REQUIRE(st);
            CHECK(*st == (i + 1 == frames.size() ? reassembly::complete : reassembly::need_more));
            ++i;
        }
        CHECK(r.command() == 0x02);
        REQUIRE(r.payload().size() == frames.size() * 15);
        CHECK(test::same(r.payload().first(n), payload));
        for (std::size_t k = n; k < r.payload().size(); ++k) CHECK(r.payload()[k] == 0);
    }
}

TEST_CASE("navbot: JSON text round trip", "[navbot][multiframe]") {
    const std::string_view text = R"({"type":"get_device_info"})";
    const auto frames = json_frames(text).value();
    reassembler<60> r;
    result<reassembly> st = reassembly::need_more;
    for (const auto& f : frames) st = r.push(f);
    REQUIRE(st);
    CHECK(*st == reassembly::complete);
    CHECK(r.text() == text);
}

TEST_CASE("navbot: reassembler error paths", "[navbot][multiframe]") {
    reassembler<45> r;
    SECTION("wrong command mid-message") {
        CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(1, 1, 'b')).error() == error{errc::command_changed, 2});
        CHECK(r.push(make_frame(2, 0, 'c')).value() == reassembly::discarded);  // end of the broken message
        CHECK(r.push(make_frame(2, 0, 'd')).value() == reassembly::complete);   // a fresh one
        CHECK(r.payload()[0] == 'd');
    }
    SECTION("skipped frame") {
        CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 0, 'c')).error() == error{errc::bad_sequence, 3});  // remaining 1 was lost
        CHECK_FALSE(r.in_progress());
        CHECK(r.push(make_frame(2, 1, 'x')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 0, 'y')).value() == reassembly::complete);
        CHECK(r.payload().size() == 30);
        CHECK(r.payload()[15] == 'y');
    }
    SECTION("remaining goes up mid-message") {
        CHECK(r.push(make_frame(2, 1, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 2, 'b')).error() == error{errc::bad_sequence, 3});
        CHECK(r.push(make_frame(2, 1, 'b')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(2, 0, 'b')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(2, 0, 'z')).value() == reassembly::complete);
    }
    SECTION("overflow") {
        CHECK(r.push(make_frame(2, 3, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 2, 'b')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 1, 'c')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 0, 'd')).error() == error{errc::capacity_exceeded, 5});  // 60 > 45
        CHECK(r.push(make_frame(2, 0, 'e')).value() == reassembly::complete);
        CHECK(r.payload().size() == 15);
    }
    SECTION("frame after error: not a frame, then the message goes on") {
        CHECK(r.push(make_frame(2, 1, 'a')).value() == reassembly::need_more);
        const auto bad = test::hex("55 AB 02 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00");
        CHECK(r.push(bad).error() == error{errc::bad_header, 1});
        CHECK(r.push(test::hex("55 AA 02 00 00 62")).error() == error{errc::too_short, 6});
        CHECK(r.in_progress());
        CHECK(r.push(make_frame(2, 0, 'b')).value() == reassembly::complete);
        CHECK(r.payload()[15] == 'b');
    }
    SECTION("a completed message stays readable until the next push") {
        CHECK(r.push(make_frame(5, 0, 'q')).value() == reassembly::complete);
        CHECK(r.command() == 5);
        CHECK(r.payload()[14] == 'q');
        CHECK(r.push(make_frame(6, 1, 'r')).value() == reassembly::need_more);
        CHECK(r.command() == 6);
    }
}
