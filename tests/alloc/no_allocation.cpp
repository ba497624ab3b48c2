// Proves that every encoder, decoder, dispatcher, scanner, fragmenter and
// reassembler runs without allocating: global operator new/delete and malloc
// are replaced by counting versions, and the program fails if any count moves
// while robowire runs. Built as its own executable (see tests/CMakeLists.txt).
#include <robowire/robowire.hpp>

#include <cstdio>
#include <cstdlib>
#include <new>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"  // replacement operators on malloc/free, on purpose
#endif

namespace {
// volatile: compilers treat malloc as touching no user globals and would keep a stale copy
volatile std::size_t allocations = 0;
void count() { allocations = allocations + 1; }
}

void* operator new(std::size_t n) {
    count();
    if (void* p = std::malloc(n ? n : 1)) return p;
    std::abort();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { count(); return std::malloc(n ? n : 1); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { count(); return std::malloc(n ? n : 1); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

// malloc itself: counted through the linker's --wrap=malloc (set in CMake).
extern "C" void* __real_malloc(std::size_t);
extern "C" void* __wrap_malloc(std::size_t n) {
    count();
    return __real_malloc(n);
}

namespace {
int failures = 0;
template <class F>
void no_alloc(const char* what, F&& f) {
    const std::size_t before = allocations;
    f();
    if (allocations != before) {
        std::printf("ALLOCATES: %s (%zu)\n", what, allocations - before);
        ++failures;
    }
}
volatile std::uint8_t sink;
void use(std::span<const std::uint8_t> b) {
    for (auto x : b) sink = x;
}
}  // namespace

int main() {
    namespace bw = robowire::buwizz3;
    namespace nb = robowire::navbot;
    namespace osp = robowire::osp;
    // a control: the counter works
    // (through a volatile pointer: optimizers may elide a new/delete pair that does not escape)
    const std::size_t before = allocations;
    static int* volatile escape = nullptr;
    escape = new int(1);
    delete escape;
    if (allocations == before) {
        std::puts("allocation counter does not count");
        return 1;
    }

    no_alloc("buwizz3 commands", [] {
        const bw::command all[] = {bw::set_device_name{"BW"}, bw::set_motion_wakeup{true, 300, 0},
                                   bw::set_accel_calibration{}, bw::read_accel_calibration{},
                                   bw::set_motor_data{{1, 2, 3, 4, 5, 6}, 1, 2}, bw::set_motor_data_extended{},
                                   bw::set_data_period{20}, bw::set_ramp_rates{}, bw::set_motor_timeout{},
                                   bw::activate_watchdog{}, bw::set_led_status{std::array<bw::rgb, 4>{}, std::array<bw::blink, 4>{}},
                                   bw::set_accel_lpf{}, bw::set_current_limits{}, bw::set_uart_baudrate{},
                                   bw::set_pu_port_function{}, bw::enable_pid_reporting{}, bw::set_servo_reference{},
                                   bw::position_servo_preset(1), bw::activate_shelf_mode{}, bw::check_charger_settings{}};
        for (const auto& m : all) {
            const auto wire = robowire::encode(m).value();
            use(wire);
            const auto back = bw::decode_command(wire);
            sink = static_cast<std::uint8_t>(back.has_value());
        }
        const std::uint8_t bad[] = {0x30, 0x80};
        sink = static_cast<std::uint8_t>(bw::decode_command(bad).code());
    });
    no_alloc("buwizz3 notifications", [] {
        bw::status s{};
        s.pid_state = bw::pid_state{1, 2, 3, 4, 5};
        const auto wire = robowire::encode(s).value();
        sink = static_cast<std::uint8_t>(bw::decode_notification(wire).has_value());
        const auto cs = robowire::encode(bw::charger_settings{{1, 2, 3}}).value();
        sink = static_cast<std::uint8_t>(bw::decode_notification(cs).has_value());
        const std::uint8_t adv[] = {0x02, 0x01, 0x06, 0x09, 0xFF, 0x4E, 0x05, 0x42, 0x57, 0x03, 0x22, 0x34, 0x12};
        sink = static_cast<std::uint8_t>(bw::parse_advertisement(adv).has_value());
        sink = static_cast<std::uint8_t>(bw::k_lp_from_cutoff(10).has_value() + bw::ramp_rate_from_seconds(1).value());
    });
    no_alloc("navbot", [] {
        nb::maneuver m{};
        m.pitch = -10;
        const auto a = nb::encode(m).value();
        const auto b = nb::encode(m, nb::sign_encoding::sign_magnitude).value();
        sink = static_cast<std::uint8_t>(nb::decode_maneuver(a).has_value() + nb::decode_maneuver(b, nb::sign_encoding::sign_magnitude).has_value());
        sink = static_cast<std::uint8_t>(nb::decode_frame(a).has_value());
        nb::reassembler<60> r;
        for (const auto& f : nb::json_frames(R"({"type":"get_device_info"})").value()) sink = static_cast<std::uint8_t>(r.push(f).has_value());
        sink = static_cast<std::uint8_t>(r.text().size());
        const std::uint8_t adv[] = {0x05, 0x09, 'n', 'a', 'v', 'b'};
        sink = static_cast<std::uint8_t>(nb::matches_advertisement(adv));
    });
    no_alloc("osp", [] {
        const osp::message all[] = {osp::generic::request_device_type{}, osp::generic::device_type{osp::device_type::obp1},
                                    osp::arm1::set_angle{1, 2}, osp::obp1::request_soc{}, osp::obp1::soc{1},
                                    osp::obp1::voltage{2}, osp::obp1::current{3}, osp::obp1::status{}};
        osp::scanner sc;
        for (const auto& m : all) {
            const auto wire = osp::encode(m).value();
            sc.feed(wire, [](osp::scanner::frame_bytes f) { sink = static_cast<std::uint8_t>(osp::decode(f).has_value()); });
            for (auto byte : wire) sink = static_cast<std::uint8_t>(sc.push(byte).has_value());
        }
        struct battery {
            osp::obp1::soc operator()(const osp::obp1::request_soc&) const { return {100}; }
        };
        const auto req = robowire::encode(osp::obp1::request_soc{}).value();
        sink = static_cast<std::uint8_t>(osp::serve(req, battery{}).has_value());
    });
    no_alloc("core", [] {
        char text[64];
        const std::uint8_t b[] = {1, 2, 3};
        sink = static_cast<std::uint8_t>(robowire::to_hex(b, text).value());
        sink = static_cast<std::uint8_t>(robowire::parse_hex<8>("01 02").value().size());
        sink = static_cast<std::uint8_t>(robowire::uuid128::parse("6e400011-b5a3-f393-e0a9-e50e24dcca9e").has_value());
    });
    if (failures) return 1;
    std::puts("no allocation in any codec path");
    return 0;
}
