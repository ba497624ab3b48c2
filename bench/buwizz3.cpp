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
#include "handwritten/buwizz3.hpp"

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
// The careful encoders through a lambda: a type of their own, so each is
// inlined into its loop (a shared function-pointer instantiation is not, by clang++).
void encode30_careful(benchmark::State& s) {
    encode_handwritten<bw::set_motor_data>(
        s, motor_inputs, [](const auto& m, std::uint8_t* out, std::size_t size) { return careful_encode_motor(m, out, size); });
}
void encode31_careful(benchmark::State& s) {
    encode_handwritten<bw::set_motor_data_extended>(s, motor_ext_inputs, [](const auto& m, std::uint8_t* out, std::size_t size) {
        return careful_encode_motor_ext(m, out, size);
    });
}
void encode53_careful(benchmark::State& s) {
    encode_handwritten<bw::set_pid_parameters>(
        s, pid_inputs, [](const auto& m, std::uint8_t* out, std::size_t size) { return careful_encode_pid(m, out, size); });
}

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
