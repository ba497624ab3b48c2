// One program from a file built with -Os and one built with -O2, both using
// the same codecs (codecs.hpp): each file must get the code of its own size
// settings (robowire's inline namespace per setting, core/config.hpp), and
// both must decode and encode right. With one definition under one name, the
// linker would keep either file's copy for both: the addresses would match.
#include <array>
#include <cstdint>
#include <cstdio>

namespace size_file {
int mode();
int failures();
std::array<std::uintptr_t, 3> codec_addresses();
}  // namespace size_file
namespace speed_file {
int mode();
int failures();
std::array<std::uintptr_t, 3> codec_addresses();
}  // namespace speed_file

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
    return status;
}
