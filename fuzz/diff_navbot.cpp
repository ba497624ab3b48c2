// Differential: robowire's NAVBOT maneuver codec against the hand-written
// ones of bench/handwritten/navbot.hpp (no table shared). First byte, bit 0:
// 0 a frame, decoded by robowire (decode<maneuver> and decode_frame) and by
// hw_decode and careful_decode: the same outcome, error code and offset and
// fields; 1 a maneuver made from the rest (near-valid: fields out of range
// now and then), encoded by robowire, hw_encode and careful_encode: the same
// error or the same bytes.
#include <robowire/ext/fuzz.hpp>
#include <robowire/navbot.hpp>

#include <array>
#include <cstring>

#include "../bench/handwritten/navbot.hpp"
#include "common.hpp"

namespace {
bool same_error(robowire::error e, hw::error h) {
    return static_cast<unsigned>(e.code) == (h & 0xFFu) && (e.code == robowire::errc::ok || e.offset == h >> 8);
}

void check_frame(std::span<const std::uint8_t> in) {
    const auto r = robowire::decode<nb::maneuver>(in);
    nb::maneuver h{};
    const auto e = hw_decode(in.data(), in.size(), h);
    FUZZ_CHECK(same_error(r ? robowire::error{} : r.error(), e));
    const nb::maneuver sentinel{1, 2, 3, 4, nb::switch_a{1}, nb::switch_b{1}, nb::switch_c{1}, nb::switch_d{1}, 5, -5};
    nb::maneuver c = sentinel;
    FUZZ_CHECK(careful_decode(in.data(), in.size(), c) == e);
    if (r) {
        FUZZ_CHECK(h == *r && c == *r);
        const auto f = nb::decode_frame(in);  // the dispatcher gives the same maneuver
        FUZZ_CHECK(f && std::holds_alternative<nb::maneuver>(*f) && std::get<nb::maneuver>(*f) == *r);
    } else {
        FUZZ_CHECK(c == sentinel);
    }
}

void check_encode(const nb::maneuver& m) {
    const auto r = robowire::encode(m);
    std::array<std::uint8_t, 32> a, b;
    a.fill(0xA5);
    b.fill(0xA5);
    const auto e = hw_encode(m, a.data());
    FUZZ_CHECK(same_error(r ? robowire::error{} : r.error(), e));
    FUZZ_CHECK(careful_encode(m, b.data()) == e);
    if (e == hw::good) {
        FUZZ_CHECK(r->size() == 20 && std::memcmp(r->data(), a.data(), 20) == 0);
        FUZZ_CHECK(a == b);
        const auto n = nb::encode(m);  // the protocol's own encoder: the same frame
        FUZZ_CHECK(n && std::memcmp(n->data(), a.data(), 20) == 0);
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    if (data[0] & 1) {
        robowire::fuzz::source s{data + 1, size - 1};
        check_encode(robowire::fuzz::make<nb::maneuver>(s, robowire::fuzz::out_of_range{32}));
    } else {
        check_frame({data + 1, size - 1});
    }
    return 0;
}
