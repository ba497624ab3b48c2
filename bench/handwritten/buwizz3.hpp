// The hand-written BuWizz3 codecs a careful user would write, with the same
// checks in robowire's order and the same error report (bench::hw): the
// baselines of bench/buwizz3.cpp, and the oracle of fuzz/diff_buwizz3.cpp,
// which shares no table with robowire. bench/verify/buwizz3.cpp proves that
// they agree with robowire on the benchmarks' inputs.
#pragma once

#include <robowire/buwizz3.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "hw.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// Internal linkage, as when these functions were part of the benchmark's own
// translation unit (the same code, the same instruction counts).
namespace {
namespace bw = robowire::buwizz3;
namespace hw = bench::hw;

// ---------------------------------------------------------------- hand-written
struct hw_status {
    std::uint8_t flags, battery, current[6], temperature;
    std::int16_t accel[3];
    std::uint8_t bl_command, bl_code, bl_data[3], charge;
    struct { std::uint8_t type; std::int8_t velocity; std::int16_t absolute; std::int32_t position; } motors[4];
    bool has_pid;
    float process_value, error, output;
    std::int8_t integrator, motor_output;
    std::uint8_t ignored_trailing_bytes;  // after the 68 known bytes (up to 129)
};
inline std::int16_t rd16(const std::uint8_t* p) { return static_cast<std::int16_t>(p[0] | p[1] << 8); }
inline std::int32_t rd32(const std::uint8_t* p) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                                     static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24);
}
inline float rdf(const std::uint8_t* p) { float f; std::memcpy(&f, p, 4); return f; }
inline void wrf(std::uint8_t* p, float f) { std::memcpy(p, &f, 4); }
constexpr bool valid_function(std::uint8_t f) { return f == 0 || f == 0x10 || (f >= 0x14 && f <= 0x16); }

// robowire's order: the command byte (if there), the length (54..129), then a
// truncated PID block (55..67 bytes).
hw::error hw_decode_status(const std::uint8_t* p, std::size_t n, hw_status& s) {
    if (n > 0 && p[0] != 0x01) return hw::fail(hw::bad_command, 0);
    if (n < 54) return hw::fail(hw::too_short, n);
    if (n > 129) return hw::fail(hw::too_long, 129);
    if (n > 54 && n < 68) return hw::fail(hw::bad_length, 54);
    s.flags = p[1];
    s.battery = p[2];
    std::memcpy(s.current, p + 3, 6);
    s.temperature = p[9];
    for (std::size_t i = 0; i < 3; ++i) s.accel[i] = rd16(p + 10 + 2 * i);
    s.bl_command = p[16];
    s.bl_code = p[17];
    std::memcpy(s.bl_data, p + 18, 3);
    s.charge = p[21];
    for (std::size_t i = 0; i < 4; ++i) {
        const std::uint8_t* m = p + 22 + 8 * i;
        s.motors[i] = {m[0], static_cast<std::int8_t>(m[1]), rd16(m + 2), rd32(m + 4)};
    }
    s.has_pid = n >= 68;
    if (s.has_pid) {
        s.process_value = rdf(p + 54);
        s.error = rdf(p + 58);
        s.output = rdf(p + 62);
        s.integrator = static_cast<std::int8_t>(p[66]);
        s.motor_output = static_cast<std::int8_t>(p[67]);
    }
    s.ignored_trailing_bytes = static_cast<std::uint8_t>(n > 68 ? n - 68 : 0);
    return hw::good;
}

