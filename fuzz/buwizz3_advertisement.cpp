// BuWizz3 advertising data: the input is split into advertisement and scan response.
// A reference parser (the AD structures walked byte by byte, the BuWizz3
// manufacturer data read by hand) gives what parse_advertisement must find.
#include <robowire/buwizz3.hpp>

#include <optional>
#include <string_view>

#include "common.hpp"

namespace {
namespace bw = robowire::buwizz3;

// What the advertisement says, from the BuWizz3 documentation: the last
// manufacturer data 4E 05 42 57 with at least 8 bytes gives the mode ("BL":
// bootloader, version 0.0; else the version bytes), then the serial's low 16
// bits little-endian; a UUID list holding the service UUID; a local name.
struct expected {
    bool manufacturer = false, uuid = false;
    bw::device_mode mode = bw::device_mode::unknown;
    std::uint8_t version[2] = {0, 0};
    std::uint16_t serial = 0;
    std::optional<std::string_view> name;
};

void walk(std::span<const std::uint8_t> d, expected& e) {
    const auto want = bw::service_uuid.on_air();
    for (std::size_t pos = 0; pos < d.size();) {
        const std::size_t len = d[pos];
        if (len == 0 || len > d.size() - pos - 1) return;  // end of the data / malformed (reported apart)
        const std::uint8_t type = d[pos + 1];
        const std::uint8_t* body = d.data() + pos + 2;
        const std::size_t n = len - 1;
        if (type == 0xFF && n >= 8 && body[0] == 0x4E && body[1] == 0x05 && body[2] == 0x42 && body[3] == 0x57) {
            e.manufacturer = true;
            const bool bootloader = body[4] == 'B' && body[5] == 'L';
            e.mode = bootloader ? bw::device_mode::bootloader : bw::device_mode::application;
            e.version[0] = bootloader ? std::uint8_t{0} : body[4];
            e.version[1] = bootloader ? std::uint8_t{0} : body[5];
            e.serial = static_cast<std::uint16_t>(body[6] + 256 * body[7]);
        } else if (type == 0x06 || type == 0x07) {
            for (std::size_t i = 0; i + 16 <= n; i += 16)
                if (fuzz::same_bytes({body + i, 16}, want)) e.uuid = true;
        } else if (type == 0x08 || type == 0x09) {
            e.name = std::string_view(reinterpret_cast<const char*>(body), n < 29 ? n : 29);
        }
        pos += 1 + len;
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::size_t split = data[0] % size;
    const std::span<const std::uint8_t> adv(data + 1, split), scan(data + 1 + split, size - 1 - split);
    const auto r = bw::parse_advertisement(adv, scan);
    const auto a = robowire::ad::validate(adv), s = robowire::ad::validate(scan);
    fuzz::check_access(r);
    FUZZ_CHECK(r.has_value() == (a.has_value() && s.has_value()));
    if (!r) {
        FUZZ_CHECK(r.error().code == robowire::errc::bad_length);
        FUZZ_CHECK(r.error().offset < adv.size() + scan.size());
        return 0;
    }
    expected e;
    walk(adv, e);
    walk(scan, e);
    FUZZ_CHECK(r->has_value() == (e.manufacturer || e.uuid));
    if (*r) {
        const auto& info = **r;
        FUZZ_CHECK(info.has_manufacturer_data == e.manufacturer && info.has_service_uuid == e.uuid);
        FUZZ_CHECK(info.mode == e.mode);
        FUZZ_CHECK(info.firmware_version[0] == e.version[0] && info.firmware_version[1] == e.version[1]);
        FUZZ_CHECK(info.serial_low16 == e.serial);
        FUZZ_CHECK(info.local_name.has_value() == e.name.has_value());
        if (e.name) FUZZ_CHECK(info.local_name->view() == *e.name);
    }
    return 0;
}
