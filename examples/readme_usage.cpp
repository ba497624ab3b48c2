// The usage example shown in README.md (kept in sync by tests/readme_example.sh).
#include <robowire/osp.hpp>
#include <cstdio>

int main() {
    namespace osp = robowire::osp;
    auto frame = robowire::encode(osp::obp1::status{osp::obp1::state::charging, 0}).value();  // 10 bytes
    auto msg = osp::decode(frame);  // std::variant of every OSP message, or an error + offset
    if (!msg) {
        const std::string_view what = robowire::to_string(msg.code());
        std::printf("error: %.*s at byte %u\n", static_cast<int>(what.size()), what.data(),
                    static_cast<unsigned>(msg.error().offset));
        return 1;
    }
    if (auto* s = std::get_if<osp::obp1::status>(&*msg)) std::printf("state %d\n", static_cast<int>(s->state));
    static_assert(robowire::decode<osp::obp1::soc>(robowire::encode(osp::obp1::soc{65535}).value())->soc_raw == 65535);
}