// The careful decoder: into robowire's own struct (its layout checked below),
// whose members hold the wire's runs on a little-endian host, so a copy per
// run decodes them; the length forms and the command byte in one test, the
// exact error in a cold function (robowire's order: command, length, PID
// block). On an error `s` is left as it was.
static_assert(std::endian::native == std::endian::little, "the careful baselines copy little-endian runs");
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Winvalid-offsetof"
#endif
static_assert(offsetof(bw::status, flags) == 0 && offsetof(bw::status, temperature_c) == 8 &&
              offsetof(bw::status, accel_raw) == 10 && offsetof(bw::status, charge_current_ma) == 21 &&
              offsetof(bw::status, pu_motors) == 24 && sizeof(bw::pu_motor) == 8 &&
              offsetof(bw::pid_state, integrator) == 12);
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
[[gnu::cold, gnu::noinline]] hw::error careful_status_error(const std::uint8_t* p, std::size_t n) {
    if (n > 0 && p[0] != 0x01) return hw::fail(hw::bad_command, 0);
    if (n < 54) return hw::fail(hw::too_short, n);
    if (n > 129) return hw::fail(hw::too_long, 129);
    return hw::fail(hw::bad_length, 54);
}
inline hw::error careful_decode_status(const std::uint8_t* p, std::size_t n, bw::status& s) {
    if (n - 54 > 129 - 54 || (n > 54 && n < 68) || p[0] != 0x01) [[unlikely]]
        return hw::never_good(careful_status_error(p, n));
    auto* o = reinterpret_cast<unsigned char*>(&s);
    // Three copies of 16, 16 and 32 bytes, each of whole vector registers:
    // the first two also write the padding after temperature_c and
    // charge_current_ma and the start of pu_motors, which the next one overwrites.
    std::memcpy(o, p + 1, 16);        // flags .. temperature_c (o[0..8]); o[9..15] overwritten below or padding
    std::memcpy(o + 10, p + 10, 16);  // accel_raw, bootloader_response, charge_current_ma (o[10..21])
    std::memcpy(o + 24, p + 22, 32);  // pu_motors
    if (n >= 68) {
        std::memcpy(static_cast<void*>(&s.pid_state.emplace()), p + 54, 14);
        s.ignored_trailing_bytes = n - 68;
    } else {
        s.pid_state.reset();
        s.ignored_trailing_bytes = 0;
    }
    return hw::good;
}
// The port flags: 6 bits each; one compare on the good path.
inline hw::error hw_check_flags(std::uint8_t brake, std::uint8_t lut, std::size_t at) {
    if ((brake | lut) <= 0x3F) return hw::good;
    return hw::fail(hw::value_out_of_range, brake > 0x3F ? at : at + 1);
}
hw::error hw_encode_motor(const bw::set_motor_data& m, std::uint8_t* out, std::size_t size) {
    for (std::size_t i = 0; i < 6; ++i)
        if (m.power[i] == -128) return hw::fail(hw::value_out_of_range, 1 + i);
    if (auto e = hw_check_flags(m.brake_flags, m.lut_disable_flags, 7); e != hw::good) return e;
    if (size < 9) return hw::fail(hw::buffer_too_small, 9);
    out[0] = 0x30;
    std::memcpy(out + 1, m.power.data(), 6);
    out[7] = m.brake_flags;
    out[8] = m.lut_disable_flags;
    return hw::good;
}
hw::error hw_encode_motor_ext(const bw::set_motor_data_extended& m, std::uint8_t* out, std::size_t size) {
    for (std::size_t i = 0; i < 2; ++i)
        if (m.power[i] == -128) return hw::fail(hw::value_out_of_range, 17 + i);
    if (auto e = hw_check_flags(m.brake_flags, m.lut_disable_flags, 19); e != hw::good) return e;
    if (size < 21) return hw::fail(hw::buffer_too_small, 21);
    out[0] = 0x31;
    std::memcpy(out + 1, m.reference.data(), 16);  // little-endian host (as rdf and wrf)
    std::memcpy(out + 17, m.power.data(), 2);
    out[19] = m.brake_flags;
    out[20] = m.lut_disable_flags;
    return hw::good;
}
hw::error hw_encode_pid(const bw::set_pid_parameters& m, std::uint8_t* out, std::size_t size) {
    const auto mode = static_cast<std::uint8_t>(m.mode);
    if (m.port > 3) return hw::fail(hw::value_out_of_range, 1);
    if (m.lim_out < 1) return hw::fail(hw::value_out_of_range, 34);
    if (m.deadband_out < 0) return hw::fail(hw::value_out_of_range, 35);
    if (m.deadband_out_boost < 0) return hw::fail(hw::value_out_of_range, 36);
    if (!valid_function(mode)) return hw::fail(hw::invalid_enum, 37);
    if (size < 38) return hw::fail(hw::buffer_too_small, 38);
    out[0] = 0x53;
    out[1] = m.port;
    wrf(out + 2, m.out_lp);
    wrf(out + 6, m.d_lp);
    wrf(out + 10, m.speed_lp);
    wrf(out + 14, m.kp);
    wrf(out + 18, m.ki);
    wrf(out + 22, m.kd);
    wrf(out + 26, m.lim_i);
    wrf(out + 30, m.reference_rate_limit);
    out[34] = static_cast<std::uint8_t>(m.lim_out);
    out[35] = static_cast<std::uint8_t>(m.deadband_out);
    out[36] = static_cast<std::uint8_t>(m.deadband_out_boost);
    out[37] = mode;
    return hw::good;
}

