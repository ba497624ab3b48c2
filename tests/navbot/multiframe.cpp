#include <robowire/navbot/maneuver.hpp>
#include <robowire/navbot/multiframe.hpp>

#include <catch2/catch.hpp>
#include <array>
#include <string>
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
// A frame's 20 bytes: 55 AA command remaining 00, then 15 times `fill`.
constexpr std::array<std::uint8_t, 20> frame_bytes(std::uint8_t cmd, std::uint8_t remaining, std::uint8_t fill) {
    std::array<std::uint8_t, 20> w{0x55, 0xAA, cmd, remaining, 0};
    for (std::size_t i = 5; i < 20; ++i) w[i] = fill;
    return w;
}
// A late repeat of a message's last frame, after a one-frame message, is a
// repeat; a frame that differs from the last one only in its payload is not.
constexpr bool late_repeat_found() {
    reassembler<45> r;
    bool ok = r.push(frame_bytes(2, 1, 'a')).value() == reassembly::need_more;
    ok = ok && r.push(frame_bytes(2, 0, 'b')).value() == reassembly::complete;
    ok = ok && r.push(frame_bytes(0x10, 0, 'm')).value() == reassembly::complete;
    ok = ok && r.push(frame_bytes(2, 0, 'b')).value() == reassembly::duplicate;
    ok = ok && r.push(frame_bytes(2, 0, 'c')).value() == reassembly::complete;
    return ok && r.payload().size() == 15 && r.payload()[0] == 'c';
}
// Frame k of the text's frames, reached by iterating (k++ then ++k).
constexpr bytes<frame_size> iterated_frame(std::string_view text, std::size_t k) {
    const auto f = json_frames(text).value();
    auto it = f.begin();
    for (std::size_t i = 0; i < k; ++i) (i % 2 == 0) ? void(it++) : void(++it);
    return *it;
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
    // the same frames by iteration, here and in a constant expression
    std::vector<bytes<frame_size>> seen(frames.begin(), frames.end());
    REQUIRE(seen.size() == 2);
    CHECK(seen[0] == test::hex("55 AA 02 01 00 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E 0F"));
    CHECK(seen[1] == test::hex("55 AA 02 00 00 10 00 00 00 00 00 00 00 00 00 00 00 00 00 00"));
    CHECK(std::next(empty.begin()) == empty.end());
    CHECK(std::next(frames.begin(), 2) == frames.end());
    CHECK(frames.begin() != std::next(frames.begin()));
    CHECK(decltype(frames.begin()){} == frames.end());
    CHECK(*empty.begin() == test::hex("55 AA 01 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00"));
    // 31 characters: 15 + 15 + 1
    constexpr std::string_view text31 = R"({"type":"get_device_info","x":})";
    STATIC_REQUIRE(text31.size() == 31);
    STATIC_REQUIRE(iterated_frame(text31, 1) ==
                   test::hex("55 AA 02 01 00 76 69 63 65 5F 69 6E 66 6F 22 2C 22 78 22 3A"));
    STATIC_REQUIRE(iterated_frame(text31, 2) ==
                   test::hex("55 AA 02 00 00 7D 00 00 00 00 00 00 00 00 00 00 00 00 00 00"));
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
            CHECK(f == frames[i]);                  // iteration and indexing agree
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
    reassembler<45> r;  // three frames
    SECTION("another multi-frame message mid-message") {
        CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(1, 1, 'b')).error() == error{errc::command_changed, 2});
        CHECK(r.in_progress());  // the frame of command 1 starts a new message
        CHECK(r.command() == 1);
        CHECK(r.push(make_frame(2, 1, 'a')).value() == reassembly::discarded);  // rest of the broken message
        CHECK(r.push(make_frame(2, 0, 'a')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(1, 0, 'c')).value() == reassembly::complete);
        CHECK(r.command() == 1);
        REQUIRE(r.payload().size() == 30);
        CHECK((r.payload()[0] == 'b' && r.payload()[15] == 'c'));
        CHECK(r.push(make_frame(2, 0, 'd')).value() == reassembly::complete);  // the broken one is over
        CHECK(r.payload()[0] == 'd');
    }
    SECTION("skipped frame at the end: the message is over") {
        CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 0, 'c')).error() == error{errc::bad_sequence, 3});  // remaining 1 was lost
        CHECK_FALSE(r.in_progress());
        CHECK(r.push(make_frame(2, 1, 'x')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 0, 'y')).value() == reassembly::complete);
        CHECK(r.payload().size() == 30);
        CHECK(r.payload()[15] == 'y');
    }
    SECTION("overflow: known from the first frame's remaining") {
        CHECK(r.push(make_frame(2, 3, 'a')).error() == error{errc::capacity_exceeded, 3});  // 4 frames > 45 bytes
        CHECK(r.push(make_frame(0x10, 0, 'm')).value() == reassembly::complete);  // other traffic goes on
        CHECK(r.push(make_frame(2, 2, 'b')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(2, 1, 'c')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(2, 0, 'd')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(2, 0, 'e')).value() == reassembly::complete);
        CHECK(r.payload().size() == 15);
        CHECK(r.payload()[0] == 'e');
    }
    SECTION("frame after error: not a frame, then the message goes on") {
        CHECK(r.push(make_frame(2, 1, 'a')).value() == reassembly::need_more);
        const auto bad = test::hex("55 AB 02 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00");
        CHECK(r.push(bad).error() == error{errc::bad_header, 1});
        const std::array<std::uint8_t, 20> zeroed{};  // a driver's buffer never written
        CHECK(r.push(zeroed).error() == error{errc::bad_header, 0});
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
    SECTION("clear forgets the message being discarded") {
        CHECK(r.push(make_frame(2, 5, 'a')).error() == error{errc::capacity_exceeded, 3});
        r.clear();
        CHECK(r.push(make_frame(2, 1, 'b')).value() == reassembly::need_more);
    }
}

