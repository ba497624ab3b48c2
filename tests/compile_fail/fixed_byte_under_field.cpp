// A fixed byte (the command) under a field.
// expect: table_fixed_byte_under_field
#include <robowire/core.hpp>

struct bad {
    std::uint16_t a{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
#ifdef ROBOWIRE_FIXED
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 1, wire::u16le{}});
#else
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 0, wire::u16le{}});
#endif
}
static_assert(robowire::max_size_v<bad> >= 2);
