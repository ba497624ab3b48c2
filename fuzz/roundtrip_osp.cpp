// Structure-aware: OSP messages built from the input, encoded, decoded back.
#include <robowire/osp.hpp>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace osp = robowire::osp;
    fuzz::reader r{{data, size}};
    const auto m = fuzz::pick<osp::message>(r.byte() % std::variant_size_v<osp::message>, r);
    fuzz::round_trip(m, [](auto in) { return osp::decode(in); });
    return 0;
}
