// BuWizz3 encode (its own translation unit: the 23 messages' encoders compile in parallel with the decoders).
#include "describe.hpp"

namespace robowire::tools {

outcome buwizz3_encode(std::string_view message, const std::vector<std::pair<std::string, std::string>>& values) {
    namespace bw = robowire::buwizz3;
    if (auto o = encode_in<bw::messages::to_device>(message, values)) return *o;
    if (auto o = encode_in<bw::messages::from_device>(message, values)) return *o;
    return failure(exit_usage, "unknown message " + shorten(message) + " (robowire list buwizz3)");
}

}  // namespace robowire::tools
