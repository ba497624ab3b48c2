#include <robowire/ext/fuzz.hpp>
#include <robowire/buwizz3.hpp>
#include <robowire/navbot.hpp>
#include <robowire/osp.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <set>
#include <string>

#include "check.hpp"
#include "each_message.hpp"

using namespace robowire;
namespace fz = robowire::fuzz;
namespace bw = robowire::buwizz3;
namespace nb = robowire::navbot;

namespace {
// Bytes that look random (xorshift32), the same on every run.
struct noise {
    std::uint32_t x = 0x12345678u;
    std::uint8_t next() {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        return static_cast<std::uint8_t>(x >> 24);
    }
    std::array<std::uint8_t, 512> block() {
        std::array<std::uint8_t, 512> b{};
        for (auto& v : b) v = next();
        return b;
    }
};

// Runs fn(type_identity<M>{}, name) for every message of the four protocol variants.
template <class Fn>
void each_protocol_message(Fn&& fn) {
    const auto in = [&]<class Variant>(std::type_identity<Variant>) {
        robowire::for_each_alternative<Variant>([&](auto t) { fn(t, table_v<typename decltype(t)::type>.name); });
    };
    in(std::type_identity<bw::command>{});
    in(std::type_identity<bw::notification>{});
    in(std::type_identity<nb::message>{});
    in(std::type_identity<osp::message>{});
}
}  // namespace

TEST_CASE("fuzz::source: bytes in order, then zeros", "[fuzz]") {
    const std::uint8_t data[] = {0x01, 0x02, 0x03};
    fz::source s{data, sizeof data};
    CHECK(s.remaining() == 3);
    CHECK(s.integral<std::uint16_t>() == 0x0201);  // first byte least significant
    CHECK(s.byte() == 0x03);
    CHECK(s.empty());
    for (int i = 0; i < 100; ++i) CHECK(s.byte() == 0);  // past the end
    CHECK(s.integral<std::int32_t>() == 0);
    CHECK(s.integral_in_range<int>(-5, 5) == -5);  // zeros: the low end
    CHECK(s.rest().empty());
    fz::source none{nullptr, 10};  // no data: empty whatever the size says
    CHECK(none.empty());
    CHECK(none.byte() == 0);
    STATIC_REQUIRE([] {
        const std::uint8_t d[] = {0xFF, 0x07};
        fz::source c{d, 2};
        return c.integral<std::int8_t>() == -1 && c.byte() == 7 && c.byte() == 0;
    }());
}

TEST_CASE("fuzz::source::integral_in_range: bytes as needed, modulo the count", "[fuzz]") {
    const std::uint8_t data[] = {0xFF, 0x10, 0x00, 0x03, 0xFF, 0xFF};
    fz::source s{data, sizeof data};
    CHECK(s.integral_in_range<int>(-100, 100) == -100 + 255 % 201);  // one byte for 201 values
    CHECK(s.integral_in_range<unsigned>(0, 1000) == 0x0010u);        // two bytes (0x0010) for 1001 values
    CHECK(s.integral_in_range<unsigned>(7, 7) == 7u);                // one value: no byte read
    CHECK(s.byte() == 0x03);
    CHECK(s.integral_in_range<std::uint16_t>(0, 0xFFFF) == 0xFFFF);
    CHECK(s.empty());
}