TEST_CASE("navbot: single frames of another command inside a message", "[navbot][multiframe]") {
    reassembler<45> r;
    CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::need_more);
    CHECK(r.push(make_frame(0x10, 0, 'm')).value() == reassembly::single);
    CHECK(r.in_progress());
    CHECK(r.push(make_frame(2, 1, 'b')).value() == reassembly::need_more);
    CHECK(r.push(make_frame(0x10, 0, 'm')).value() == reassembly::single);
    CHECK(r.push(make_frame(0x11, 0, 'n')).value() == reassembly::single);
    CHECK(r.push(make_frame(2, 0, 'c')).value() == reassembly::complete);
    CHECK(r.command() == 2);
    REQUIRE(r.payload().size() == 45);
    CHECK((r.payload()[0] == 'a' && r.payload()[15] == 'b' && r.payload()[30] == 'c'));
    // with nothing in progress a one-frame message is simply complete
    CHECK(r.push(make_frame(0x10, 0, 'm')).value() == reassembly::complete);
    CHECK(r.command() == 0x10);
}

TEST_CASE("navbot: a 300-byte JSON reply while maneuver frames keep coming", "[navbot][multiframe]") {
    // {"pad":"xxx...x"} with 289 x: 8 + 289 + 2 = 299 characters, + a final space = 300 (20 frames).
    const std::string text = R"({"pad":")" + std::string(289, 'x') + R"("} )";
    REQUIRE(text.size() == 300);
    const auto frames = json_frames(text).value();
    REQUIRE(frames.size() == 20);
    maneuver m{};
    m.switch_a = switch_a::start;
    m.pitch = 10;
    const auto drive = robowire::encode(m).value();
    reassembler<300> r;
    std::size_t i = 0;
    for (const auto& f : frames) {
        ++i;
        const auto st = r.push(f);
        REQUIRE(st);
        CHECK(*st == (i == 20 ? reassembly::complete : reassembly::need_more));
        if (i < 20) CHECK(r.push(drive).value() == reassembly::single);
    }
    CHECK(r.command() == command::json);
    CHECK(r.text() == text);
    CHECK(r.json().value() == text);
}

