#include <robowire/protocols.hpp>
#include <robowire/reflect.hpp>

#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

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

namespace {
template <std::size_t N>
constexpr bool has_token(std::span<const fuzz_token> dict, const std::uint8_t (&bytes)[N]) {
    for (const auto& t : dict)
        if (equal_bytes(t.view(), std::span<const std::uint8_t>(bytes, N))) return true;
    return false;
}
constexpr bool no_repeats(std::span<const fuzz_token> dict) {
    for (std::size_t i = 0; i < dict.size(); ++i)
        for (std::size_t j = i + 1; j < dict.size(); ++j)
            if (equal_bytes(dict[i].view(), dict[j].view())) return false;
    return true;
}
}  // namespace

// Directions and fuzz dictionaries, from the documents' frame layouts (typed by hand).
TEST_CASE("descriptors: message variants by direction and fuzz dictionaries", "[core][descriptor]") {
    STATIC_REQUIRE(std::is_same_v<buwizz3::messages::to_device, buwizz3::command>);
    STATIC_REQUIRE(std::is_same_v<buwizz3::messages::from_device, buwizz3::notification>);
    STATIC_REQUIRE(buwizz3::descriptor.has_directions);
    STATIC_REQUIRE(std::is_same_v<osp::messages::to_device, osp::messages::from_device>);
    STATIC_REQUIRE_FALSE(osp::descriptor.has_directions);
    STATIC_REQUIRE_FALSE(navbot::descriptor.has_directions);

    constexpr const auto& osp_dict = fuzz_dictionary_v<osp::messages>;
    constexpr const auto& buwizz3_dict = fuzz_dictionary_v<buwizz3::messages>;
    constexpr const auto& navbot_dict = fuzz_dictionary_v<navbot::messages>;
    // OSP: FF AA DEV CMD for each of the 11 messages (OBP1's requests CMD 01..04,
    // its answers 11..14) and the trailer 55 77, once each.
    STATIC_REQUIRE(osp_dict.size() == 12);
    STATIC_REQUIRE(has_token(osp_dict, {0xFF, 0xAA, 0x00, 0x01}));  // REQ_DEVICE_TYPE
    STATIC_REQUIRE(has_token(osp_dict, {0xFF, 0xAA, 0x01, 0x02}));  // ARM1 set angle
    STATIC_REQUIRE(has_token(osp_dict, {0xFF, 0xAA, 0x02, 0x14}));
    STATIC_REQUIRE(has_token(osp_dict, {0x55, 0x77}));
    STATIC_REQUIRE_FALSE(has_token(osp_dict, {0xFF, 0xAA}));  // only with DEV CMD
    STATIC_REQUIRE(no_repeats(osp_dict));

    // BuWizz3: a command byte each (0x40 with its sub-command 0x10), 0x01 the status.
    STATIC_REQUIRE(has_token(buwizz3_dict, {0x30}));  // set motor data
    STATIC_REQUIRE(has_token(buwizz3_dict, {0x40, 0x10}));
    STATIC_REQUIRE(has_token(buwizz3_dict, {0x01}));
    STATIC_REQUIRE(no_repeats(buwizz3_dict));

    // NAVBOT: 55 AA, and a maneuver's 55 AA 10 00 (command 0x10, remaining 0).
    STATIC_REQUIRE(navbot_dict.size() == 2);
    STATIC_REQUIRE(has_token(navbot_dict, {0x55, 0xAA, 0x10, 0x00}));
    STATIC_REQUIRE(has_token(navbot_dict, {0x55, 0xAA}));
}

// for_each_protocol: all_protocols' descriptors, in that order, each with its messages.
TEST_CASE("descriptors: for_each_protocol pairs each descriptor with its messages", "[core][descriptor]") {
    constexpr bool paired = [] {
        std::size_t n = 0;
        bool ok = true;
        for_each_protocol([&](auto entry) {
            using messages = typename decltype(entry)::messages;
            ok = ok && n < std::size(all_protocols) && &entry.descriptor == all_protocols[n];
            if (entry.descriptor.name == "buwizz3") ok = ok && std::is_same_v<messages, buwizz3::messages>;
            else if (entry.descriptor.name == "navbot") ok = ok && std::is_same_v<messages, navbot::messages>;
            else ok = ok && std::is_same_v<messages, osp::messages>;
            ++n;
        });
        return ok && n == 3;
    }();
    STATIC_REQUIRE(paired);
}
