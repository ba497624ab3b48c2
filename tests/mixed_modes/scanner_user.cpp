// Built at -O2 by symbols.py (see scanner_caller.cpp).
#include <robowire/osp.hpp>

void on_uart(robowire::osp::scanner& s) {
    const std::uint8_t b[1] = {0xFF};
    s.feed(b, [](robowire::osp::scanner::frame_bytes) {});
}
