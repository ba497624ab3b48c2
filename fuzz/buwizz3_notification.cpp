// BuWizz3 device -> host packets: decode_notification, then re-encode.
#include <robowire/buwizz3.hpp>

#include "common.hpp"

FUZZ_STRUCTURE_AWARE(robowire::buwizz3::notification)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace bw = robowire::buwizz3;
    const std::span<const std::uint8_t> in(data, size);
    const auto n = bw::decode_notification(in);
    if (!n) {
        FUZZ_CHECK(n.error().offset <= size);
        return 0;
    }
    const auto wire = robowire::encode(*n);
    FUZZ_CHECK(wire.has_value());
    // A status longer than 68 bytes re-encodes to its known fields; the rest is counted.
    std::size_t trailing = 0;
    if (const auto* s = std::get_if<bw::status>(&*n)) trailing = s->ignored_trailing_bytes;
    FUZZ_CHECK(wire->size() + trailing == size);
    FUZZ_CHECK(fuzz::same_bytes(*wire, in.first(wire->size())));
    return 0;
}
