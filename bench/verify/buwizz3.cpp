// robowire and the hand-written baselines of bench/buwizz3.cpp, run on the same inputs:
// the same outcome, error code and offset, and output (bench/verify/run).
#include "../buwizz3.cpp"
#include "check.hpp"
#include <vector>

static void check_status(const std::uint8_t* p, std::size_t n, const std::string& ctx0, std::size_t variant) {
    const std::span<const std::uint8_t> in(p, n);
    auto r = robowire::decode<bw::status>(in);
    bw::status into{};
    const auto ei = robowire::decode_into(into, in);
    hw_status h{};
    const auto e = hw_decode_status(p, n, h);
    const std::string ctx = ctx0 + " n=" + std::to_string(n) + " variant " + std::to_string(variant);
    if (same_err("status decode", rw_err(r), e, ctx) && e == hw::good) {
        if (!same_status(h, *r)) mismatch("status decode", ctx);
    }
    if (same_err("status decode_into", ei, e, ctx) && e == hw::good) {
        if (!same_status(h, into)) mismatch("status decode_into", ctx);
    }
    bw::status sentinel{};
    sentinel.flags = 0x5A;
    sentinel.pu_motors[3].position = -7;
    sentinel.ignored_trailing_bytes = 3;
    bw::status c = sentinel;
    const auto ce = careful_decode_status(p, n, c);
    if (same_err("status decode careful", ei, ce, ctx) && !(ce == hw::good ? c == into : c == sentinel))
        mismatch("status decode careful", ctx);
}

template <class M, class Enc>
static void check_encode(const char* what, const M& m, Enc enc, const std::string& ctx) {
    constexpr std::size_t max = robowire::max_size_v<M>;
    // encode
    auto r = robowire::encode(m);
    std::array<std::uint8_t, 64> hb;
    hb.fill(0xA5);
    const auto e = enc(m, hb.data(), hb.size());
    if (same_err(what, rw_err(r), e, ctx + " encode") && e == hw::good) {
        if (r->size() != max || std::memcmp(r->data(), hb.data(), max) != 0) mismatch(what, ctx);
        for (std::size_t i = max; i < 64; ++i) if (hb[i] != 0xA5) mismatch(what, ctx + " wrote past");
    }
    if (e != hw::good)
        for (auto c : hb) if (c != 0xA5) { mismatch(what, ctx + " wrote on error"); break; }
    // encode_to, every buffer size
    for (std::size_t size = 0; size <= max + 2; ++size) {
        std::array<std::uint8_t, 64> rb, b2;
        rb.fill(0x5A);
        b2.fill(0x5A);
        auto n = robowire::encode_to(m, std::span(rb.data(), size));
        const auto e2 = enc(m, b2.data(), size);
        if (same_err((std::string(what) + " encode_to").c_str(), rw_err(n), e2, ctx + " size=" + std::to_string(size))) {
            if (rb != b2) mismatch(what, ctx + " encode_to bytes size=" + std::to_string(size));
            if (e2 == hw::good && *n != max) mismatch(what, "written size");
        }
    }
}

int main() {
    // ---- status
    bench::rng rr;
    const auto ins = status_inputs();
    for (std::size_t v = 0; v < ins.size(); ++v) {
        const auto buf = padded<131>(ins[v], rr);
        // every single-byte change at every length for variant 0; at 54, 68 and 129 for all
        sweep_lengths(
            buf, [&](std::size_t n) { return v == 0 || n == 54 || n == 68 || n == 129; },
            [&](const std::uint8_t* p, std::size_t n, const std::string& ctx) { check_status(p, n, ctx, v); });
    }
    // ---- 0x30
    const auto power_flags = [](std::size_t powers) {  // powers[0..powers), then the brake and LUT flag bytes
        return [powers](auto& m, std::size_t k, int val) {
            if (k < powers) m.power[k] = static_cast<std::int8_t>(val);
            else if (k == powers) m.brake_flags = static_cast<std::uint8_t>(val);
            else m.lut_disable_flags = static_cast<std::uint8_t>(val);
        };
    };
    const int bad30[8] = {-128, -128, -128, -128, -128, -128, 0x40, 0xFF};
    for (const auto& base : motor_inputs()) {
        check_encode("encode 0x30", base, hw_encode_motor, "bench");
        check_encode("encode 0x30 careful", base, careful_encode_motor, "bench");
        check_encode("encode 0x30 word", base, careful_encode_motor_word, "bench");
        sweep_fields(base, 8, power_flags(6), bad30, [](const bw::set_motor_data& m, const std::string& ctx) {
            check_encode("encode 0x30", m, hw_encode_motor, ctx);
        check_encode("encode 0x30 careful", m, careful_encode_motor, ctx);
        check_encode("encode 0x30 word", m, careful_encode_motor_word, ctx);
        });
    }
    // ---- 0x31
    const int bad31[4] = {-128, -128, 0x80, 0x40};
    for (const auto& base : motor_ext_inputs()) {
        check_encode("encode 0x31", base, hw_encode_motor_ext, "bench");
        check_encode("encode 0x31 careful", base, careful_encode_motor_ext, "bench");
        sweep_fields(base, 4, power_flags(2), bad31, [](const bw::set_motor_data_extended& m, const std::string& ctx) {
            check_encode("encode 0x31", m, hw_encode_motor_ext, ctx);
        check_encode("encode 0x31 careful", m, careful_encode_motor_ext, ctx);
        });
        for (std::uint32_t x : {0u, 1u, 0x80000000u, 0xFFFFFFFFu, 0x7FFFFFFFu}) {
            auto m = base;
            m.reference[x % 4] = static_cast<std::int32_t>(x);
            check_encode("encode 0x31", m, hw_encode_motor_ext, "ref");
        check_encode("encode 0x31 careful", m, careful_encode_motor_ext, "ref");
        }
    }
    // ---- 0x53
    auto set = [](bw::set_pid_parameters& m, std::size_t k, int val) {
        switch (k) {
        case 0: m.port = static_cast<std::uint8_t>(val); break;
        case 1: m.lim_out = static_cast<std::int8_t>(val); break;
        case 2: m.deadband_out = static_cast<std::int8_t>(val); break;
        case 3: m.deadband_out_boost = static_cast<std::int8_t>(val); break;
        default: m.mode = static_cast<bw::port_function>(val); break;
        }
    };
    const int bad53[5] = {4, 0, -1, -128, 0x13};
    for (const auto& base : pid_inputs()) {
        check_encode("encode 0x53", base, hw_encode_pid, "bench");
        check_encode("encode 0x53 careful", base, careful_encode_pid, "bench");
        sweep_fields(base, 5, set, bad53, [](const bw::set_pid_parameters& m, const std::string& ctx) {
            check_encode("encode 0x53", m, hw_encode_pid, ctx);
        check_encode("encode 0x53 careful", m, careful_encode_pid, ctx);
        });
        for (float f : {std::numeric_limits<float>::quiet_NaN(), -0.0f, std::numeric_limits<float>::infinity(), 1e-40f}) {
            auto m = base;
            m.kd = f;
            m.out_lp = -f;
            check_encode("encode 0x53", m, hw_encode_pid, "float");
        check_encode("encode 0x53 careful", m, careful_encode_pid, "float");
        }
    }
    return report();
}
