// Fields listed out of offset order.
// expect: table_fields_out_of_offset_order
#include <robowire/core.hpp>

struct bad {
    std::uint8_t a{};
    std::uint8_t b{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
#ifdef ROBOWIRE_FIXED
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 1, wire::u8{}},
                           field{"b", &bad::b, 2, wire::u8{}});
#else
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 2, wire::u8{}},
                           field{"b", &bad::b, 1, wire::u8{}});
#endif
}
static_assert(robowire::max_size_v<bad> == 3);