TEST_CASE("fuzz::make from an empty input: every field at its range's low end", "[fuzz]") {
    // Ranges from the protocol documents (specs/navbot-es02-ble-protocol.txt,
    // buwizz3-api-v3.22.txt), as the tables give them.
    STATIC_REQUIRE([] {
        fz::source s;
        const auto m = fz::make<nb::maneuver>(s);
        return m.roll == -100 && m.height == 0 && m.pitch == -100 && m.yaw == -100 && m.ball_x == -5 &&
               m.ball_y == -5 && m.switch_a == nb::switch_a::stop && m.switch_d == nb::switch_d::standard;
    }());
    STATIC_REQUIRE([] {
        fz::source s;
        const auto m = fz::make<bw::set_motion_wakeup>(s);
        return !m.enabled && m.idle_timeout_s == 10 && m.shallow_sleep_timeout_s == 0;  // idle timeout >= 10 s
    }());
    STATIC_REQUIRE([] {
        fz::source s;
        const auto m = fz::make<bw::set_pid_parameters>(s);
        return m.port == 0 && m.lim_out == 1 && m.deadband_out == 0 && m.kp == 0.0f;  // LimOut (0 - 127]
    }());
    STATIC_REQUIRE([] {
        fz::source s;
        const auto m = fz::make<bw::set_led_status>(s);
        return !m.colors && !m.blink;
    }());
    // No optional block: the 54-byte status.
    STATIC_REQUIRE([] {
        fz::source s;
        return robowire::encode(fz::make<bw::status>(s))->size() == 54;
    }());
    // The first alternative, with its first enum code.
    STATIC_REQUIRE([] {
        fz::source s;
        return std::holds_alternative<osp::generic::request_device_type>(fz::make<osp::message>(s));
    }());
    STATIC_REQUIRE([] {
        const std::uint8_t pick_device_type[] = {1, 0};
        fz::source s{pick_device_type, 2};
        const auto v = fz::make<osp::message>(s);
        return std::get<osp::generic::device_type>(v).type == osp::device_type::invalid;
    }());
}

TEST_CASE("fuzz::make: the bytes pick the values", "[fuzz]") {
    // maneuver: roll, height, pitch, yaw (one byte each), switches a-d (a byte
    // picks an entry of the enum's table), ball_x, ball_y.
    const std::uint8_t in[] = {200, 101, 0, 201, 2, 5, 1, 4, 10, 11};
    fz::source s{in, sizeof in};
    const auto m = fz::make<nb::maneuver>(s);
    CHECK(m.roll == 100);    // -100 + 200
    CHECK(m.height == 0);    // 101 % 101
    CHECK(m.pitch == -100);
    CHECK(m.yaw == -100);    // 201 % 201
    CHECK(m.switch_a == nb::switch_a::start_touch_panel);
    CHECK(m.switch_b == nb::switch_b::mark);  // 5 % 2
    CHECK(m.switch_c == nb::switch_c::lock);
    CHECK(m.switch_d == nb::switch_d::pitch_adjust);  // 4 % 3
    CHECK(m.ball_x == 5);   // -5 + 10 % 11
    CHECK(m.ball_y == -5);  // 11 % 11
    CHECK(s.empty());
    // text: a length 0..12, then characters 1..255 (a byte b gives 1 + b % 255).
    const std::uint8_t name[] = {3, 'A' - 1, 'B' - 1, 0};
    fz::source t{name, sizeof name};
    CHECK(fz::make<bw::set_device_name>(t).name == "AB\x01");
}

TEST_CASE("fuzz::make: every message of every protocol encodes, and decodes back", "[fuzz]") {
    each_protocol_message([](auto type, std::string_view name) {
        using M = typename decltype(type)::type;
        INFO(name);
        noise n;
        std::set<std::size_t> sizes;
        std::set<std::uint64_t> distinct;  // FNV-1a of each encoding
        for (int i = 0; i < 2000; ++i) {
            const auto in = n.block();
            fz::source s{in.data(), in.size()};
            const M m = fz::make<M>(s);
            const auto wire = robowire::encode(m);
            REQUIRE(wire);
            const auto back = robowire::decode<M>(wire->span());
            REQUIRE(back);
            CHECK(test::same(robowire::encode(*back)->span(), wire->span()));
            sizes.insert(wire->size());
            std::uint64_t h = 0xcbf29ce484222325u;
            for (const auto b : *wire) h = (h ^ b) * 0x100000001b3u;
            distinct.insert(h);
        }
        CHECK(sizes.count(min_size_v<M>) == 1);  // optional blocks absent, shortest text and tail
        CHECK(sizes.count(max_size_v<M>) == 1);  // every optional block, longest text and tail
        // Messages with fields take more than one value (those without: one frame).
        CHECK((distinct.size() > 1) == (table_v<M>.field_count > 0));
    });
}

