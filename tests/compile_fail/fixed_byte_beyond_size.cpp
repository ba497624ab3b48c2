// A fixed byte past the message's declared size.
// expect: table_fixed_byte_beyond_message_size
#include <robowire/core.hpp>

struct bad {
    std::uint8_t a{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
    auto t = make_table<bad>("bad", {{0, 0x30, errc::bad_command}, {5, 0x55, errc::bad_trailer}},
                             field{"a", &bad::a, 1, wire::u8{}});
#ifdef ROBOWIRE_FIXED
    t.declared_size = 6;
#else
    t.declared_size = 5;
#endif
    return t;
}
static_assert(robowire::max_size_v<bad> >= 5);
