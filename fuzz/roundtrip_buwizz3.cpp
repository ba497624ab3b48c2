// Structure-aware: BuWizz3 messages built from the input, encoded, decoded back.
#include <robowire/buwizz3.hpp>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace bw = robowire::buwizz3;
    fuzz::reader r{{data, size}};
    const std::size_t which = r.byte();
    if (which & 0x80) {
        const auto m = fuzz::pick<bw::notification>(which % std::variant_size_v<bw::notification>, r);
        fuzz::round_trip(m, [](auto in) { return bw::decode_notification(in); });
    } else {
        const auto m = fuzz::pick<bw::command>(which % std::variant_size_v<bw::command>, r);
        fuzz::round_trip(m, [](auto in) { return bw::decode_command(in); });
    }
    return 0;
}