// The careful encoders: the checks, the exact error in a cold function (the
// hand-written encoders above, which check in robowire's order), then the
// command byte and one copy of the struct's members, whose layout is the
// wire's (checked below; little-endian host).
static_assert(sizeof(bw::set_motor_data) == 8 && sizeof(bw::set_motor_data_extended) == 20 &&
              offsetof(bw::set_motor_data_extended, power) == 16 &&
              offsetof(bw::set_pid_parameters, out_lp) == 4 && offsetof(bw::set_pid_parameters, lim_out) == 36 &&
              offsetof(bw::set_pid_parameters, mode) == 39);
template <class M>
[[gnu::cold, gnu::noinline]] hw::error careful_encode_error(hw::error (*enc)(const M&, std::uint8_t*, std::size_t),
                                                            const M& m, std::uint8_t* out, std::size_t size) {
    return enc(m, out, size);
}
// 0x30, word arithmetic on the 8 bytes: a power byte of 0x80 (bit 7 set, the
// low seven clear: their sum with 0x7F leaves bit 7 clear), or a flag byte above 0x3F.
inline hw::error careful_encode_motor_word(const bw::set_motor_data& m, std::uint8_t* out, std::size_t size) {
    std::uint64_t q;
    std::memcpy(&q, &m, 8);
    constexpr std::uint64_t low7 = 0x7F7F7F7F7F7F7F7Full, power = 0x0000808080808080ull, flags = 0xC0C0000000000000ull;
    if ((q & ((~((q & low7) + low7) & power) | flags)) != 0 || size < 9) [[unlikely]]
        return hw::never_good(careful_encode_error(hw_encode_motor, m, out, size));
    out[0] = 0x30;
    std::memcpy(out + 1, &q, 8);
    return hw::good;
}
#if defined(__SSE2__)
// 0x30, SSE2: each byte plus off[i], as a signed byte, above lim[i] is bad
// (a power byte 0x80 becomes 0x7F; a flag byte above 0x3F lands above 0xBF).
alignas(16) inline constexpr std::uint8_t motor_off[16] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x80, 0x80};
alignas(16) inline constexpr std::uint8_t motor_lim[16] = {0x7E, 0x7E, 0x7E, 0x7E, 0x7E, 0x7E, 0xBF, 0xBF,
                                                          0x7F, 0x7F, 0x7F, 0x7F, 0x7F, 0x7F, 0x7F, 0x7F};
