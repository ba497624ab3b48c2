// A u8 at offset 2 over the high byte of a u16 at offset 1.
// expect: table_fields_overlap
#include <robowire/core.hpp>

struct bad {
    std::uint16_t a{};
    std::uint8_t b{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
#ifdef ROBOWIRE_FIXED
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 1, wire::u16le{}},
                           field{"b", &bad::b, 3, wire::u8{}});
#else
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 1, wire::u16le{}},
                           field{"b", &bad::b, 2, wire::u8{}});
#endif
}
static_assert(robowire::max_size_v<bad> == 4);
