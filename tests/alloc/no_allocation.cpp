// Proves that every encoder, decoder, dispatcher, scanner, fragmenter and
// reassembler runs without allocating: global operator new/delete and malloc
// are replaced by counting versions, and the program fails if any count moves
// while robowire runs. Every message of every protocol's variant is encoded
// and decoded. Built as its own executable (see tests/CMakeLists.txt).
#include <robowire/robowire.hpp>

#include <cstdio>
#include <cstdlib>
#include <new>

#include "../each_message.hpp"

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
// fn(v) for every alternative of the protocol's variant, default-constructed and filled.
template <class Variant, class Fn>
void each(Fn&& fn) {
    robowire::for_each_alternative<Variant>([&](auto t) {
        using M = typename decltype(t)::type;
        fn(Variant{std::in_place_type<M>, M{}});
        fn(Variant{std::in_place_type<M>, test::filled<M>()});
    });
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
        each<bw::command>([](const bw::command& m) {
            const auto wire = robowire::encode(m).value();
            use(wire);
            const auto back = bw::decode_command(wire);
            sink = static_cast<std::uint8_t>(back.has_value());
        });
        const std::uint8_t bad[] = {0x30, 0x80};
        sink = static_cast<std::uint8_t>(bw::decode_command(bad).code());
    });
    no_alloc("buwizz3 notifications", [] {
        each<bw::notification>([](const bw::notification& m) {
            const auto wire = robowire::encode(m).value();
            use(wire);
            sink = static_cast<std::uint8_t>(bw::decode_notification(wire).has_value());
        });
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
        each<nb::message>([](const nb::message& msg) {
            const auto wire = robowire::encode(msg).value();
            use(wire);
            sink = static_cast<std::uint8_t>(nb::decode_frame(wire).has_value());
        });
        nb::reassembler<60> r;
        for (const auto& f : nb::json_frames(R"({"type":"get_device_info"})").value()) sink = static_cast<std::uint8_t>(r.push(f).has_value());
        sink = static_cast<std::uint8_t>(r.text().size());
        const std::uint8_t adv[] = {0x05, 0x09, 'n', 'a', 'v', 'b'};
        sink = static_cast<std::uint8_t>(nb::matches_advertisement(adv));
    });
    no_alloc("osp", [] {
        osp::scanner sc;
        each<osp::message>([&sc](const osp::message& m) {
            const auto wire = osp::encode(m).value();
            sc.feed(wire, [](osp::scanner::frame_bytes f) { sink = static_cast<std::uint8_t>(osp::decode(f).has_value()); });
            for (auto byte : wire) sink = static_cast<std::uint8_t>(sc.push(byte).has_value());
        });
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