TEST_CASE("navbot: repeated frames", "[navbot][multiframe]") {
    reassembler<45> r;
    CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::need_more);
    CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::duplicate);
    CHECK(r.push(make_frame(2, 1, 'b')).value() == reassembly::need_more);
    CHECK(r.push(make_frame(2, 1, 'b')).value() == reassembly::duplicate);
    CHECK(r.push(make_frame(2, 0, 'c')).value() == reassembly::complete);
    CHECK(r.push(make_frame(2, 0, 'c')).value() == reassembly::duplicate);  // not a one-frame tail
    REQUIRE(r.payload().size() == 45);  // the completed message is still there
    CHECK(r.payload()[30] == 'c');
    // a one-frame message sent twice is two messages (the app repeats maneuvers)
    CHECK(r.push(make_frame(0x10, 0, 'd')).value() == reassembly::complete);
    CHECK(r.push(make_frame(0x10, 0, 'd')).value() == reassembly::complete);
    CHECK(r.payload().size() == 15);
    // a late repeat of the multi-frame message's last frame is still a repeat, not a one-frame message
    CHECK(r.push(make_frame(2, 0, 'c')).value() == reassembly::duplicate);
    CHECK(r.command() == 0x10);
}

TEST_CASE("navbot: repeated frames, pushed as bytes", "[navbot][multiframe]") {
    reassembler<45> r;
    CHECK(r.push(frame_bytes(2, 2, 'a')).value() == reassembly::need_more);
    CHECK(r.push(frame_bytes(2, 1, 'b')).value() == reassembly::need_more);
    CHECK(r.push(frame_bytes(2, 1, 'b')).value() == reassembly::duplicate);
    CHECK(r.push(frame_bytes(2, 2, 'a')).value() == reassembly::restarted);  // not the last frame: a new start
    CHECK(r.push(frame_bytes(2, 1, 'b')).value() == reassembly::need_more);
    CHECK(r.push(frame_bytes(2, 0, 'c')).value() == reassembly::complete);
    CHECK(r.push(frame_bytes(2, 0, 'c')).value() == reassembly::duplicate);
    REQUIRE(r.payload().size() == 45);
    CHECK((r.payload()[0] == 'a' && r.payload()[15] == 'b' && r.payload()[30] == 'c'));
    CHECK(r.push(frame_bytes(0x10, 0, 'd')).value() == reassembly::complete);
    CHECK(r.push(frame_bytes(2, 0, 'c')).value() == reassembly::duplicate);  // late repeat
    CHECK(r.push(frame_bytes(2, 1, 'c')).value() == reassembly::need_more);  // same payload, other remaining
    CHECK(r.push(frame_bytes(2, 0, 'c')).value() == reassembly::complete);
    REQUIRE(r.payload().size() == 30);
    STATIC_REQUIRE(late_repeat_found());
}

TEST_CASE("navbot: a discarded frame inside a message, pushed as bytes", "[navbot][multiframe]") {
    reassembler<45> r;
    CHECK(r.push(frame_bytes(2, 5, 'a')).error() == error{errc::capacity_exceeded, 3});  // 6 frames > 45 bytes
    CHECK(r.push(frame_bytes(3, 2, 'x')).value() == reassembly::need_more);
    CHECK(r.push(frame_bytes(2, 4, 'a')).value() == reassembly::discarded);  // the broken message goes on
    CHECK(r.push(frame_bytes(2, 4, 'a')).value() == reassembly::duplicate);
    CHECK(r.push(frame_bytes(3, 1, 'y')).value() == reassembly::need_more);
    CHECK(r.push(frame_bytes(3, 1, 'y')).value() == reassembly::duplicate);
    CHECK(r.push(frame_bytes(3, 0, 'z')).value() == reassembly::complete);
    CHECK(r.command() == 3);
    REQUIRE(r.payload().size() == 45);
    CHECK((r.payload()[0] == 'x' && r.payload()[15] == 'y' && r.payload()[30] == 'z'));
    CHECK(r.push(frame_bytes(3, 0, 'z')).value() == reassembly::duplicate);
    CHECK(r.push(frame_bytes(2, 3, 'a')).value() == reassembly::discarded);
    r.clear();
    CHECK(r.push(frame_bytes(2, 3, 'a')).error() == error{errc::capacity_exceeded, 3});
}