inline hw::error careful_encode_motor(const bw::set_motor_data& m, std::uint8_t* out, std::size_t size) {
    const auto vec = [](const std::uint8_t(&a)[16]) { return _mm_load_si128(reinterpret_cast<const __m128i*>(a)); };
    const __m128i v = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(&m));
    if (_mm_movemask_epi8(_mm_cmpgt_epi8(_mm_add_epi8(v, vec(motor_off)), vec(motor_lim))) != 0 || size < 9)
        [[unlikely]] return hw::never_good(careful_encode_error(hw_encode_motor, m, out, size));
    out[0] = 0x30;
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + 1), v);
    return hw::good;
}
#else
inline hw::error careful_encode_motor(const bw::set_motor_data& m, std::uint8_t* out, std::size_t size) {
    return careful_encode_motor_word(m, out, size);
}
#endif
// 0x31: a branch per check, the two flag bytes as one 16-bit test.
inline hw::error careful_encode_motor_ext(const bw::set_motor_data_extended& m, std::uint8_t* out, std::size_t size) {
    std::uint16_t f;  // brake_flags, lut_disable_flags
    std::memcpy(&f, &m.brake_flags, 2);
    if (m.power[0] == -128 || m.power[1] == -128 || (f & 0xC0C0) != 0 || size < 21) [[unlikely]]
        return hw::never_good(careful_encode_error(hw_encode_motor_ext, m, out, size));
    out[0] = 0x31;
    std::memcpy(out + 1, &m, 20);
    return hw::good;
}
// 0x53: a branch per check, the two deadbands' signs as one 16-bit test, the
// mode looked up in a table of the 256 values (valid: 0x00, 0x10, 0x14, 0x15, 0x16).
inline constexpr auto valid_mode = [] {
    std::array<bool, 256> t{};
    for (std::size_t i = 0; i < 256; ++i) t[i] = valid_function(static_cast<std::uint8_t>(i));
    return t;
}();
inline hw::error careful_encode_pid(const bw::set_pid_parameters& m, std::uint8_t* out, std::size_t size) {
    std::uint16_t db;  // deadband_out, deadband_out_boost
    std::memcpy(&db, &m.deadband_out, 2);
    if (m.port > 3 || m.lim_out < 1 || (db & 0x8080) != 0 || !valid_mode[static_cast<std::uint8_t>(m.mode)] ||
        size < 38) [[unlikely]]
        return hw::never_good(careful_encode_error(hw_encode_pid, m, out, size));
    out[0] = 0x53;
    out[1] = m.port;
    std::memcpy(out + 2, reinterpret_cast<const unsigned char*>(&m) + 4, 36);
    return hw::good;
}
// A careful user's dispatcher: tagged union, the same checks and the same
// error report (bench::hw), the LED blink bytes split into frequency and duty
// as robowire does.
struct hw_wakeup { bool enabled; std::uint32_t idle, sleep; };
struct hw_motor { std::int8_t power[6]; std::uint8_t brake, lut; };
struct hw_motor_ext { std::int32_t ref[4]; std::int8_t power[2]; std::uint8_t brake, lut; };
struct hw_led { bool has_colors, has_blink; std::uint8_t rgb[12]; struct { std::uint8_t frequency, duty; } blink[4]; };
struct hw_uart { std::uint8_t channel; std::uint32_t baud; };
struct hw_pid { std::uint8_t port; float f[8]; std::int8_t lim_out, db, boost; std::uint8_t mode; };
struct hw_command {
    std::uint8_t kind;
    union {
        char name[13];
        hw_wakeup wakeup;
        float factors[6];
        hw_motor motor;
        hw_motor_ext motor_ext;
        std::uint8_t one;
        std::uint8_t ramps[12];
        hw_led led;
        std::uint8_t limits[6];
        hw_uart uart;
        std::uint8_t functions[4];
        std::int32_t reference[4];
        hw_pid pid;
    };
};
inline hw::error hw_power(const std::uint8_t* p, std::size_t n, std::size_t at, std::int8_t* out) {
    for (std::size_t i = 0; i < n; ++i) {
        if (p[at + i] == 0x80) return hw::fail(hw::value_out_of_range, at + i);
        out[i] = static_cast<std::int8_t>(p[at + i]);
    }
    return hw::good;
}
inline hw::error hw_flags(const std::uint8_t* p, std::size_t at) {
    if (p[at] & 0xC0) return hw::fail(hw::value_out_of_range, at);
    if (p[at + 1] & 0xC0) return hw::fail(hw::value_out_of_range, at + 1);
    return hw::good;
}
hw::error hw_decode_command(const std::uint8_t* p, std::size_t n, hw_command& c) {
    if (n == 0) return hw::fail(hw::too_short, 0);
    c.kind = p[0];
    switch (p[0]) {
    case 0x20: {
        if (auto e = hw::length(n, 13); e != hw::good) return e;
        std::size_t len = 0;
        while (len < 12 && p[1 + len]) ++len;
        for (std::size_t i = len; i < 12; ++i) if (p[1 + i]) return hw::fail(hw::bad_padding, 1 + i);
        std::memcpy(c.name, p + 1, 12);
        c.name[12] = 0;
        return hw::good;
    }
    case 0x21:
        if (auto e = hw::length(n, 10); e != hw::good) return e;
        if (p[1] > 1) return hw::fail(hw::value_out_of_range, 1);
        c.wakeup = {p[1] != 0, static_cast<std::uint32_t>(rd32(p + 2)), static_cast<std::uint32_t>(rd32(p + 6))};
        return c.wakeup.idle >= 10 ? hw::good : hw::fail(hw::value_out_of_range, 2);
    case 0x22:
        if (auto e = hw::length(n, 25); e != hw::good) return e;
        for (std::size_t i = 0; i < 6; ++i) c.factors[i] = rdf(p + 1 + 4 * i);
        return hw::good;
    case 0x23: case 0xA1: case 0xAC: return hw::length(n, 1);
    case 0x30:
        if (auto e = hw::length(n, 9); e != hw::good) return e;
        if (auto e = hw_power(p, 6, 1, c.motor.power); e != hw::good) return e;
        if (auto e = hw_flags(p, 7); e != hw::good) return e;
        c.motor.brake = p[7];
        c.motor.lut = p[8];
        return hw::good;
    case 0x31:
        if (auto e = hw::length(n, 21); e != hw::good) return e;
        for (std::size_t i = 0; i < 4; ++i) c.motor_ext.ref[i] = rd32(p + 1 + 4 * i);
        if (auto e = hw_power(p, 2, 17, c.motor_ext.power); e != hw::good) return e;
        if (auto e = hw_flags(p, 19); e != hw::good) return e;
        c.motor_ext.brake = p[19];
        c.motor_ext.lut = p[20];
        return hw::good;
    case 0x32:
        if (auto e = hw::length(n, 2); e != hw::good) return e;
        if (p[1] < 20) return hw::fail(hw::value_out_of_range, 1);
        c.one = p[1];
        return hw::good;
    case 0x33:
        if (auto e = hw::length(n, 13); e != hw::good) return e;
        std::memcpy(c.ramps, p + 1, 12);
        return hw::good;
    case 0x34:
        if (auto e = hw::length(n, 2); e != hw::good) return e;
        if (p[1] == 255) return hw::fail(hw::value_out_of_range, 1);
        c.one = p[1];
        return hw::good;
    case 0x35:
        if (auto e = hw::length(n, 2); e != hw::good) return e;
        c.one = p[1];
        return hw::good;
    case 0x36:
        if (n != 1 && n != 13 && n != 17)  // bad_length: at the start of the block cut short
            return n > 17 ? hw::fail(hw::too_long, 17) : hw::fail(hw::bad_length, n < 13 ? 1 : 13);
        c.led.has_colors = n > 1;
        c.led.has_blink = n > 13;
        if (n > 1) std::memcpy(c.led.rgb, p + 1, 12);
        if (n > 13)
            for (std::size_t i = 0; i < 4; ++i) {
                c.led.blink[i].frequency = static_cast<std::uint8_t>(p[13 + i] >> 4);
                c.led.blink[i].duty = p[13 + i] & 0x0F;
            }
        return hw::good;
    case 0x37:
        if (auto e = hw::length(n, 2); e != hw::good) return e;
        if (p[1] > 3 && (p[1] < 8 || p[1] > 11)) return hw::fail(hw::invalid_enum, 1);
        c.one = p[1];
        return hw::good;
    case 0x38:
        if (auto e = hw::length(n, 7); e != hw::good) return e;
        std::memcpy(c.limits, p + 1, 6);
        return hw::good;
    case 0x40:
        if (n > 1 && p[1] != 0x10) return hw::fail(hw::bad_command, 1);
        if (auto e = hw::length(n, 7); e != hw::good) return e;
        c.uart = {p[2], static_cast<std::uint32_t>(rd32(p + 3))};
        return hw::good;
    case 0x50:
        if (auto e = hw::length(n, 5); e != hw::good) return e;
        for (std::size_t i = 0; i < 4; ++i) {
            if (!valid_function(p[1 + i])) return hw::fail(hw::invalid_enum, 1 + i);
            c.functions[i] = p[1 + i];
        }
        return hw::good;
    case 0x51:
        if (auto e = hw::length(n, 2); e != hw::good) return e;
        if (p[1] > 4) return hw::fail(hw::value_out_of_range, 1);
        c.one = p[1];
        return hw::good;
    case 0x52:
        if (auto e = hw::length(n, 17); e != hw::good) return e;
        for (std::size_t i = 0; i < 4; ++i) c.reference[i] = rd32(p + 1 + 4 * i);
        return hw::good;
    case 0x53:
        if (auto e = hw::length(n, 38); e != hw::good) return e;
        if (p[1] > 3) return hw::fail(hw::value_out_of_range, 1);
        c.pid.port = p[1];
        for (std::size_t i = 0; i < 8; ++i) c.pid.f[i] = rdf(p + 2 + 4 * i);
        c.pid.lim_out = static_cast<std::int8_t>(p[34]);
        c.pid.db = static_cast<std::int8_t>(p[35]);
        c.pid.boost = static_cast<std::int8_t>(p[36]);
        c.pid.mode = p[37];
        if (c.pid.lim_out < 1) return hw::fail(hw::value_out_of_range, 34);
        if (c.pid.db < 0) return hw::fail(hw::value_out_of_range, 35);
        if (c.pid.boost < 0) return hw::fail(hw::value_out_of_range, 36);
        return valid_function(p[37]) ? hw::good : hw::fail(hw::invalid_enum, 37);
    default: return hw::fail(hw::unknown_message, 0);
    }
}

