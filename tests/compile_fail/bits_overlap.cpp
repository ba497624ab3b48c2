// Two bit fields in one byte whose bits overlap (bits 0-3 and 3-4).
// expect: table_fields_overlap
#include <robowire/core.hpp>

struct bad {
    std::uint8_t low{};
    std::uint8_t high{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
#ifdef ROBOWIRE_FIXED
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"low", &bad::low, 1, wire::bits<0, 4>{}},
                           field{"high", &bad::high, 1, wire::bits<4, 2>{}});
#else
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"low", &bad::low, 1, wire::bits<0, 4>{}},
                           field{"high", &bad::high, 1, wire::bits<3, 2>{}});
#endif
}
static_assert(robowire::max_size_v<bad> == 2);
