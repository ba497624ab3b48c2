// One program from a file built with -Os and one built with -O2, both using
// the same codecs (codecs.hpp): each file must get the code of its own size
// settings (robowire's inline namespace per setting, core/config.hpp), and
// both must decode and encode right. With one definition under one name, the
// linker would keep either file's copy for both: the addresses would match.
#include <array>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

namespace size_file {
int mode();
int failures();
std::array<std::uintptr_t, 3> codec_addresses();
std::string outcome(int which, std::span<const std::uint8_t> in);
}  // namespace size_file
namespace speed_file {
int mode();
int failures();
std::array<std::uintptr_t, 3> codec_addresses();
std::string outcome(int which, std::span<const std::uint8_t> in);
}  // namespace speed_file

// Random inputs that reach every check: a message's first bytes mostly right,
// small byte values (in most ranges), lengths around each message's.
struct inputs {
    std::uint32_t state = 12345;
    std::uint32_t next() {  // xorshift32
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return state;
    }
    std::vector<std::uint8_t> make(int which) {
        static constexpr std::uint8_t commands[] = {0x20, 0x21, 0x22, 0x23, 0x30, 0x31, 0x32, 0x33, 0x34, 0x35, 0x36,
                                                    0x37, 0x38, 0x40, 0x50, 0x51, 0x52, 0x53, 0xA1, 0xAC, 0x01, 0x55};
        const bool navbot = which >= 4 && which <= 6, status = which == 2 || which == 3;
        std::size_t n = next() % 70;
        if (next() % 3 != 0) n = navbot ? 20 : which == 7 ? 10 : status ? 50 + next() % 84 : n;
        std::vector<std::uint8_t> b(n);
        for (auto& x : b) x = static_cast<std::uint8_t>(next() % 3 != 0 ? next() % 6 : next());
        if (n == 0) return b;
        b[0] = which <= 1 ? commands[next() % sizeof commands] : status ? 0x01 : which == 7 ? 0xFF : 0x55;
        if (n > 1 && (navbot || which == 7)) b[1] = 0xAA;
        if (n > 2 && navbot && next() % 4 != 0) b[2] = 0x10;
        if (n > 3 && navbot && next() % 4 != 0) b[3] = 0;
        if (n > 9 && which == 7) b[8] = 0x55, b[9] = 0x77;
        if (n > 1 && b[0] == 0x40 && next() % 2 != 0) b[1] = 0x10;
        if (next() % 8 == 0) b[next() % n] = static_cast<std::uint8_t>(next());
        return b;
    }
};

int main() {
    int status = 0;
    const auto check = [&](bool ok, const char* what) {
        std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
        if (!ok) status = 1;
    };
    check(size_file::mode() == 11, "size.cpp built with ROBOWIRE_OPTIMIZE_SIZE 1, ROBOWIRE_ARRAY_LOOPS 1 (-Os)");
    check(speed_file::mode() == 0, "speed.cpp built with ROBOWIRE_OPTIMIZE_SIZE 0, ROBOWIRE_ARRAY_LOOPS 0 (-O2)");
    check(size_file::failures() == 0, "size.cpp decodes and encodes right");
    check(speed_file::failures() == 0, "speed.cpp decodes and encodes right");
    const auto a = size_file::codec_addresses(), b = speed_file::codec_addresses();
    const char* names[] = {"decode<buwizz3::status>", "encode<buwizz3::status>", "osp::decode<osp::message>"};
    for (std::size_t i = 0; i < a.size(); ++i) {
        char what[120];
        std::snprintf(what, sizeof what, "%s: one copy per file", names[i]);
        check(a[i] != b[i], what);
    }
    // Both files agree on every input: the same errors (code and offset), the
    // same values (as the bytes they encode to), decode_into's object kept on an error.
    inputs gen;
    long differ = 0, decoded = 0;
    constexpr long per_codec = 40000;
    for (long k = 0; k < 9 * per_codec; ++k) {
        const int which = static_cast<int>(k % 9);
        const auto in = gen.make(which);
        const std::string x = size_file::outcome(which, in), y = speed_file::outcome(which, in);
        if (x != y && differ++ < 5) std::printf("codec %d, %zu bytes: size file and speed file differ\n", which, in.size());
        if (x == y && x[0] != 'E') ++decoded;
        if (x.find("changed") != std::string::npos && differ++ < 5) std::printf("codec %d: decode_into changed the object\n", which);
    }
    char what[120];
    std::snprintf(what, sizeof what, "size and speed files agree on %ld inputs (%ld decoded)", 9 * per_codec, decoded);
    check(differ == 0, what);
    return status;
}
