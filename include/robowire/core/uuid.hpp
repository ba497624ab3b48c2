// robowire/core/uuid.hpp - 128-bit UUIDs: canonical string and on-air byte order.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "result.hpp"

namespace robowire {

// A 128-bit UUID. `value` holds the bytes in canonical (string) order, most
// significant first; BLE sends them least significant first (on_air()).
struct uuid128 {
    std::array<std::uint8_t, 16> value{};

    // Parses "xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx" (either case).
    static constexpr result<uuid128> parse(std::string_view s) noexcept {
        if (s.size() != 36) return fail(errc::bad_length, s.size());
        uuid128 u;
        std::size_t k = 0;
        for (std::size_t i = 0; i < 36;) {
            if (i == 8 || i == 13 || i == 18 || i == 23) {
                if (s[i] != '-') return fail(errc::value_out_of_range, i);
                ++i;
                continue;
            }
            const int hi = nibble(s[i]), lo = nibble(s[i + 1]);
            if (hi < 0) return fail(errc::value_out_of_range, i);
            if (lo < 0) return fail(errc::value_out_of_range, i + 1);
            u.value[k++] = static_cast<std::uint8_t>(hi * 16 + lo);
            i += 2;
        }
        return u;
    }
    // From the 16 bytes as received over the air (least significant first).
    static constexpr uuid128 from_on_air(std::span<const std::uint8_t, 16> b) noexcept {
        uuid128 u;
        for (std::size_t i = 0; i < 16; ++i) u.value[i] = b[15 - i];
        return u;
    }
    // The 16 bytes in on-air order (least significant first).
    constexpr std::array<std::uint8_t, 16> on_air() const noexcept {
        std::array<std::uint8_t, 16> b{};
        for (std::size_t i = 0; i < 16; ++i) b[i] = value[15 - i];
        return b;
    }
    // Canonical lower-case string, 36 characters, no terminator.
    constexpr std::array<char, 36> to_chars() const noexcept {
        constexpr std::string_view digits = "0123456789abcdef";
        std::array<char, 36> s{};
        std::size_t o = 0;
        for (std::size_t i = 0; i < 16; ++i) {
            if (i == 4 || i == 6 || i == 8 || i == 10) s[o++] = '-';
            s[o++] = digits[value[i] >> 4];
            s[o++] = digits[value[i] & 0x0F];
        }
        return s;
    }
    // The 16-bit "short" value at bytes 2-3 of the canonical form (xxxxSSSS-...).
    constexpr std::uint16_t short_value() const noexcept {
        return static_cast<std::uint16_t>(value[2] << 8 | value[3]);
    }
    // This UUID with bytes 2-3 replaced by `v` (how vendor bases derive characteristics).
    constexpr uuid128 with_short_value(std::uint16_t v) const noexcept {
        uuid128 u = *this;
        u.value[2] = static_cast<std::uint8_t>(v >> 8);
        u.value[3] = static_cast<std::uint8_t>(v);
        return u;
    }
    friend constexpr bool operator==(const uuid128&, const uuid128&) = default;

private:
    static constexpr int nibble(char c) noexcept {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    }
};

// A UUID from its canonical string ("xxxxxxxx-xxxx-..."), parsed at compile
// time: a malformed string does not compile.
consteval uuid128 uuid_literal(std::string_view s) {
    const auto r = uuid128::parse(s);
    return r.value();
}

}  // namespace robowire
