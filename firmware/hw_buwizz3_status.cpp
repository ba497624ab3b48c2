// Hand-written baseline for buwizz3_status.cpp: the status report decode alone.
// Written for size on a little-endian core: the struct is laid out so that
// each run of wire fields is a run of members (the offsets static_asserted),
// and each run is one fixed-size copy.
#include "handwritten.hpp"

namespace {
struct status {
    std::uint8_t flags, battery, current[6], temperature;  // wire 1..9
    std::int16_t accel[3];                                 // wire 10..15
    std::uint8_t bl_command, bl_code, bl_data[3], charge;  // wire 16..21
    struct { std::uint8_t type; std::int8_t velocity; std::int16_t absolute; std::int32_t position; } motors[4];
    bool has_pid;
    float process_value, error, output;  // wire 54..65
    std::int8_t integrator, motor_output;
    std::uint32_t ignored;
};
static_assert(offsetof(status, temperature) == 8 && offsetof(status, accel) == 10 &&
              offsetof(status, charge) == 21 && sizeof(status::motors) == 32 &&
              offsetof(status, motor_output) - offsetof(status, process_value) == 13,
              "each copy below is a run of members");
}  // namespace

HW_CODEC hw::error decode_status(const std::uint8_t* p, std::size_t n, status& s) {
    // robowire's order: the command byte once present, then the length
    if (n == 0) return hw::fail(hw::too_short, 0);
    if (p[0] != 0x01) return hw::fail(hw::bad_command, 0);
    if (n < 54) return hw::fail(hw::too_short, n);
    if (n > 129) return hw::fail(hw::too_long, 129);
    if (n > 54 && n < 68) return hw::fail(hw::bad_length, 54);  // bytes past the short form
    std::memcpy(&s.flags, p + 1, 9);   // flags .. temperature
    std::memcpy(s.accel, p + 10, 12);  // accel .. charge
    std::memcpy(s.motors, p + 22, 32);
    s.has_pid = n >= 68;
    if (s.has_pid) std::memcpy(&s.process_value, p + 54, 14);
    s.ignored = static_cast<std::uint32_t>(n > 68 ? n - 68 : 0);
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
