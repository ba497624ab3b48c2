// Structure-aware: BuWizz3 messages made from the input (robowire::fuzz::make),
// encoded, decoded back. First byte: bit 7 notification/command, bit 6 the
// near-valid form (a field out of range now and then), and modulo the
// number of messages, which one.
#include <robowire/buwizz3.hpp>
#include <robowire/ext/fuzz.hpp>

#include "common.hpp"

namespace {
template <class Variant, class Decode>
void one(const std::uint8_t* data, std::size_t size, bool near_valid, Decode&& decode) {
    robowire::fuzz::source s{data, size};
    if (near_valid) {
        fuzz::round_trip(robowire::fuzz::make<Variant>(s, robowire::fuzz::out_of_range{}), decode);
    } else {
        const auto m = robowire::fuzz::make<Variant>(s);
        FUZZ_CHECK(robowire::encode(m).has_value());  // make draws inside every range
        fuzz::round_trip(m, decode);
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace bw = robowire::buwizz3;
    const std::uint8_t which = size > 0 ? data[0] : 0;
    if (which & 0x80) one<bw::notification>(data, size, which & 0x40, [](auto in) { return bw::decode_notification(in); });
    else one<bw::command>(data, size, which & 0x40, [](auto in) { return bw::decode_command(in); });
    return 0;
}