// The hand-written status and robowire's hold the same values (floats: the same bits).
[[maybe_unused]] bool same_status(const hw_status& h, const bw::status& s) {
    if (h.flags != s.flags || h.battery != s.battery_voltage_raw || h.temperature != s.temperature_c ||
        h.charge != s.charge_current_ma) return false;
    for (std::size_t i = 0; i < 6; ++i) if (h.current[i] != s.motor_current_raw[i]) return false;
    for (std::size_t i = 0; i < 3; ++i) if (h.accel[i] != s.accel_raw[i]) return false;
    if (h.bl_command != s.bootloader_response.command || h.bl_code != s.bootloader_response.code) return false;
    for (std::size_t i = 0; i < 3; ++i) if (h.bl_data[i] != s.bootloader_response.data[i]) return false;
    for (std::size_t i = 0; i < 4; ++i) {
        const auto& m = s.pu_motors[i];
        if (h.motors[i].type != m.type || h.motors[i].velocity != m.velocity ||
            h.motors[i].absolute != m.absolute_position || h.motors[i].position != m.position) return false;
    }
    if (h.has_pid != s.pid_state.has_value()) return false;
    if (h.has_pid) {
        const auto& p = *s.pid_state;
        if (std::memcmp(&h.process_value, &p.process_value, 4) || std::memcmp(&h.error, &p.error, 4) ||
            std::memcmp(&h.output, &p.output, 4) || h.integrator != p.integrator || h.motor_output != p.motor_output)
            return false;
    }
    return h.ignored_trailing_bytes == s.ignored_trailing_bytes;
}

}  // namespace