TEST_CASE("navbot: the sender starts a message over", "[navbot][multiframe]") {
    reassembler<45> r;
    SECTION("higher remaining") {
        CHECK(r.push(make_frame(2, 2, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 1, 'b')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 2, 'x')).value() == reassembly::restarted);
        CHECK(r.push(make_frame(2, 1, 'y')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 0, 'z')).value() == reassembly::complete);
        REQUIRE(r.payload().size() == 45);
        CHECK((r.payload()[0] == 'x' && r.payload()[15] == 'y' && r.payload()[30] == 'z'));
    }
    SECTION("same remaining, other bytes") {
        CHECK(r.push(make_frame(2, 1, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 1, 'b')).value() == reassembly::restarted);
        CHECK(r.push(make_frame(2, 0, 'c')).value() == reassembly::complete);
        REQUIRE(r.payload().size() == 30);
        CHECK((r.payload()[0] == 'b' && r.payload()[15] == 'c'));
    }
    SECTION("restart too long for the capacity") {
        CHECK(r.push(make_frame(2, 1, 'a')).value() == reassembly::need_more);
        CHECK(r.push(make_frame(2, 4, 'b')).error() == error{errc::capacity_exceeded, 3});
        CHECK_FALSE(r.in_progress());
        CHECK(r.push(make_frame(2, 3, 'b')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(2, 0, 'b')).value() == reassembly::discarded);
        CHECK(r.push(make_frame(2, 0, 'e')).value() == reassembly::complete);
    }
}

TEST_CASE("navbot: lost frames inside a message", "[navbot][multiframe]") {
    reassembler<90> r;
    CHECK(r.push(make_frame(2, 5, 'a')).value() == reassembly::need_more);
    CHECK(r.push(make_frame(2, 3, 'c')).error() == error{errc::bad_sequence, 3});  // remaining 4 lost
    CHECK_FALSE(r.in_progress());
    CHECK(r.push(make_frame(0x10, 0, 'm')).value() == reassembly::complete);  // other traffic goes on
    CHECK(r.push(make_frame(2, 2, 'd')).value() == reassembly::discarded);
    CHECK(r.push(make_frame(2, 1, 'e')).value() == reassembly::discarded);
    CHECK(r.push(make_frame(2, 0, 'f')).value() == reassembly::discarded);  // end of the broken message
    CHECK(r.push(make_frame(2, 0, 'n')).value() == reassembly::complete);
    CHECK(r.payload().size() == 15);
    CHECK(r.payload()[0] == 'n');
}

TEST_CASE("navbot: listening from the middle of a message", "[navbot][multiframe]") {
    // {"type":"get_device_info"}: frame 0 carries {"type":"get_de, frame 1 vice_info"}
    const auto frames = json_frames(R"({"type":"get_device_info"})").value();
    REQUIRE(frames.size() == 2);
    reassembler<60> r;
    CHECK(r.push(frames[1]).value() == reassembly::complete);  // cannot be told from a one-frame message
    CHECK(r.text() == R"(vice_info"})");
    CHECK(r.json().error() == error{errc::bad_json, 0});
    CHECK(r.push(frames[0]).value() == reassembly::need_more);
    CHECK(r.json().error() == error{errc::too_short, 15});  // nothing complete
    CHECK(r.push(frames[1]).value() == reassembly::complete);
    CHECK(r.json().value() == R"({"type":"get_device_info"})");
}

TEST_CASE("navbot: json_object", "[navbot][multiframe]") {
    STATIC_REQUIRE(json_object(R"({"a":1})").value() == R"({"a":1})");
    STATIC_REQUIRE(json_object(" {\"a\":[1,{\"b\":\"}]\"}]} \r\n").has_value());  // braces inside a string
    STATIC_REQUIRE(json_object(R"({"a":"\"}"})").has_value());                    // escaped quote
    STATIC_REQUIRE(json_object(R"({"a":1)").error() == error{errc::bad_json, 6});    // ends inside
    STATIC_REQUIRE(json_object(R"({"a":"x})").error() == error{errc::bad_json, 8});  // string not closed
    STATIC_REQUIRE(json_object(R"("a":1})").error() == error{errc::bad_json, 0});    // not an object
    STATIC_REQUIRE(json_object(R"({"a":1}})").error() == error{errc::bad_json, 7});  // more after it
    STATIC_REQUIRE(json_object(R"({"a":1} {"b":2})").error() == error{errc::bad_json, 8});
    STATIC_REQUIRE(json_object(R"({"a":[1})").error() == error{errc::bad_json, 7});  // ] expected
    STATIC_REQUIRE(json_object("").error() == error{errc::bad_json, 0});
    STATIC_REQUIRE(json_object("{\"a\":\"\n\"}").error() == error{errc::bad_json, 6});  // raw newline in a string
    STATIC_REQUIRE(to_string(errc::bad_json) == "not one complete JSON object");
}
