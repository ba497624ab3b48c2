// robowire/buwizz3/uuids.hpp - BuWizz3 GATT UUIDs: canonical strings and on-air bytes.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <cstdint>

#include "../core/uuid.hpp"

namespace robowire::buwizz3 {

// Service 500592d1-74fb-4481-88b3-9919b1676e93; its document prints the
// on-air order 93:6E:67:B1:19:99:B3:88:81:44:FB:74:D1:92:05:50.
inline constexpr uuid128 service_uuid = uuid_literal("500592d1-74fb-4481-88b3-9919b1676e93");
// Characteristics: the service UUID with bytes 2-3 replaced.
inline constexpr uuid128 application_uuid = service_uuid.with_short_value(0x2901);  // commands + status (write, notify)
inline constexpr uuid128 bootloader_uuid = service_uuid.with_short_value(0x8000);   // firmware update (write, notify)

// UART on motor port n (1..4): 50053901-... to 50053904-...; value_out_of_range otherwise.
constexpr result<uuid128> uart_characteristic(int n) noexcept {
    if (n < 1 || n > 4) return fail(errc::value_out_of_range, 0);
    return service_uuid.with_short_value(static_cast<std::uint16_t>(0x3900 + n));
}

}  // namespace robowire::buwizz3
