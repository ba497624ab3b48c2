// Hand-written baseline for buwizz3_status.cpp: the status report decode alone.
#include "handwritten.hpp"

namespace {
struct status {
    std::uint8_t flags, battery, current[6], temperature;
    std::int16_t accel[3];
    std::uint8_t bl_command, bl_code, bl_data[3], charge;
    struct { std::uint8_t type; std::int8_t velocity; std::int16_t absolute; std::int32_t position; } motors[4];
    bool has_pid;
    float process_value, error, output;
    std::int8_t integrator, motor_output;
    std::uint8_t ignored;
};
}  // namespace

HW_CODEC hw::error decode_status(const std::uint8_t* p, std::size_t n, status& s) {
    if (n < 54) return hw::fail(hw::too_short, n);
    if (n > 129) return hw::fail(hw::too_long, 129);
    if (n > 54 && n < 68) return hw::fail(hw::bad_length, n);
    if (p[0] != 0x01) return hw::fail(hw::bad_command, 0);
    s.flags = p[1];
    s.battery = p[2];
    std::memcpy(s.current, p + 3, 6);
    s.temperature = p[9];
    for (std::size_t i = 0; i < 3; ++i) s.accel[i] = static_cast<std::int16_t>(hw::rd16(p + 10 + 2 * i));
    s.bl_command = p[16];
    s.bl_code = p[17];
    std::memcpy(s.bl_data, p + 18, 3);
    s.charge = p[21];
    for (std::size_t i = 0; i < 4; ++i) {
        const std::uint8_t* m = p + 22 + 8 * i;
        s.motors[i] = {m[0], static_cast<std::int8_t>(m[1]), static_cast<std::int16_t>(hw::rd16(m + 2)),
                       static_cast<std::int32_t>(hw::rd32(m + 4))};
    }
    s.has_pid = n >= 68;
    if (s.has_pid) {
        s.process_value = hw::rdf(p + 54);
        s.error = hw::rdf(p + 58);
        s.output = hw::rdf(p + 62);
        s.integrator = static_cast<std::int8_t>(p[66]);
        s.motor_output = static_cast<std::int8_t>(p[67]);
    }
    s.ignored = static_cast<std::uint8_t>(n > 68 ? n - 68 : 0);
    return hw::good;
}

ENTRY void hw_buwizz3_decode_status(const std::uint8_t* p, std::size_t n) {
    status s;
    const auto e = decode_status(p, n, s);
    if (e.code == 0) hw::out(reinterpret_cast<const std::uint8_t*>(&s), sizeof s);  // every field
    else hw::report(e);
}

int main() {
    const auto in = read_input<160>();
    hw_buwizz3_decode_status(in.data(), size_in(129));
    return 0;
}
