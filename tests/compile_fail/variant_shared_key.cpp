// Two alternatives of a variant with the same key byte: the second could never be decoded.
// expect: variant_alternatives_share_a_key
#include <robowire/core.hpp>

#include <variant>

struct ping {
    std::uint8_t seq{};
};
struct pong {
    std::uint8_t seq{};
};
constexpr auto table_of(std::type_identity<ping>) {
    using namespace robowire;
    return make_table<ping>("ping", {{0, 0x01, errc::bad_command}}, field{"seq", &ping::seq, 1, wire::u8{}});
}
constexpr auto table_of(std::type_identity<pong>) {
    using namespace robowire;
#ifdef ROBOWIRE_FIXED
    return make_table<pong>("pong", {{0, 0x02, errc::bad_command}}, field{"seq", &pong::seq, 1, wire::u8{}});
#else
    return make_table<pong>("pong", {{0, 0x01, errc::bad_command}}, field{"seq", &pong::seq, 1, wire::u8{}});
#endif
}
constexpr std::uint8_t in[] = {0x01, 0x07};
static_assert(robowire::decode_variant<std::variant<ping, pong>>(in).has_value());
