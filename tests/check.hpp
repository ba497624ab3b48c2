// Test helpers: hex literals and byte comparisons.
#pragma once

#include <robowire/core/bytes.hpp>

#include <cstdint>
#include <span>
#include <string_view>

namespace test {

// Bytes from a hex literal written by hand ("01 5C FF"); a bad literal does not compile in constexpr.
template <std::size_t N = 256>
constexpr robowire::bytes<N> hex(std::string_view s) {
    return robowire::parse_hex<N>(s).value();
}

constexpr bool same(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    return robowire::equal_bytes(a, b);
}

}  // namespace test
