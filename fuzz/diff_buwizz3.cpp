// Differential: robowire's BuWizz3 codec against the hand-written one of
// bench/handwritten/buwizz3.hpp (no table shared), on decode and encode.
// First byte, modulo 4: 0 a command packet (decode_command against
// hw_decode_command), 1 a notification (status against hw_decode_status and
// careful_decode_status), 2 an encoded command made from the rest (0x30, 0x31
// or 0x53, near-valid: out-of-range fields now and then) against
// hw_encode_* and careful_encode_* with every buffer size, 3 the same message
// decoded back from robowire's bytes by the hand-written decoder. Same outcome,
// error code and offset, same decoded values or encoded bytes. The unit
// helpers of a decoded command against the document's formulas.
#include <robowire/buwizz3.hpp>
#include <robowire/ext/fuzz.hpp>

#include <array>
#include <cstring>
#include <type_traits>

#include "../bench/handwritten/buwizz3.hpp"
#include "common.hpp"

namespace {
bool same_error(robowire::error e, hw::error h) {
    return static_cast<unsigned>(e.code) == (h & 0xFFu) && (e.code == robowire::errc::ok || e.offset == h >> 8);
}
template <class T>
robowire::error error_of(const robowire::result<T>& r) {
    return r ? robowire::error{} : r.error();
}
bool same_float(float a, float b) { return std::memcmp(&a, &b, 4) == 0; }
template <std::size_t N, class A, class B>
bool same_array(const A& a, const B& b) {
    for (std::size_t i = 0; i < N; ++i)
        if (static_cast<long long>(a[i]) != static_cast<long long>(b[i])) return false;
    return true;
}

// A decoded command holds what the hand-written dispatcher read.
bool same_command(const bw::command& c, const hw_command& h) {
    return std::visit(
        [&](const auto& m) -> bool {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, bw::set_device_name>) {
                return m.name.view() == std::string_view(h.name);
            } else if constexpr (std::is_same_v<M, bw::set_motion_wakeup>) {
                return m.enabled == h.wakeup.enabled && m.idle_timeout_s == h.wakeup.idle &&
                       m.shallow_sleep_timeout_s == h.wakeup.sleep;
            } else if constexpr (std::is_same_v<M, bw::set_accel_calibration>) {
                for (std::size_t i = 0; i < 6; ++i)
                    if (!same_float(m.factors[i], h.factors[i])) return false;
                return true;
            } else if constexpr (std::is_same_v<M, bw::set_motor_data>) {
                return same_array<6>(m.power, h.motor.power) && m.brake_flags == h.motor.brake &&
                       m.lut_disable_flags == h.motor.lut;
            } else if constexpr (std::is_same_v<M, bw::set_motor_data_extended>) {
                return same_array<4>(m.reference, h.motor_ext.ref) && same_array<2>(m.power, h.motor_ext.power) &&
                       m.brake_flags == h.motor_ext.brake && m.lut_disable_flags == h.motor_ext.lut;
            } else if constexpr (std::is_same_v<M, bw::set_data_period>) {
                return m.period_ms == h.one;
            } else if constexpr (std::is_same_v<M, bw::set_ramp_rates>) {
                return same_array<6>(m.ramp_up, h.ramps) && same_array<6>(m.ramp_down, h.ramps + 6);
            } else if constexpr (std::is_same_v<M, bw::set_motor_timeout>) {
                return m.mode == h.one;
            } else if constexpr (std::is_same_v<M, bw::activate_watchdog>) {
                return m.timeout_s == h.one;
            } else if constexpr (std::is_same_v<M, bw::set_led_status>) {
                if (m.colors.has_value() != h.led.has_colors || m.blink.has_value() != h.led.has_blink) return false;
                for (std::size_t i = 0; m.colors && i < 4; ++i)
                    if ((*m.colors)[i].r != h.led.rgb[3 * i] || (*m.colors)[i].g != h.led.rgb[3 * i + 1] ||
                        (*m.colors)[i].b != h.led.rgb[3 * i + 2])
                        return false;
                for (std::size_t i = 0; m.blink && i < 4; ++i)
                    if ((*m.blink)[i].frequency_hz != h.led.blink[i].frequency || (*m.blink)[i].duty != h.led.blink[i].duty)
                        return false;
                return true;
            } else if constexpr (std::is_same_v<M, bw::set_accel_lpf>) {
                return static_cast<std::uint8_t>(m.setting) == h.one;
            } else if constexpr (std::is_same_v<M, bw::set_current_limits>) {
                return same_array<6>(m.limit_raw, h.limits);
            } else if constexpr (std::is_same_v<M, bw::set_uart_baudrate>) {
                return m.channel == h.uart.channel && m.baudrate == h.uart.baud;
            } else if constexpr (std::is_same_v<M, bw::set_pu_port_function>) {
                for (std::size_t i = 0; i < 4; ++i)
                    if (static_cast<std::uint8_t>(m.function[i]) != h.functions[i]) return false;
                return true;
            } else if constexpr (std::is_same_v<M, bw::enable_pid_reporting>) {
                return m.port == h.one;
            } else if constexpr (std::is_same_v<M, bw::set_servo_reference>) {
                return same_array<4>(m.reference, h.reference);
            } else if constexpr (std::is_same_v<M, bw::set_pid_parameters>) {
                const float f[8] = {m.out_lp, m.d_lp, m.speed_lp, m.kp, m.ki, m.kd, m.lim_i, m.reference_rate_limit};
                for (std::size_t i = 0; i < 8; ++i)
                    if (!same_float(f[i], h.pid.f[i])) return false;
                return m.port == h.pid.port && m.lim_out == h.pid.lim_out && m.deadband_out == h.pid.db &&
                       m.deadband_out_boost == h.pid.boost && static_cast<std::uint8_t>(m.mode) == h.pid.mode;
            } else {
                return true;  // no fields: 0x23, 0xA1, 0xAC
            }
        },
        c);
}
// The command byte of each alternative (its fixed byte 0), to check the kind.
std::uint8_t command_byte(const bw::command& c) {
    return robowire::encode(c).value()[0];
}

