// A host stand-in for the Arduino core: enough to compile and run a sketch.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

struct HostSerial {
    std::vector<std::uint8_t> rx, tx;
    std::size_t pos = 0;
    void begin(unsigned long) {}
    int available() const { return static_cast<int>(rx.size() - pos); }
    int read() { return pos < rx.size() ? rx[pos++] : -1; }
    std::size_t write(const std::uint8_t* b, std::size_t n) { tx.insert(tx.end(), b, b + n); return n; }
};
inline HostSerial Serial;
