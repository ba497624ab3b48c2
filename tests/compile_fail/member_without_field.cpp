// A struct member that no field covers (it would never be encoded).
// expect: table_leaves_struct_members_without_field
#include <robowire/core.hpp>

struct bad {
    std::uint8_t speed{};
    std::uint8_t forgotten{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
    auto t = make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"speed", &bad::speed, 1, wire::u8{}});
#ifdef ROBOWIRE_FIXED
    t.members_not_on_wire = 1;  // forgotten: declared as not on the wire
#endif
    return t;
}
static_assert(robowire::max_size_v<bad> == 2);