// lpf_hz: 12.5 Hz x 2^code for codes 0-3, 0.78125 Hz x 2^(code - 8) for
// 8-11 (the document's table, rounded to 3 decimals there); power in percent:
// raw x 100 / 127.
void check_units(const bw::command& c) {
    if (const auto* l = std::get_if<bw::set_accel_lpf>(&c)) {
        const unsigned code = static_cast<unsigned>(l->setting);
        const double hz = (code & 8 ? 0.78125 : 12.5) * (1u << (code & 3));
        const double got = bw::lpf_hz(l->setting);
        FUZZ_CHECK(got > hz * 0.999 && got < hz * 1.001);
    } else if (const auto* m = std::get_if<bw::set_motor_data>(&c)) {
        for (const auto p : m->power) FUZZ_CHECK(bw::percent_from_power(p) == p * 100.0 / 127.0);
    }
}

void check_command(std::span<const std::uint8_t> in) {
    const auto r = bw::decode_command(in);
    hw_command h{};
    const auto e = hw_decode_command(in.data(), in.size(), h);
    if (!same_error(error_of(r), e))
        std::fprintf(stderr, "robowire %u@%u, hand-written %u@%u\n", static_cast<unsigned>(error_of(r).code),
                     error_of(r).offset, e & 0xFFu, e >> 8u);
    FUZZ_CHECK(same_error(error_of(r), e));
    if (r) {
        FUZZ_CHECK(command_byte(*r) == h.kind);
        FUZZ_CHECK(same_command(*r, h));
        check_units(*r);
    }
}

void check_status(std::span<const std::uint8_t> in) {
    const auto r = robowire::decode<bw::status>(in);
    hw_status h{};
    const auto e = hw_decode_status(in.data(), in.size(), h);
    FUZZ_CHECK(same_error(error_of(r), e));
    if (r) FUZZ_CHECK(same_status(h, *r));
    bw::status sentinel{};
    sentinel.flags = 0x5A;
    sentinel.pu_motors[3].position = -7;
    bw::status c = sentinel;
    const auto ce = careful_decode_status(in.data(), in.size(), c);
    FUZZ_CHECK(ce == e);
    if (r) FUZZ_CHECK(same_status(h, c));
    else FUZZ_CHECK(c == sentinel);
}

// encode, encode_to with every buffer size up to the frame's plus 2: the same
// error or bytes as both hand-written encoders, nothing written past the frame.
template <class M, class Enc>
void check_encode(const M& m, Enc enc, Enc careful) {
    constexpr std::size_t max = robowire::max_size_v<M>;
    const auto r = robowire::encode(m);
    for (std::size_t size = 0; size <= max + 2; ++size) {
        std::array<std::uint8_t, 64> a, b, c;
        a.fill(0xA5);
        b.fill(0xA5);
        c.fill(0xA5);
        const auto n = robowire::encode_to(m, std::span(a.data(), size));
        const auto e = enc(m, b.data(), size);
        FUZZ_CHECK(same_error(error_of(n), e));
        FUZZ_CHECK(careful(m, c.data(), size) == e);
        FUZZ_CHECK(std::memcmp(b.data(), c.data(), 64) == 0);
        if (e == hw::good) {
            FUZZ_CHECK(*n == max && std::memcmp(a.data(), b.data(), 64) == 0);
            FUZZ_CHECK(r && r->size() == max && std::memcmp(r->data(), b.data(), max) == 0);
        }
    }
    if (!r) {  // the error of a field comes before that of the buffer: an encoder with room gives it
        std::array<std::uint8_t, 64> b{};
        FUZZ_CHECK(same_error(r.error(), enc(m, b.data(), b.size())));
    }
}

// The message encoded by robowire, decoded by the hand-written dispatcher.
template <class M>
void check_encode_decode(const M& m) {
    const auto r = robowire::encode(m);
    if (!r) return;
    hw_command h{};
    FUZZ_CHECK(hw_decode_command(r->data(), r->size(), h) == hw::good);
    FUZZ_CHECK(same_command(bw::command{m}, h));
}

template <class M>
M near_valid(robowire::fuzz::source& s) {
    return robowire::fuzz::make<M>(s, robowire::fuzz::out_of_range{32});
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::span<const std::uint8_t> in(data + 1, size - 1);
    switch (data[0] % 4) {
    case 0: check_command(in); break;
    case 1: check_status(in); break;
    case 2: {
        robowire::fuzz::source s{in.data(), in.size()};
        switch (s.byte() % 3) {
        case 0: check_encode(near_valid<bw::set_motor_data>(s), hw_encode_motor, careful_encode_motor); break;
        case 1: check_encode(near_valid<bw::set_motor_data_extended>(s), hw_encode_motor_ext, careful_encode_motor_ext); break;
        default: check_encode(near_valid<bw::set_pid_parameters>(s), hw_encode_pid, careful_encode_pid); break;
        }
        break;
    }
    default: {
        robowire::fuzz::source s{in.data(), in.size()};
        std::visit([](const auto& m) { check_encode_decode(m); },
                   robowire::fuzz::make<bw::command>(s, robowire::fuzz::out_of_range{32}));
        break;
    }
    }
    return 0;
}
