// Runs the Arduino example sketch on the host: noise and two requests in, two answers out.
#include "Arduino.h"
#include "sketch.cpp"

#include <cstdio>

int main() {
    Serial.rx = {0x00, 0xFF, 0x13, 0xFF, 0xAA, 0x02, 0x02, 0, 0, 0, 0, 0x55, 0x77,   // noise, request_voltage
                 0xFF, 0xAA, 0x00, 0x01, 0, 0, 0, 0, 0x55, 0x77};                     // request_device_type
    setup();
    for (int i = 0; i < 3; ++i) loop();
    const std::vector<std::uint8_t> want{0xFF, 0xAA, 0x02, 0x12, 0x72, 0x06, 0, 0, 0x55, 0x77,  // 1650 = 0x0672
                                         0xFF, 0xAA, 0x00, 0x11, 0x02, 0, 0, 0, 0x55, 0x77};
    if (Serial.tx != want) {
        std::puts("arduino sketch: wrong answers");
        return 1;
    }
    std::puts("arduino sketch: ok");
    return 0;
}
