#include <robowire/buwizz3/advertisement.hpp>
#include <robowire/buwizz3/uuids.hpp>

#include <catch2/catch.hpp>

#include "check.hpp"

using namespace robowire;
using namespace robowire::buwizz3;

namespace {
constexpr bool chars_are(const uuid128& u, std::string_view s) {
    const auto c = u.to_chars();
    return std::string_view(c.data(), c.size()) == s;
}
// flags; complete local name "BuWizz3" (7 chars, length 8); manufacturer data 4E 05 'B' 'W' 03 22 serial 0x1234
constexpr auto app_adv = test::hex("02 01 06 08 09 42 75 57 69 7A 7A 33 09 FF 4E 05 42 57 03 22 34 12");
// scan response: incomplete list of 128-bit UUIDs (0x06), the service on-air
constexpr auto scan = test::hex("11 06 93 6E 67 B1 19 99 B3 88 81 44 FB 74 D1 92 05 50");
constexpr auto boot_adv = test::hex("02 01 06 09 FF 4E 05 42 57 42 4C 00 00");
}  // namespace

TEST_CASE("buwizz3: UUIDs", "[buwizz3][uuid]") {
    STATIC_REQUIRE(service_uuid.on_air() == std::array<std::uint8_t, 16>{0x93, 0x6E, 0x67, 0xB1, 0x19, 0x99, 0xB3, 0x88,
                                                                         0x81, 0x44, 0xFB, 0x74, 0xD1, 0x92, 0x05, 0x50});
    STATIC_REQUIRE(chars_are(service_uuid, "500592d1-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(chars_are(application_uuid, "50052901-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(chars_are(bootloader_uuid, "50058000-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(chars_are(uart_characteristic(1).value(), "50053901-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(chars_are(uart_characteristic(4).value(), "50053904-74fb-4481-88b3-9919b1676e93"));
    STATIC_REQUIRE(uart_characteristic(0).code() == errc::value_out_of_range);
    STATIC_REQUIRE(uart_characteristic(5).code() == errc::value_out_of_range);
    STATIC_REQUIRE((application_uuid.on_air()[12] == 0x01 && application_uuid.on_air()[13] == 0x29));
}

TEST_CASE("buwizz3: advertising in application mode", "[buwizz3][advertising]") {
    constexpr auto a = parse_advertisement(app_adv, scan).value();
    STATIC_REQUIRE(a.has_value());
    STATIC_REQUIRE(a->mode == device_mode::application);
    STATIC_REQUIRE(a->firmware_version == std::array<std::uint8_t, 2>{0x03, 0x22});
    STATIC_REQUIRE(a->serial_low16 == 0x1234);
    STATIC_REQUIRE(a->has_manufacturer_data);
    STATIC_REQUIRE(a->has_service_uuid);
    STATIC_REQUIRE(a->local_name.value() == "BuWizz3");
    const auto r = parse_advertisement(app_adv);
    REQUIRE(r);
    REQUIRE(r->has_value());
    CHECK_FALSE((*r)->has_service_uuid);
    CHECK((*r)->serial_low16 == 0x1234);
}

TEST_CASE("buwizz3: advertising in bootloader mode, by service UUID only, and not a BuWizz3", "[buwizz3][advertising]") {
    constexpr auto b = parse_advertisement(boot_adv).value();
    STATIC_REQUIRE(b->mode == device_mode::bootloader);
    STATIC_REQUIRE(b->serial_low16 == 0);
    STATIC_REQUIRE(b->firmware_version == std::array<std::uint8_t, 2>{0, 0});
    STATIC_REQUIRE(!b->local_name.has_value());
    constexpr auto only_uuid = parse_advertisement(test::hex("02 01 06"), scan).value();
    STATIC_REQUIRE((only_uuid->has_service_uuid && only_uuid->mode == device_mode::unknown));
    STATIC_REQUIRE(!parse_advertisement(test::hex("02 01 06 05 09 4F 74 68 72")).value().has_value());
    // manufacturer data of another company / too short is not BuWizz3
    STATIC_REQUIRE(!parse_advertisement(test::hex("09 FF 4C 00 42 57 03 22 34 12")).value().has_value());
    STATIC_REQUIRE(!parse_advertisement(test::hex("07 FF 4E 05 42 57 03 22")).value().has_value());
    CHECK(parse_advertisement(boot_adv).value()->mode == device_mode::bootloader);
}

TEST_CASE("buwizz3: the last manufacturer data record counts, whole", "[buwizz3][advertising]") {
    // application record (version 4C 01, serial 0x0642) then a bootloader record: found by fuzzing
    constexpr auto a = parse_advertisement(test::hex("02 01 06 09 FF 4E 05 42 57 4C 01 42 06 09 FF 4E 05 42 57 42 4C 00 00")).value();
    STATIC_REQUIRE(a->mode == device_mode::bootloader);
    STATIC_REQUIRE(a->firmware_version == std::array<std::uint8_t, 2>{0, 0});
    STATIC_REQUIRE(a->serial_low16 == 0);
}

TEST_CASE("buwizz3: malformed advertising data", "[buwizz3][advertising]") {
    STATIC_REQUIRE(parse_advertisement(test::hex("02 01 06 09 FF 4E")).error() == error{errc::bad_length, 3});
    // scan response offsets count after the advertisement (3 bytes)
    STATIC_REQUIRE(parse_advertisement(test::hex("02 01 06"), test::hex("11 06 93")).error() == error{errc::bad_length, 3});
    CHECK(parse_advertisement(test::hex("05")).error() == error{errc::bad_length, 0});
}
