// A field past the message's declared size.
// expect: table_field_beyond_message_size
#include <robowire/core.hpp>

struct bad {
    std::uint16_t a{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
    auto t = make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 3, wire::u16le{}});
#ifdef ROBOWIRE_FIXED
    t.declared_size = 5;
#else
    t.declared_size = 4;
#endif
    return t;
}
static_assert(robowire::max_size_v<bad> >= 4);
