// BuWizz3 device -> host packets: decode_notification, then re-encode; a
// status's flag accessors agree with flag_bits_of(status).
#include <robowire/buwizz3.hpp>

#include "common.hpp"

FUZZ_STRUCTURE_AWARE(robowire::buwizz3::notification)

namespace {
namespace bw = robowire::buwizz3;
// The status's flag accessors read the bits that flag_bits_of(status) names
// (the layout the tools print): two statements of one layout, compared.
void check_flags(const bw::status& s) {
    const auto bit = [&](std::string_view name) -> unsigned {
        for (const auto& b : robowire::flag_bits_v<bw::status>)
            if (b.name == name) return (unsigned{s.flags} >> b.lo) & ((1u << b.width) - 1u);
        const bool named_in_flag_bits = false;
        FUZZ_CHECK(named_in_flag_bits);
        return 0;
    };
    FUZZ_CHECK(s.error() == (bit("error") != 0));
    FUZZ_CHECK(s.motion_wakeup_enabled() == (bit("motion_wakeup") != 0));
    FUZZ_CHECK(s.long_range_phy() == (bit("long_range_phy") != 0));
    FUZZ_CHECK(static_cast<unsigned>(s.battery_level()) == bit("battery"));
    FUZZ_CHECK(s.charging() == (bit("charging") != 0));
    FUZZ_CHECK(s.usb_connected() == (bit("usb_connected") != 0));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace bw = robowire::buwizz3;
    const std::span<const std::uint8_t> in(data, size);
    const auto n = bw::decode_notification(in);
    fuzz::check_text(n);
    fuzz::check_decode_into<bw::notification>(in);
    if (!n) {
        FUZZ_CHECK(n.error().offset <= size);
        return 0;
    }
    const auto wire = robowire::encode(*n);
    FUZZ_CHECK(wire.has_value());
    // A status longer than 68 bytes re-encodes to its known fields; the rest is counted.
    std::size_t trailing = 0;
    if (const auto* s = std::get_if<bw::status>(&*n)) {
        trailing = s->ignored_trailing_bytes;
        check_flags(*s);
    }
    FUZZ_CHECK(wire->size() + trailing == size);
    FUZZ_CHECK(fuzz::same_bytes(*wire, in.first(wire->size())));
    return 0;
}
