// An OSP battery pack on a serial port: finds requests in the byte stream and answers them.
#include <robowire.h>

namespace osp = robowire::osp;

osp::scanner scanner;

struct battery {
    osp::obp1::soc operator()(const osp::obp1::request_soc&) const { return {52428}; }        // 80 %
    osp::obp1::voltage operator()(const osp::obp1::request_voltage&) const { return {1650}; }  // 16.50 V
    osp::generic::device_type operator()(const osp::generic::request_device_type&) const {
        return {osp::device_type::obp1};
    }
};

void setup() { Serial.begin(115200); }

void loop() {
    while (Serial.available() > 0) {
        const std::uint8_t byte = static_cast<std::uint8_t>(Serial.read());
        scanner.feed(std::span(&byte, 1), [](osp::scanner::frame_bytes frame) {
            const auto answer = osp::serve(frame, battery{});
            if (answer && *answer) Serial.write((*answer)->data(), (*answer)->size());
        });
    }
}
