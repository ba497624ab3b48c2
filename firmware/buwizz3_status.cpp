// BuWizz3: the status report decode alone (what an app reading telemetry links),
// with every field of the result read, so that none of the decode is left out.
#include <robowire/buwizz3/status.hpp>

#include "harness.hpp"

namespace bw = robowire::buwizz3;

ENTRY void buwizz3_decode_status(const std::uint8_t* p, std::size_t n) {
    const auto s = robowire::decode<bw::status>({p, n});
    if (s) out(std::span(reinterpret_cast<const std::uint8_t*>(&*s), sizeof(bw::status)));  // every field
    else sink = static_cast<std::uint32_t>(s.code()) | std::uint32_t{s.error().offset} << 8;  // as hw::report
}

int main() {
    const auto in = read_input<160>();
    buwizz3_decode_status(in.data(), size_in(129));
    return 0;
}
