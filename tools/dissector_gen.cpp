// robowire_dissector_gen PROTOCOL|all DIR: writes the Wireshark Lua plugins
// (used by the build; `robowire dissector` does the same).
#include <cstdio>

#include "dissector.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fputs("usage: robowire_dissector_gen <buwizz3|navbot|osp|all> DIR\n", stderr);
        return 2;
    }
    return robowire::tool::write_dissectors(argv[1], argv[2], stderr);
}
