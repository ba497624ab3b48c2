// robowire demo: encodes and decodes real frames of each protocol and prints them.
#include <robowire/robowire.hpp>

#include <array>
#include <cstdio>
#include <span>
#include <string_view>

namespace {
int failures = 0;

void print_hex(std::string_view label, std::span<const std::uint8_t> b) {
    std::array<char, 3 * 256> text{};
    const auto n = robowire::to_hex(b, text);
    std::printf("  %-34s %.*s\n", label.data(), static_cast<int>(n.value_or(0)), text.data());
}

void expect(bool ok, std::string_view what) {
    if (!ok) {
        ++failures;
        std::printf("  FAILED: %.*s\n", static_cast<int>(what.size()), what.data());
    }
}

void buwizz3_demo() {
    namespace bw = robowire::buwizz3;
    std::puts("BuWizz3 (BLE power brick)");
    const auto drive = robowire::encode(bw::set_motor_data{{100, -100, 0, 0, 127, -127}, 0x03, 0}).value();
    print_hex("set_motor_data", drive);
    const auto cmd = bw::decode_command(drive);
    expect(cmd && std::holds_alternative<bw::set_motor_data>(*cmd), "buwizz3 decode_command");
    const auto pid = robowire::encode(bw::position_servo_preset(0)).value();
    print_hex("set_pid_parameters (preset)", pid);
    // A 54-byte status report as it arrives 20 times a second.
    std::array<std::uint8_t, 54> report{0x01, 0x73, 0x50, 0x0A, 0x14, 0x1E, 0x28, 0x32, 0xC8, 0x23, 0xF0, 0xFF, 0xF0, 0x7F};
    report[22] = 0x30;  // port 1: motor type 0x30, velocity -20, absolute -180, position -100000
    report[23] = 0xEC;
    report[24] = 0x4C;
    report[25] = 0xFF;
    report[26] = 0x60;
    report[27] = 0x79;
    report[28] = 0xFE;
    report[29] = 0xFF;
    const auto n = bw::decode_notification(report);
    expect(n && std::holds_alternative<bw::status>(*n), "buwizz3 status");
    if (n) {
        const auto& s = std::get<bw::status>(*n);
        std::printf("  status: battery %.2f V, port 6 %.3f A, accel x %.1f mg, port 1 at %d deg, charging %s\n",
                    bw::battery_volts(s), bw::motor_amps(s, 5), bw::accel_milli_g(s.accel_raw[0]),
                    static_cast<int>(s.pu_motors[0].position), s.charging() ? "yes" : "no");
        expect(s.pu_motors[0].position == -100000 && s.battery_voltage_raw == 80, "buwizz3 status fields");
    }
    // Out of range is an error, not a silently truncated value.
    const auto bad = robowire::encode(bw::set_data_period{10});
    std::printf("  set_data_period 10 ms: %s at byte %u\n", robowire::to_string(bad.code()).data(), static_cast<unsigned>(bad.error().offset));
    expect(bad.code() == robowire::errc::value_out_of_range, "buwizz3 range");
}

void navbot_demo() {
    namespace navbot = robowire::navbot;
    std::puts("NAVBOT-ES02 (BLE, 20-byte frames)");
    navbot::maneuver m{};
    m.switch_a = navbot::switch_a::start;
    m.pitch = -10;  // back slowly
    const auto wire = navbot::encode(m).value();
    print_hex("maneuver: start, pitch -10", wire);
    expect(wire[7] == 0xF6, "two's complement -10");
    const auto back = navbot::decode_maneuver(wire);
    expect(back && *back == m, "navbot round trip");
    // The document's sample writes -10 as 0x8A; the robot would read -118.
    const auto doc = navbot::encode(m, navbot::sign_encoding::sign_magnitude).value();
    print_hex("same, document's sign-magnitude", doc);
    const auto refused = navbot::decode_maneuver(doc);
    std::printf("  read the robot's way: %s at byte %u (0x8A = -118)\n", robowire::to_string(refused.code()).data(),
                static_cast<unsigned>(refused.error().offset));
    expect(refused.code() == robowire::errc::value_out_of_range, "sign-magnitude refused");
    // A JSON request split into frames and put back together.
    const auto frames = navbot::json_frames(R"({"type":"get_device_info"})").value();
    navbot::reassembler<60> r;
    for (const auto& f : frames) {
        print_hex("json frame", f);
        (void)r.push(f);
    }
    std::printf("  reassembled %zu frames: %.*s\n", frames.size(), static_cast<int>(r.text().size()), r.text().data());
    expect(r.text() == R"({"type":"get_device_info"})", "navbot json");
}

void osp_demo() {
    namespace osp = robowire::osp;
    std::puts("OSP (serial, 10-byte frames)");
    // Host asks a battery pack for its voltage ...
    const auto request = robowire::encode(osp::obp1::request_voltage{}).value();
    print_hex("request_voltage", request);
    // ... the pack answers 16.50 V; the answer arrives with noise in a serial stream.
    const auto answer = robowire::encode(osp::obp1::voltage{1650}).value();
    print_hex("voltage 16.50 V", answer);
    std::array<std::uint8_t, 16> stream{0x00, 0xFF, 0x13};
    for (std::size_t i = 0; i < answer.size(); ++i) stream[3 + i] = answer[i];
    osp::scanner scanner;
    scanner.feed(stream, [&](osp::scanner::frame_bytes f) {
        const auto m = osp::decode(f);
        expect(m.has_value(), "osp decode");
        if (const auto* v = m ? std::get_if<osp::obp1::voltage>(&*m) : nullptr)
            std::printf("  scanner found: voltage %.2f V\n", osp::obp1::volts(*v));
    });
    std::printf("  scanner: %llu frame, %llu noise bytes skipped\n",
                static_cast<unsigned long long>(scanner.frames()), static_cast<unsigned long long>(scanner.skipped()));
    expect(scanner.frames() == 1, "osp scanner");
    // A frame with a bad trailer is rejected with the offset of the bad byte.
    std::array<std::uint8_t, 10> bad{0xFF, 0xAA, 0x02, 0x12, 0x72, 0x06, 0x00, 0x00, 0x55, 0x00};
    const auto err = osp::decode(bad);
    std::printf("  bad frame: %s at byte %u\n", robowire::to_string(err.code()).data(), static_cast<unsigned>(err.error().offset));
    expect(err.error() == robowire::error{robowire::errc::bad_trailer, 9}, "osp bad trailer");
}
}  // namespace

int main() {
    buwizz3_demo();
    navbot_demo();
    osp_demo();
    if (failures) {
        std::printf("%d check(s) failed\n", failures);
        return 1;
    }
    std::puts("demo: all frames encoded and decoded as expected");
    return 0;
}
