// BuWizz3: status decode, command encode, decode_command over a mixed batch.
// Baselines: memcpy of the same bytes (the floor) and the hand-written codec
// a careful user would write (shifts and memcpy into a plain struct, with the
// same length, command and range checks in robowire's order, and the same
// error report: bench::hw, an error code and its byte offset). The encoders
// check every field, then the buffer's size, before writing any byte.
#include <robowire/buwizz3.hpp>

#include <bit>
#include <cstddef>

#include "common.hpp"

namespace {
namespace bw = robowire::buwizz3;
namespace hw = bench::hw;

// ---------------------------------------------------------------- inputs
constexpr std::array<std::uint8_t, 68> status68{
    0x01, 0x73, 0x50, 0x0A, 0x14, 0x1E, 0x28, 0x32, 0xC8, 0x23, 0xF0, 0xFF, 0xF0, 0x7F, 0x00, 0x08, 0x0B,
    0x0C, 0x0D, 0x0E, 0x0F, 0x7D, 0x30, 0xEC, 0x4C, 0xFF, 0x60, 0x79, 0xFE, 0xFF, 0x31, 0x64, 0xB3, 0x00,
    0x40, 0xE2, 0x01, 0x00, 0x4B, 0xFF, 0x01, 0x00, 0x01, 0x00, 0x00, 0x00, 0x4C, 0x7F, 0xFF, 0xFF, 0xFF,
    0xFF, 0xFF, 0x7F, 0x9A, 0x99, 0x19, 0x3F, 0x00, 0x00, 0x20, 0xC0, 0x00, 0x00, 0x4C, 0x41, 0xF9, 0x2A};

// `variants` different status reports (accelerometer and positions vary).
bench::vector<std::array<std::uint8_t, 68>> status_inputs() {
    bench::rng r;
    bench::vector<std::array<std::uint8_t, 68>> v(bench::variants, status68);
    for (auto& s : v)
        for (std::size_t i : {10u, 11u, 12u, 13u, 26u, 27u, 34u, 35u, 54u, 55u}) s[i] = r.byte();
    return v;
}

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
inline bool valid_function(std::uint8_t f) { return f == 0 || f == 0x10 || (f >= 0x14 && f <= 0x16); }

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
        return careful_status_error(p, n);
    auto* o = reinterpret_cast<unsigned char*>(&s);
    std::memcpy(o, p + 1, 9);     // flags .. temperature_c
    std::memcpy(o + 10, p + 10, 12);  // accel_raw, bootloader_response, charge_current_ma
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

template <std::size_t N>
void status_decode_robowire(benchmark::State& state) {
    const auto in = status_inputs();
    for (auto _ : bench::measure(state)) {
        for (const auto& item : in) {
            auto r = robowire::decode<bw::status>(std::span(item).first(N));
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, in.size());
}
template <std::size_t N>
void status_decode_into(benchmark::State& state) {
    const auto in = status_inputs();
    bw::status s{};
    bench::in_memory(s);
    for (auto _ : bench::measure(state)) {
        for (const auto& item : in) {
            auto e = robowire::decode_into(s, std::span(item).first(N));
            bench::consume(e);
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, in.size());
}
template <std::size_t N>
void status_decode_handwritten(benchmark::State& state) {
    const auto in = status_inputs();
    hw_status s{};
    bench::in_memory(s);
    for (auto _ : bench::measure(state)) {
        for (const auto& item : in) {
            bench::consume(hw_decode_status(item.data(), N, s));
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, in.size());
}
template <std::size_t N>
void status_decode_memcpy(benchmark::State& state) {
    const auto in = status_inputs();
    std::array<std::uint8_t, 68> out{};
    for (auto _ : bench::measure(state)) {
        for (const auto& item : in) {
            std::memcpy(out.data(), item.data(), N);
            benchmark::DoNotOptimize(out);
        }
    }
    bench::messages(state, in.size());
}

// The same, with the length loaded per message from memory, as a BLE stack
// hands a notification over ("_runtime_length" cases).
template <std::size_t N>
bench::vector<std::size_t> lengths() {
    return bench::vector<std::size_t>(bench::variants, N);
}
template <std::size_t N, bool RuntimeLength>
void status_decode_rw(benchmark::State& state) {
    const auto in = status_inputs();
    const auto len = lengths<N>();
    const std::size_t count = in.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t n = RuntimeLength ? len[i] : N;
            auto r = robowire::decode<bw::status>(std::span(in[i]).first(n));
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, in.size());
}
template <std::size_t N, bool RuntimeLength>
void status_decode_into_rw(benchmark::State& state) {
    const auto in = status_inputs();
    const auto len = lengths<N>();
    bw::status s{};
    bench::in_memory(s);
    const std::size_t count = in.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t n = RuntimeLength ? len[i] : N;
            auto e = robowire::decode_into(s, std::span(in[i]).first(n));
            bench::consume(e);
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, in.size());
}
template <std::size_t N, bool RuntimeLength>
void status_decode_careful(benchmark::State& state) {
    const auto in = status_inputs();
    const auto len = lengths<N>();
    bw::status s{};
    bench::in_memory(s);
    const std::size_t count = in.size();  // in a register: not reloaded after each clobber
    for (auto _ : bench::measure(state)) {
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t n = RuntimeLength ? len[i] : N;
            bench::consume(careful_decode_status(in[i].data(), n, s));
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, in.size());
}

// ---- encoders: 0x30, 0x31, 0x53
bench::vector<bw::set_motor_data> motor_inputs() {
    bench::rng r;
    bench::vector<bw::set_motor_data> v(bench::variants);
    for (auto& m : v) {
        for (auto& p : m.power) p = static_cast<std::int8_t>(static_cast<int>(r.next() % 255) - 127);
        m.brake_flags = r.byte() & 0x3F;
        m.lut_disable_flags = r.byte() & 0x3F;
    }
    return v;
}
bench::vector<bw::set_motor_data_extended> motor_ext_inputs() {
    bench::rng r;
    bench::vector<bw::set_motor_data_extended> v(bench::variants);
    for (auto& m : v) {
        for (auto& x : m.reference) x = static_cast<std::int32_t>(r.next());
        for (auto& p : m.power) p = static_cast<std::int8_t>(static_cast<int>(r.next() % 255) - 127);
        m.brake_flags = r.byte() & 0x3F;
        m.lut_disable_flags = r.byte() & 0x3F;
    }
    return v;
}
bench::vector<bw::set_pid_parameters> pid_inputs() {
    bench::rng r;
    bench::vector<bw::set_pid_parameters> v(bench::variants);
    for (auto& m : v) {
        m = (r.next() & 1) ? bw::position_servo_preset(r.byte() & 3) : bw::speed_servo_preset(r.byte() & 3);
        m.kp = static_cast<float>(r.next() % 1000) / 1000.0f;
    }
    return v;
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

// The careful encoders: every check as one yes/no, the exact error in a cold
// function (the hand-written encoders above, which check in robowire's
// order), then the command byte and one copy of the struct's members, whose
// layout is the wire's (checked below; little-endian host).
static_assert(sizeof(bw::set_motor_data) == 8 && sizeof(bw::set_motor_data_extended) == 20 &&
              offsetof(bw::set_pid_parameters, out_lp) == 4 && offsetof(bw::set_pid_parameters, mode) == 39);
template <class M>
[[gnu::cold, gnu::noinline]] hw::error careful_encode_error(hw::error (*enc)(const M&, std::uint8_t*, std::size_t),
                                                            const M& m, std::uint8_t* out, std::size_t size) {
    return enc(m, out, size);
}
inline unsigned power_bad(const std::int8_t* p, std::size_t n) {  // any power of -128
    unsigned bad = 0;
    for (std::size_t i = 0; i < n; ++i) bad |= p[i] == -128;
    return bad;
}
inline hw::error careful_encode_motor(const bw::set_motor_data& m, std::uint8_t* out, std::size_t size) {
    if (power_bad(m.power.data(), 6) | ((m.brake_flags | m.lut_disable_flags) > 0x3F) | (size < 9)) [[unlikely]]
        return careful_encode_error(hw_encode_motor, m, out, size);
    out[0] = 0x30;
    std::memcpy(out + 1, &m, 8);
    return hw::good;
}
inline hw::error careful_encode_motor_ext(const bw::set_motor_data_extended& m, std::uint8_t* out, std::size_t size) {
    if (power_bad(m.power.data(), 2) | ((m.brake_flags | m.lut_disable_flags) > 0x3F) | (size < 21)) [[unlikely]]
        return careful_encode_error(hw_encode_motor_ext, m, out, size);
    out[0] = 0x31;
    std::memcpy(out + 1, &m, 20);
    return hw::good;
}
inline hw::error careful_encode_pid(const bw::set_pid_parameters& m, std::uint8_t* out, std::size_t size) {
    const auto mode = static_cast<std::uint8_t>(m.mode);
    if (static_cast<unsigned>(m.port > 3) | (m.lim_out < 1) | ((m.deadband_out | m.deadband_out_boost) < 0) | !valid_function(mode) |
        (size < 38)) [[unlikely]]
        return careful_encode_error(hw_encode_pid, m, out, size);
    out[0] = 0x53;
    out[1] = m.port;
    std::memcpy(out + 2, reinterpret_cast<const unsigned char*>(&m) + 4, 36);
    return hw::good;
}

template <class M, class Make>
void encode_robowire(benchmark::State& state, Make make) {
    const auto in = make();
    for (auto _ : bench::measure(state)) {
        for (const auto& item : in) {
            alignas(64) auto r = robowire::encode(item);  // aligned like the baselines' buffers
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, in.size());
}
template <class M, class Make>
void encode_to_robowire(benchmark::State& state, Make make) {
    const auto in = make();
    alignas(64) std::array<std::uint8_t, 64> out{};
    for (auto _ : bench::measure(state)) {
        for (const auto& item : in) {
            const auto n = robowire::encode_to(item, out);
            bench::consume(n);
            benchmark::DoNotOptimize(out);
        }
    }
    bench::messages(state, in.size());
}
template <class M, class Make, class Enc>
void encode_handwritten(benchmark::State& state, Make make, Enc enc) {
    const auto in = make();
    alignas(64) std::array<std::uint8_t, 64> out{};
    for (auto _ : bench::measure(state)) {
        for (const auto& item : in) {
            bench::consume(enc(item, out.data(), out.size()));
            benchmark::DoNotOptimize(out);
        }
    }
    bench::messages(state, in.size());
}

void encode30_robowire(benchmark::State& s) { encode_robowire<bw::set_motor_data>(s, motor_inputs); }
void encode30_to(benchmark::State& s) { encode_to_robowire<bw::set_motor_data>(s, motor_inputs); }
void encode31_to(benchmark::State& s) { encode_to_robowire<bw::set_motor_data_extended>(s, motor_ext_inputs); }
void encode53_to(benchmark::State& s) { encode_to_robowire<bw::set_pid_parameters>(s, pid_inputs); }
void encode30_handwritten(benchmark::State& s) { encode_handwritten<bw::set_motor_data>(s, motor_inputs, hw_encode_motor); }
void encode31_robowire(benchmark::State& s) { encode_robowire<bw::set_motor_data_extended>(s, motor_ext_inputs); }
void encode31_handwritten(benchmark::State& s) {
    encode_handwritten<bw::set_motor_data_extended>(s, motor_ext_inputs, hw_encode_motor_ext);
}
void encode53_robowire(benchmark::State& s) { encode_robowire<bw::set_pid_parameters>(s, pid_inputs); }
void encode53_handwritten(benchmark::State& s) { encode_handwritten<bw::set_pid_parameters>(s, pid_inputs, hw_encode_pid); }
void encode30_careful(benchmark::State& s) { encode_handwritten<bw::set_motor_data>(s, motor_inputs, careful_encode_motor); }
void encode31_careful(benchmark::State& s) {
    encode_handwritten<bw::set_motor_data_extended>(s, motor_ext_inputs, careful_encode_motor_ext);
}
void encode53_careful(benchmark::State& s) { encode_handwritten<bw::set_pid_parameters>(s, pid_inputs, careful_encode_pid); }

// ---- decode_command over every command
// One command per 64-byte slot of one page-aligned block.
const bench::vector<std::span<const std::uint8_t>>& command_batch() {
    static bench::vector<std::array<std::uint8_t, 64>> slots(20);
    static const bench::vector<std::span<const std::uint8_t>> batch = [] {
        bench::vector<std::span<const std::uint8_t>> v;
        auto add = [&](const auto& m) {
            const auto b = robowire::encode(m).value();
            auto& slot = slots.at(v.size());
            std::copy(b.begin(), b.end(), slot.begin());
            v.emplace_back(slot.data(), b.size());
        };
        add(bw::set_device_name{"MyBrick"});
        add(bw::set_motion_wakeup{true, 300, 3600});
        add(bw::set_accel_calibration{{1, -1, 0.5f, 0.6f, -2.5f, 0}});
        add(bw::read_accel_calibration{});
        add(bw::set_motor_data{{127, -127, 0, 64, -64, 1}, 0x21, 0x3F});
        add(bw::set_motor_data_extended{{1000, -1000, 0, 0x12345678}, {-127, 100}, 3, 0});
        add(bw::set_data_period{50});
        add(bw::set_ramp_rates{{1, 2, 3, 4, 5, 6}, {0, 13, 100, 255, 7, 8}});
        add(bw::set_motor_timeout{11});
        add(bw::activate_watchdog{5});
        add(bw::set_led_status{std::array<bw::rgb, 4>{}, std::array<bw::blink, 4>{{{1, 15}, {15, 0}, {0, 8}, {5, 5}}}});
        add(bw::set_accel_lpf{bw::lpf_setting::hz_6_25});
        add(bw::set_current_limits{{50, 50, 50, 50, 100, 100}});
        add(bw::set_uart_baudrate{2, 115200});
        add(bw::set_pu_port_function{});
        add(bw::enable_pid_reporting{3});
        add(bw::set_servo_reference{{-1, 0, 90, 0x7FFFFFFF}});
        add(bw::position_servo_preset(0));
        add(bw::activate_shelf_mode{});
        add(bw::check_charger_settings{});
        return v;
    }();
    return batch;
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
        if (n != 1 && n != 13 && n != 17) return n > 17 ? hw::fail(hw::too_long, 17) : hw::fail(hw::bad_length, n);
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

void commands_robowire(benchmark::State& state) {
    const auto& batch = command_batch();
    for (auto _ : bench::measure(state)) {
        for (const auto& item : batch) {
            auto r = bw::decode_command(item);
            benchmark::DoNotOptimize(r);
        }
    }
    bench::messages(state, batch.size());
}
void commands_handwritten(benchmark::State& state) {
    const auto& batch = command_batch();
    hw_command c{};
    bench::in_memory(c);
    for (auto _ : bench::measure(state)) {
        for (const auto& item : batch) {
            bench::consume(hw_decode_command(item.data(), item.size(), c));
            benchmark::ClobberMemory();  // the escaped output is written
        }
    }
    bench::messages(state, batch.size());
}
void commands_memcpy(benchmark::State& state) {
    const auto& batch = command_batch();
    alignas(64) std::array<std::uint8_t, 64> out{};
    for (auto _ : bench::measure(state)) {
        for (const auto& item : batch) {
            std::memcpy(out.data(), item.data(), item.size());
            benchmark::DoNotOptimize(out);
        }
    }
    bench::messages(state, batch.size());
}
}  // namespace

BENCHMARK(status_decode_careful<68, false>)->Name("buwizz3.status68_decode:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_careful<68, false>)->Name("buwizz3.status68_decode_into:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_careful<68, true>)->Name("buwizz3.status68_decode_runtime_length:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_careful<68, true>)->Name("buwizz3.status68_decode_into_runtime_length:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_rw<68, true>)->Name("buwizz3.status68_decode_runtime_length:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_into_rw<68, true>)->Name("buwizz3.status68_decode_into_runtime_length:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_careful<54, false>)->Name("buwizz3.status54_decode:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_careful<54, false>)->Name("buwizz3.status54_decode_into:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_careful<54, true>)->Name("buwizz3.status54_decode_runtime_length:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_careful<54, true>)->Name("buwizz3.status54_decode_into_runtime_length:careful")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_rw<54, true>)->Name("buwizz3.status54_decode_runtime_length:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_into_rw<54, true>)->Name("buwizz3.status54_decode_into_runtime_length:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_robowire<68>)->Name("buwizz3.status68_decode:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_into<68>)->Name("buwizz3.status68_decode_into:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_handwritten<68>)->Name("buwizz3.status68_decode_into:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_handwritten<68>)->Name("buwizz3.status68_decode:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_memcpy<68>)->Name("buwizz3.status68_decode:memcpy")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_robowire<54>)->Name("buwizz3.status54_decode:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_into<54>)->Name("buwizz3.status54_decode_into:robowire")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_handwritten<54>)->Name("buwizz3.status54_decode_into:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_handwritten<54>)->Name("buwizz3.status54_decode:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(status_decode_memcpy<54>)->Name("buwizz3.status54_decode:memcpy")->Apply(bench::rounds<1>);
BENCHMARK(encode30_robowire)->Name("buwizz3.encode_0x30:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode30_handwritten)->Name("buwizz3.encode_0x30:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(encode30_careful)->Name("buwizz3.encode_0x30:careful")->Apply(bench::rounds<1>);
BENCHMARK(encode30_to)->Name("buwizz3.encode_to_0x30:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode30_handwritten)->Name("buwizz3.encode_to_0x30:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(encode30_careful)->Name("buwizz3.encode_to_0x30:careful")->Apply(bench::rounds<1>);
BENCHMARK(encode31_robowire)->Name("buwizz3.encode_0x31:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode31_handwritten)->Name("buwizz3.encode_0x31:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(encode31_careful)->Name("buwizz3.encode_0x31:careful")->Apply(bench::rounds<1>);
BENCHMARK(encode31_to)->Name("buwizz3.encode_to_0x31:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode31_handwritten)->Name("buwizz3.encode_to_0x31:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(encode31_careful)->Name("buwizz3.encode_to_0x31:careful")->Apply(bench::rounds<1>);
BENCHMARK(encode53_robowire)->Name("buwizz3.encode_0x53:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode53_handwritten)->Name("buwizz3.encode_0x53:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(encode53_careful)->Name("buwizz3.encode_0x53:careful")->Apply(bench::rounds<1>);
BENCHMARK(encode53_to)->Name("buwizz3.encode_to_0x53:robowire")->Apply(bench::rounds<1>);
BENCHMARK(encode53_handwritten)->Name("buwizz3.encode_to_0x53:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(encode53_careful)->Name("buwizz3.encode_to_0x53:careful")->Apply(bench::rounds<1>);
BENCHMARK(commands_robowire)->Name("buwizz3.decode_command_mixed:robowire")->Apply(bench::rounds<1>);
BENCHMARK(commands_handwritten)->Name("buwizz3.decode_command_mixed:handwritten")->Apply(bench::rounds<1>);
BENCHMARK(commands_memcpy)->Name("buwizz3.decode_command_mixed:memcpy")->Apply(bench::rounds<1>);
