// Uses robowire as an installed package would be used.
#include <robowire/robowire.hpp>

#include <cstdio>

int main() {
    namespace osp = robowire::osp;
    const auto frame = robowire::encode(osp::obp1::voltage{1234}).value();
    const auto back = robowire::decode<osp::obp1::voltage>(frame);
    if (!back || back->centivolts != 1234) return 1;
    std::puts("consumer: ok");
    return 0;
}
