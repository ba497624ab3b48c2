// Hand-written baseline for buwizz3.cpp: every command decoded and encoded,
// every notification decoded, the 0x31 drive command built from values.
// Written for size on a little-endian core: where a command's wire fields are
// a run of struct members (the offsets static_asserted), one fixed-size copy.
#include "handwritten.hpp"

namespace {
struct wakeup_t { std::uint8_t enabled; std::uint32_t idle, sleep; };
struct motor_t { std::int8_t power[6]; std::uint8_t brake, lut; };
struct motor_ext_t { std::int32_t ref[4]; std::int8_t power[2]; std::uint8_t brake, lut; };
struct led_t { bool has_colors, has_blink; std::uint8_t rgb[12], frequency_hz[4], duty[4]; };
struct uart_t { std::uint8_t channel; std::uint32_t baud; };
struct pid_params { std::uint8_t port; float f[8]; std::int8_t lim_out, db, boost; std::uint8_t mode; };
struct command {
    std::uint8_t kind;  // the command byte
    union {
        char name[12];
        wakeup_t wakeup;
        float factors[6];
        motor_t motor;
        motor_ext_t motor_ext;
        std::uint8_t one;  // 0x32, 0x34, 0x35, 0x37, 0x51
        std::uint8_t ramps[12];
        led_t led;
        std::uint8_t limits[6];
        uart_t uart;
        std::uint8_t functions[4];
        std::int32_t reference[4];
        pid_params pid;
    };
};
// The runs copied below: wire bytes [a, b) are the members from the named one on.
static_assert(sizeof(command::motor) == 8 && sizeof(command::motor_ext) == 20, "0x30: wire 1..8, 0x31: wire 1..20");
static_assert(sizeof(command::pid) == 40, "0x53: f[8] .. mode are wire 2..37");
static_assert(sizeof(command::wakeup) == 12, "0x21: idle, sleep are wire 2..9");
bool valid_function(std::uint8_t f) { return f == 0 || f == 0x10 || (f >= 0x14 && f <= 0x16); }
bool valid_lpf(std::uint8_t v) { return v <= 3 || (v >= 8 && v <= 11); }
// The wire length of each command (0: unknown; 0x36 has three).
std::size_t wire_size(std::uint8_t c) {
    switch (c) {
    case 0x20: return 13; case 0x21: return 10; case 0x22: return 25;
    case 0x23: case 0xA1: case 0xAC: case 0x36: return 1;
    case 0x30: return 9; case 0x31: return 21; case 0x33: return 13; case 0x38: return 7; case 0x40: return 7;
    case 0x32: case 0x34: case 0x35: case 0x37: case 0x51: return 2;
    case 0x50: return 5; case 0x52: return 17; case 0x53: return 38;
    default: return 0;
    }
}
hw::error check_power(const std::int8_t* p, std::size_t n, std::size_t at) {
    for (std::size_t i = 0; i < n; ++i)
        if (p[i] == -128) return hw::fail(hw::value_out_of_range, at + i);
    return hw::good;
}
hw::error check_flags(std::uint8_t brake, std::uint8_t lut, std::size_t at) {
    if (brake & 0xC0) return hw::fail(hw::value_out_of_range, at);
    if (lut & 0xC0) return hw::fail(hw::value_out_of_range, at + 1);
    return hw::good;
}

HW_CODEC hw::error decode_command(const std::uint8_t* p, std::size_t n, command& c) {
    if (n == 0) return hw::fail(hw::too_short, 0);
    c.kind = p[0];
    const std::size_t want = wire_size(p[0]);
    if (want == 0) return hw::fail(hw::unknown_message, 0);
    if (p[0] == 0x40 && n > 1 && p[1] != 0x10) return hw::fail(hw::bad_command, 1);  // fixed bytes, then the length
    if (p[0] == 0x36) {
        if (n != 1 && n != 13 && n != 17)  // bad_length at the first byte past the last whole form
            return n > 17 ? hw::fail(hw::too_long, 17) : hw::fail(hw::bad_length, n < 13 ? 1 : 13);
    } else if (auto e = hw::length(n, want); e.code) {
        return e;
    }
    switch (p[0]) {
    case 0x20: {
        std::size_t len = 0;
        while (len < 12 && p[1 + len]) ++len;
        for (std::size_t i = len; i < 12; ++i)
            if (p[1 + i]) return hw::fail(hw::bad_padding, 1 + i);
        std::memcpy(c.name, p + 1, 12);
        return hw::good;
    }
    case 0x21:
        if (p[1] > 1) return hw::fail(hw::value_out_of_range, 1);
        c.wakeup.enabled = p[1];
        std::memcpy(&c.wakeup.idle, p + 2, 8);
        return c.wakeup.idle >= 10 ? hw::good : hw::fail(hw::value_out_of_range, 2);
    case 0x22: std::memcpy(c.factors, p + 1, 24); return hw::good;
    case 0x23: case 0xA1: case 0xAC: return hw::good;
    case 0x30:
        std::memcpy(&c.motor, p + 1, 8);
        if (auto e = check_power(c.motor.power, 6, 1); e.code) return e;
        return check_flags(p[7], p[8], 7);
    case 0x31:
        std::memcpy(&c.motor_ext, p + 1, 20);
        if (auto e = check_power(c.motor_ext.power, 2, 17); e.code) return e;
        return check_flags(p[19], p[20], 19);
    case 0x32: c.one = p[1]; return p[1] >= 20 ? hw::good : hw::fail(hw::value_out_of_range, 1);
    case 0x33: std::memcpy(c.ramps, p + 1, 12); return hw::good;
    case 0x34: c.one = p[1]; return p[1] != 255 ? hw::good : hw::fail(hw::value_out_of_range, 1);
    case 0x35: c.one = p[1]; return hw::good;
    case 0x36:  // colours (r, g, b per port), then blink (frequency << 4 | duty per port)
        c.led.has_colors = n >= 13;
        c.led.has_blink = n == 17;
        if (c.led.has_colors) std::memcpy(c.led.rgb, p + 1, 12);
        if (c.led.has_blink) {
            for (std::size_t i = 0; i < 4; ++i) {
                c.led.frequency_hz[i] = static_cast<std::uint8_t>(p[13 + i] >> 4);
                c.led.duty[i] = p[13 + i] & 15;
            }
        }
        return hw::good;
    case 0x37: c.one = p[1]; return valid_lpf(p[1]) ? hw::good : hw::fail(hw::invalid_enum, 1);
    case 0x38: std::memcpy(c.limits, p + 1, 6); return hw::good;
    case 0x40:
        c.uart.channel = p[2];
        std::memcpy(&c.uart.baud, p + 3, 4);
        return hw::good;
    case 0x50:
        for (std::size_t i = 0; i < 4; ++i) {
            if (!valid_function(p[1 + i])) return hw::fail(hw::invalid_enum, 1 + i);
            c.functions[i] = p[1 + i];
        }
        return hw::good;
    case 0x51: c.one = p[1]; return p[1] <= 4 ? hw::good : hw::fail(hw::value_out_of_range, 1);
    case 0x52: std::memcpy(c.reference, p + 1, 16); return hw::good;
    case 0x53:
        if (p[1] > 3) return hw::fail(hw::value_out_of_range, 1);
        c.pid.port = p[1];
        std::memcpy(c.pid.f, p + 2, 36);
        if (c.pid.lim_out < 1) return hw::fail(hw::value_out_of_range, 34);
        if (c.pid.db < 0) return hw::fail(hw::value_out_of_range, 35);
        if (c.pid.boost < 0) return hw::fail(hw::value_out_of_range, 36);
        return valid_function(p[37]) ? hw::good : hw::fail(hw::invalid_enum, 37);
    default: return hw::fail(hw::unknown_message, 0);
    }
}

// Encodes c into out (at least 38 bytes); checks every field first. Returns the length, 0 on error.
HW_CODEC std::size_t encode_command(const command& c, std::uint8_t* out, hw::error& e) {
    std::size_t n = c.kind == 0x36 ? 1u + (c.led.has_colors ? 12u : 0u) + (c.led.has_blink ? 4u : 0u) : wire_size(c.kind);
    e = hw::good;
    switch (c.kind) {
    case 0x21:
        if (c.wakeup.enabled > 1) e = hw::fail(hw::value_out_of_range, 1);
        else if (c.wakeup.idle < 10) e = hw::fail(hw::value_out_of_range, 2);
        break;
    case 0x30: e = check_power(c.motor.power, 6, 1); if (!e.code) e = check_flags(c.motor.brake, c.motor.lut, 7); break;
    case 0x31: e = check_power(c.motor_ext.power, 2, 17); if (!e.code) e = check_flags(c.motor_ext.brake, c.motor_ext.lut, 19); break;
    case 0x32: if (c.one < 20) e = hw::fail(hw::value_out_of_range, 1); break;
    case 0x34: if (c.one == 255) e = hw::fail(hw::value_out_of_range, 1); break;
    case 0x36:
        if (c.led.has_blink && !c.led.has_colors) e = hw::fail(hw::missing_field, 1);
        else if (c.led.has_blink)
            for (std::size_t i = 0; i < 4 && !e.code; ++i)
                if ((c.led.frequency_hz[i] | c.led.duty[i]) > 15) e = hw::fail(hw::value_out_of_range, 13 + i);
        break;
    case 0x37: if (!valid_lpf(c.one)) e = hw::fail(hw::invalid_enum, 1); break;
    case 0x50: for (std::size_t i = 0; i < 4 && !e.code; ++i) if (!valid_function(c.functions[i])) e = hw::fail(hw::invalid_enum, 1 + i); break;
    case 0x51: if (c.one > 4) e = hw::fail(hw::value_out_of_range, 1); break;
    case 0x53:
        if (c.pid.port > 3) e = hw::fail(hw::value_out_of_range, 1);
        else if (c.pid.lim_out < 1) e = hw::fail(hw::value_out_of_range, 34);
        else if (c.pid.db < 0) e = hw::fail(hw::value_out_of_range, 35);
        else if (c.pid.boost < 0) e = hw::fail(hw::value_out_of_range, 36);
        else if (!valid_function(c.pid.mode)) e = hw::fail(hw::invalid_enum, 37);
        break;
    default: if (n == 0) e = hw::fail(hw::unknown_message, 0); break;
    }
    if (e.code) return 0;
    out[0] = c.kind;
    switch (c.kind) {
    case 0x20: {
        std::size_t len = 0;
        while (len < 12 && c.name[len]) ++len;
        std::memcpy(out + 1, c.name, len);
        std::memset(out + 1 + len, 0, 12 - len);
        break;
    }
    case 0x21: out[1] = c.wakeup.enabled; std::memcpy(out + 2, &c.wakeup.idle, 8); break;
    case 0x22: std::memcpy(out + 1, c.factors, 24); break;
    case 0x30: std::memcpy(out + 1, &c.motor, 8); break;
    case 0x31: std::memcpy(out + 1, &c.motor_ext, 20); break;
    case 0x32: case 0x34: case 0x35: case 0x37: case 0x51: out[1] = c.one; break;
    case 0x33: std::memcpy(out + 1, c.ramps, 12); break;
    case 0x36:
        if (c.led.has_colors) std::memcpy(out + 1, c.led.rgb, 12);
        if (c.led.has_blink)
            for (std::size_t i = 0; i < 4; ++i)
                out[13 + i] = static_cast<std::uint8_t>(c.led.frequency_hz[i] << 4 | c.led.duty[i]);
        break;
    case 0x38: std::memcpy(out + 1, c.limits, 6); break;
    case 0x40: out[1] = 0x10; out[2] = c.uart.channel; std::memcpy(out + 3, &c.uart.baud, 4); break;
    case 0x50: std::memcpy(out + 1, c.functions, 4); break;
    case 0x52: std::memcpy(out + 1, c.reference, 16); break;
    case 0x53: out[1] = c.pid.port; std::memcpy(out + 2, c.pid.f, 36); break;
    default: break;
    }
    return n;
}

struct status {  // laid out as hw_buwizz3_status.cpp's
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
              "each status copy below is a run of members");
struct charger_t { std::uint8_t n; std::uint8_t data[128]; };
struct notification {
    std::uint8_t kind;
    union {
        status s;
        float factors[6];
        charger_t charger;
    };
};
HW_CODEC hw::error decode_status(const std::uint8_t* p, std::size_t n, status& s) {
    if (n < 54) return hw::fail(hw::too_short, n);  // p[0] is 0x01 (the caller's switch)
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
HW_CODEC hw::error decode_notification(const std::uint8_t* p, std::size_t n, notification& m) {
    if (n == 0) return hw::fail(hw::too_short, 0);
    m.kind = p[0];
    switch (p[0]) {
    case 0x01: return decode_status(p, n, m.s);
    case 0x23:
        if (auto e = hw::length(n, 25); e.code) return e;
        std::memcpy(m.factors, p + 1, 24);
        return hw::good;
    case 0xAC:
        if (n > 129) return hw::fail(hw::too_long, 129);
        m.charger.n = static_cast<std::uint8_t>(n - 1);
        std::memcpy(m.charger.data, p + 1, n - 1);
        return hw::good;
    default: return hw::fail(hw::unknown_message, 0);
    }
}
}  // namespace

ENTRY void hw_buwizz3_decode_command(const std::uint8_t* p, std::size_t n) {
    command c;
    const auto e = decode_command(p, n, c);
    if (e.code == 0) hw::out(reinterpret_cast<const std::uint8_t*>(&c), sizeof c);  // every field
    else sink = e.code;
}
ENTRY void hw_buwizz3_decode_notification(const std::uint8_t* p, std::size_t n) {
    notification m;
    const auto e = decode_notification(p, n, m);
    if (e.code == 0) hw::out(reinterpret_cast<const std::uint8_t*>(&m), sizeof m);  // every field
    else sink = e.code;
}
ENTRY void hw_buwizz3_encode_command(const std::uint8_t* p, std::size_t n) {
    command c;
    if (decode_command(p, n, c).code) return;
    std::uint8_t out[38];
    hw::error e;
    if (const std::size_t k = encode_command(c, out, e)) hw::out(out, k);
}
ENTRY void hw_buwizz3_encode_drive(const std::uint8_t* b) {
    command c;
    c.kind = 0x31;
    for (std::size_t i = 0; i < 4; ++i) c.motor_ext.ref[i] = static_cast<std::int32_t>(b[i] * 1000);
    c.motor_ext.power[0] = static_cast<std::int8_t>(b[4]);  // every field from the input, as buwizz3.cpp
    c.motor_ext.power[1] = static_cast<std::int8_t>(b[5]);
    c.motor_ext.brake = b[6];
    c.motor_ext.lut = b[7];
    std::uint8_t out[38];
    hw::error e;
    if (const std::size_t k = encode_command(c, out, e)) hw::out(out, k);
}

int main() {
    const auto in = read_input<160>();
    const auto n = size_in(129);
    hw_buwizz3_decode_command(in.data(), n);
    hw_buwizz3_decode_notification(in.data(), n);
    hw_buwizz3_encode_command(in.data(), n);
    hw_buwizz3_encode_drive(in.data());
    return 0;
}
