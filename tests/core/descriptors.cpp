#include <robowire/protocols.hpp>

#include <catch2/catch.hpp>
#include <string_view>

using namespace robowire;

namespace {
constexpr bool chars_are(const uuid128& u, std::string_view s) {
    const auto c = u.to_chars();
    return std::string_view(c.data(), c.size()) == s;
}
}  // namespace

// UUIDs as printed in specs/buwizz3.md and specs/navbot.md (typed by hand).
TEST_CASE("descriptors: names, characteristics and stream kinds", "[core][descriptor]") {
    STATIC_REQUIRE(std::size(all_protocols) == 3);
    STATIC_REQUIRE(find_descriptor("buwizz3") == &buwizz3::descriptor);
    STATIC_REQUIRE(find_descriptor("navbot") == &navbot::descriptor);
    STATIC_REQUIRE(find_descriptor("osp") == &osp::descriptor);
    STATIC_REQUIRE(find_descriptor("OSP") == nullptr);

    STATIC_REQUIRE(osp::descriptor.characteristics.empty());
    STATIC_REQUIRE(osp::descriptor.stream == stream_kind::scanner);
    STATIC_REQUIRE(navbot::descriptor.stream == stream_kind::reassembler);
    STATIC_REQUIRE(buwizz3::descriptor.stream == stream_kind::none);

    STATIC_REQUIRE(buwizz3::descriptor.characteristics.size() == 1);
    STATIC_REQUIRE(chars_are(buwizz3::descriptor.characteristics[0].uuid, "50052901-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(buwizz3::descriptor.characteristics[0].carries == gatt_direction::both);

    STATIC_REQUIRE(navbot::descriptor.characteristics.size() == 2);
    STATIC_REQUIRE(chars_are(navbot::descriptor.characteristics[0].uuid, "6e400012-b5a3-f393-e0a9-e50e24dcca9e"));
    STATIC_REQUIRE(navbot::descriptor.characteristics[0].carries == gatt_direction::to_device);
    STATIC_REQUIRE(chars_are(navbot::descriptor.characteristics[1].uuid, "6e400013-b5a3-f393-e0a9-e50e24dcca9e"));
    STATIC_REQUIRE(navbot::descriptor.characteristics[1].carries == gatt_direction::from_device);

    // find(): a UUID another protocol owns, or the service's, is not a characteristic.
    STATIC_REQUIRE(navbot::descriptor.find(uuid_literal("6e400013-b5a3-f393-e0a9-e50e24dcca9e")) ==
                   &navbot::descriptor.characteristics[1]);
    STATIC_REQUIRE(navbot::descriptor.find(uuid_literal("6e400011-b5a3-f393-e0a9-e50e24dcca9e")) == nullptr);
    STATIC_REQUIRE(buwizz3::descriptor.find(navbot::write_uuid) == nullptr);
}
