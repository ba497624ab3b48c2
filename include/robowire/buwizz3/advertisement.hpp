// robowire/buwizz3/advertisement.hpp - recognise a BuWizz3 in BLE advertising data.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "../core/advertising.hpp"
#include "../core/text.hpp"
#include "uuids.hpp"

namespace robowire::buwizz3 {

enum class device_mode : std::uint8_t { unknown, application, bootloader };

// What an advertisement (and its scan response) says about a BuWizz3.
struct advertisement {
    device_mode mode = device_mode::unknown;         // from manufacturer data
    std::array<std::uint8_t, 2> firmware_version{};  // application mode: x y (3.22 advertises 03 22)
    std::uint16_t serial_low16 = 0;                  // low 16 bits of the serial (0 in bootloader mode)
    bool has_manufacturer_data = false;              // 4E 05 42 57 ... seen
    bool has_service_uuid = false;                   // service UUID in AD type 0x06 or 0x07
    std::optional<text<29>> local_name{};            // complete or shortened local name
    friend constexpr bool operator==(const advertisement&, const advertisement&) = default;
};

// Manufacturer data payload after AD type 0xFF: company 0x054E little-endian, then 'B' 'W'.
inline constexpr std::array<std::uint8_t, 4> manufacturer_prefix{0x4E, 0x05, 0x42, 0x57};

namespace impl {
template <class Deferred>
constexpr void read_structures(std::span<const std::uint8_t> ad_data, advertisement& seen, error& walk_error) noexcept {
    ad::basic_reader<Deferred> r(ad_data);
    while (auto s = r.next()) {
        const auto d = s->data;
        if (s->type == ad::manufacturer_data && d.size() >= 8 && d[0] == manufacturer_prefix[0] &&
            d[1] == manufacturer_prefix[1] && d[2] == manufacturer_prefix[2] && d[3] == manufacturer_prefix[3]) {
            seen.has_manufacturer_data = true;
            if (d[4] == 0x42 && d[5] == 0x4C) {  // 'B' 'L'
                seen.mode = device_mode::bootloader;
                seen.firmware_version = {0, 0};
            } else {
                seen.mode = device_mode::application;
                seen.firmware_version = {d[4], d[5]};
            }
            seen.serial_low16 = static_cast<std::uint16_t>(d[6] | d[7] << 8);
        } else if (s->type == ad::incomplete_uuid128_list || s->type == ad::complete_uuid128_list) {
            const auto want = service_uuid.on_air();
            for (std::size_t i = 0; i + 16 <= d.size(); i += 16) {
                bool same = true;
                for (std::size_t k = 0; k < 16; ++k) same = same && d[i + k] == want[k];
                if (same) seen.has_service_uuid = true;
            }
        } else if (s->type == ad::complete_local_name || s->type == ad::shortened_local_name) {
            std::array<char, 29> chars{};
            const std::size_t n = d.size() < chars.size() ? d.size() : chars.size();
            for (std::size_t i = 0; i < n; ++i) chars[i] = static_cast<char>(d[i]);
            seen.local_name = text<29>::make(std::string_view(chars.data(), n)).value();
        }
    }
    if (r.error().code != errc::ok && walk_error.code == errc::ok) walk_error = r.error();
}
}  // namespace impl

// Parses an advertisement and, optionally, its scan response. When several
// BuWizz3 manufacturer data structures are present, the last one counts. Returns
// nullopt when neither BuWizz3 manufacturer data nor the BuWizz3 service UUID
// is present; bad_length (offset of the bad length byte; scan response
// offsets count after the advertisement) when the AD data is malformed.
// Returns a result<std::optional<advertisement>> (a template: a file that
// includes this header but parses nothing instantiates neither).
template <class Deferred = void>
constexpr auto parse_advertisement(std::span<const std::uint8_t> ad_data,
                                   std::span<const std::uint8_t> scan_data = {}) noexcept {
    using found = std::optional<codec::deferred_t<advertisement, Deferred>>;
    advertisement seen;
    error ad_error{};
    impl::read_structures<Deferred>(ad_data, seen, ad_error);
    error scan_error{};
    impl::read_structures<Deferred>(scan_data, seen, scan_error);
    if (ad_error.code != errc::ok) return result<found>(ad_error);
    if (scan_error.code != errc::ok) return result<found>(fail(scan_error.code, ad_data.size() + scan_error.offset));
    if (!seen.has_manufacturer_data && !seen.has_service_uuid) return result<found>(found{});
    return result<found>(found{seen});
}

}  // namespace robowire::buwizz3
