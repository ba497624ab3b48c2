// A message longer than 65535 bytes (error offsets are 16 bits).
// expect: table_message_longer_than_65535_bytes
#include <robowire/core.hpp>

struct bad {
    std::uint8_t a{};
};
constexpr auto table_of(std::type_identity<bad>) {
    using namespace robowire;
#ifdef ROBOWIRE_FIXED
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 65534, wire::u8{}});  // ends at 65535
#else
    return make_table<bad>("bad", {{0, 0x30, errc::bad_command}}, field{"a", &bad::a, 65535, wire::u8{}});  // ends at 65536
#endif
}
static_assert(robowire::max_size_v<bad> >= 1);