TEST_CASE("fuzz::make of a variant: every alternative, as the protocol's decoder sees it", "[fuzz]") {
    noise n;
    std::set<std::size_t> seen;
    for (int i = 0; i < 2000; ++i) {
        const auto in = n.block();
        fz::source s{in.data(), in.size()};
        const auto m = fz::make<osp::message>(s);
        seen.insert(m.index());
        const auto wire = robowire::encode(m);
        REQUIRE(wire);
        const auto back = osp::decode(wire->span());
        REQUIRE(back);
        CHECK(back->index() == m.index());
    }
    CHECK(seen.size() == std::variant_size_v<osp::message>);
}

TEST_CASE("fuzz::make with out_of_range: rejected now and then, with the field's error", "[fuzz]") {
    std::set<std::string_view> rejected;
    each_protocol_message([&](auto type, std::string_view name) {
        using M = typename decltype(type)::type;
        INFO(name);
        noise n;
        int bad = 0;
        for (int i = 0; i < 1000; ++i) {
            const auto in = n.block();
            fz::source s{in.data(), in.size()};
            const auto wire = robowire::encode(fz::make<M>(s, fz::out_of_range{}));
            if (wire) continue;
            ++bad;
            const auto e = wire.error();
            CHECK((e.code == errc::value_out_of_range || e.code == errc::invalid_enum || e.code == errc::missing_field));
            if (e.code != errc::missing_field) CHECK(field_at<M>(e));  // the offset names a field
        }
        if (bad > 0) rejected.insert(name);
        if (name == "maneuver") {
            // 10 fields with a narrower range than their byte, each out of range with p = 1/32:
            // 1 - (31/32)^10 = 27 % of the messages.
            CHECK(bad > 180);
            CHECK(bad < 360);
        }
    });
    // Messages whose documents give a field a narrower range than its wire type,
    // an enumeration, text, or an optional block that needs another.
    for (const auto name : {"maneuver", "set_device_name", "set_motion_wakeup", "set_motor_data", "set_motor_data_extended",
                            "set_data_period", "set_motor_timeout", "set_led_status", "set_accel_lpf",
                            "set_pu_port_function", "enable_pid_reporting", "set_pid_parameters", "device_type", "status"}) {
        INFO(name);
        CHECK(rejected.count(name) == 1);
    }
    // Every field of the frame, the BuWizz3 notifications and the OSP requests takes any value.
    for (const auto name : {"frame", "accel_calibration", "charger_settings", "request_soc", "soc", "voltage"}) {
        INFO(name);
        CHECK(rejected.count(name) == 0);
    }
}

namespace {
// mutate() applied to valid encodings: how many results decode, and none equals its input.
template <class Variant, class Decode>
int mutated_decoding(Decode&& decode, int rounds) {
    noise n;
    int decoded = 0;
    for (int i = 0; i < rounds; ++i) {
        const auto in = n.block();
        fz::source s{in.data(), in.size()};
        const auto wire = robowire::encode(fz::make<Variant>(s));
        REQUIRE(wire);
        std::array<std::uint8_t, 256> buf{};
        for (std::size_t k = 0; k < wire->size(); ++k) buf[k] = (*wire)[k];
        const std::size_t size = fz::mutate<Variant>(buf.data(), wire->size(), buf.size(), static_cast<unsigned>(i));
        REQUIRE(size <= buf.size());
        CHECK_FALSE((size == wire->size() && test::same({buf.data(), size}, wire->span())));
        if (decode(std::span<const std::uint8_t>(buf.data(), size))) ++decoded;
    }
    return decoded;
}
}  // namespace

