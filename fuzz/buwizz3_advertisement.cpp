// BuWizz3 advertising data: the input is split into advertisement and scan response.
#include <robowire/buwizz3.hpp>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace bw = robowire::buwizz3;
    if (size == 0) return 0;
    const std::size_t split = data[0] % size;
    const std::span<const std::uint8_t> adv(data + 1, split), scan(data + 1 + split, size - 1 - split);
    const auto r = bw::parse_advertisement(adv, scan);
    const auto a = robowire::ad::validate(adv), s = robowire::ad::validate(scan);
    FUZZ_CHECK(r.has_value() == (a.has_value() && s.has_value()));
    if (!r) {
        FUZZ_CHECK(r.error().code == robowire::errc::bad_length);
        FUZZ_CHECK(r.error().offset < adv.size() + scan.size());
        return 0;
    }
    if (*r) {
        const auto& info = **r;
        FUZZ_CHECK(info.has_manufacturer_data || info.has_service_uuid);
        FUZZ_CHECK(info.has_manufacturer_data == (info.mode != bw::device_mode::unknown));
        if (info.mode == bw::device_mode::bootloader) FUZZ_CHECK(info.firmware_version[0] == 0 && info.firmware_version[1] == 0);
    }
    return 0;
}
