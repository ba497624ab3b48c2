// Structure-aware: OSP messages made from the input (robowire::fuzz::make),
// encoded (by osp::encode too), decoded back. First byte: bit 6 the near-valid form (a field out
// of range now and then), and modulo the number of messages, which one.
#include <robowire/ext/fuzz.hpp>
#include <robowire/osp.hpp>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace osp = robowire::osp;
    const bool near_valid = size > 0 && (data[0] & 0x40) != 0;
    robowire::fuzz::source s{data, size};
    const auto m = near_valid ? robowire::fuzz::make<osp::message>(s, robowire::fuzz::out_of_range{})
                              : robowire::fuzz::make<osp::message>(s);
    if (!near_valid) FUZZ_CHECK(robowire::encode(m).has_value());  // make draws inside every range
    // osp::encode (one frame writer for every message) agrees with robowire::encode.
    const auto generic = robowire::encode(m), own = osp::encode(m);
    fuzz::check_text(own);
    FUZZ_CHECK(own.has_value() == generic.has_value());
    if (own) FUZZ_CHECK(fuzz::same_bytes(*own, *generic));
    else FUZZ_CHECK(own.error() == generic.error());
    fuzz::round_trip<fuzz::floats::none>(m, [](auto in) { return osp::decode(in); });
    return 0;
}