TEST_CASE("fuzz::mutate: one change, most results still decode", "[fuzz]") {
    const int rounds = 1000;
    const int bw_commands = mutated_decoding<bw::command>([](auto in) { return bw::decode_command(in).has_value(); }, rounds);
    const int bw_notifications =
        mutated_decoding<bw::notification>([](auto in) { return bw::decode_notification(in).has_value(); }, rounds);
    const int navbot = mutated_decoding<nb::message>([](auto in) { return nb::decode_frame(in).has_value(); }, rounds);
    const int osp_frames = mutated_decoding<osp::message>([](auto in) { return osp::decode(in).has_value(); }, rounds);
    // Most mutations keep the frame valid; some put a field just out of range (near-valid input).
    for (const int decoded : {bw_commands, navbot, osp_frames}) {
        CHECK(decoded > rounds / 2);
        CHECK(decoded < rounds);
    }
    // Every field of the notifications takes any value of its bytes (flags,
    // raw readings, floats, a tail): every change decodes.
    CHECK(bw_notifications == rounds);
}

TEST_CASE("fuzz::mutate: input that does not decode is repaired or mutated byte by byte", "[fuzz]") {
    // OSP frames are FF AA DEV CMD P1..P4 55 77 (specs/osp-open-serial-peripheral-v0.1.0.txt).
    std::array<std::uint8_t, 64> buf{};
    const auto bad_marker = test::hex("FF AA 02 14 03 05 00 00 55 00");
    for (std::size_t k = 0; k < bad_marker.size(); ++k) buf[k] = bad_marker[k];
    int repaired = 0;
    for (unsigned seed = 0; seed < 64; ++seed) {
        auto b = buf;
        const std::size_t n = fz::mutate<osp::message>(b.data(), bad_marker.size(), b.size(), seed);
        const auto r = osp::decode({b.data(), n});
        if (r && std::holds_alternative<osp::obp1::status>(*r)) {
            ++repaired;
            CHECK(std::get<osp::obp1::status>(*r) == osp::obp1::status{osp::obp1::state::charging, 5});
        }
    }
    CHECK(repaired > 32);  // the best-matching alternative is repaired, but 1 time in 8
    // Too short: made as long as the message (BuWizz3 status: 54 bytes).
    {
        std::array<std::uint8_t, 200> b{};
        b[0] = 0x01;
        for (unsigned seed = 0; seed < 8; ++seed) {
            auto c = b;
            const std::size_t n = fz::mutate<bw::notification>(c.data(), 10, c.size(), seed);
            if (c[0] == 0x01) CHECK((n == 54 || n == 68));
        }
    }
    // Nothing to repair (a field out of range): a byte-level change; with
    // a fallback, the fallback's.
    const auto out_of_range = test::hex("55 AA 10 00 00 00 00 65 00 00 00 00 00 00 00 00 00 00 00 00");  // pitch 101
    REQUIRE_FALSE(nb::decode_frame(out_of_range.span()));
    std::array<std::uint8_t, 20> b{};
    for (std::size_t k = 0; k < b.size(); ++k) b[k] = out_of_range[k];
    static int calls = 0;
    const fz::byte_mutator count = [](std::uint8_t*, std::size_t size, std::size_t) { ++calls; return size; };
    for (unsigned seed = 0; seed < 16; ++seed) {
        auto c = b;
        const std::size_t n = fz::mutate<std::variant<nb::maneuver>>(c.data(), c.size(), c.size(), seed, count);
        CHECK(n == 20);
    }
    CHECK(calls > 0);
    // Without a fallback, the bytes always change.
    for (unsigned seed = 0; seed < 64; ++seed) {
        auto c = b;
        const std::size_t n = fz::mutate<std::variant<nb::maneuver>>(c.data(), c.size(), c.size(), seed);
        CHECK_FALSE((n == b.size() && c == b));
    }
}

TEST_CASE("fuzz::mutate: the result fits max_size", "[fuzz]") {
    // A 68-byte status with room for 60 bytes: never longer than 60.
    noise n;
    for (unsigned seed = 0; seed < 200; ++seed) {
        const auto in = n.block();
        fz::source s{in.data(), in.size()};
        auto m = fz::make<bw::status>(s);
        m.pid_state.emplace();
        const auto wire = robowire::encode(m);
        std::array<std::uint8_t, 68> b{};
        for (std::size_t k = 0; k < b.size(); ++k) b[k] = (*wire)[k];
        const std::size_t size = fz::mutate<bw::notification>(b.data(), 54, 60, seed);
        CHECK(size <= 60);
    }
}
