// Built at -Os by symbols.py: calls a function of scanner_user.cpp, built at
// -O2, with an osp::scanner, a type per size setting. The link must fail.
#include <robowire/osp.hpp>

void on_uart(robowire::osp::scanner& s);

int main() {
    robowire::osp::scanner s;
    on_uart(s);
    return static_cast<int>(s.frames());
}
