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
    std::printf("  bad frame: %s at byte %zu\n", robowire::to_string(err.code()).data(), err.error().offset);
    expect(err.error() == robowire::error{robowire::errc::bad_trailer, 9}, "osp bad trailer");
}
}  // namespace

int main() {
    osp_demo();
    if (failures) {
        std::printf("%d check(s) failed\n", failures);
        return 1;
    }
    std::puts("demo: all frames encoded and decoded as expected");
    return 0;
}
