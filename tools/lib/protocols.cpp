// The tool's protocols, in `list` order: the one place a new protocol's
// tools/<protocol>.cpp is named.
#include "tools.hpp"

namespace robowire::tools {

std::span<const protocol* const> protocols() {
    static const protocol* const all[] = {&buwizz3_protocol(), &navbot_protocol(), &osp_protocol()};
    return all;
}
const protocol* find_protocol(std::string_view name) {
    for (const protocol* p : protocols())
        if (p->name == name) return p;
    return nullptr;
}
std::string protocol_names() {
    std::string out;
    const auto all = protocols();
    for (std::size_t i = 0; i < all.size(); ++i)
        out += std::string(i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + std::string(all[i]->name);
    return out;
}

}  // namespace robowire::tools
