// robowire/core/detail/divide.hpp - division by a constant without a divide
// instruction, for the integer unit helpers.
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <cstdint>

namespace robowire::detail {

// floor(n / D) for 0 <= n <= Max, exact, in 32-bit arithmetic: n x M >> S
// (M / 2^S close to 1 / D, Max x M < 2^32) is at most Fix off the quotient,
// and Fix compare-and-step corrections land on it. A core without a divide
// instruction (Cortex-M0+) then links no __udivsi3 / __divsi3. Each use is
// tested against the plain division over its whole input range.
template <std::uint32_t D, std::uint32_t Max, std::uint32_t M, unsigned S, unsigned Fix>
[[nodiscard]] constexpr std::uint32_t divide(std::uint32_t n) noexcept {
    static_assert(D > 1 && static_cast<std::uint64_t>(Max) * M < (std::uint64_t{1} << 32), "n x M must fit 32 bits");
    std::uint32_t q = n * M >> S;
    for (unsigned k = 0; k < Fix; ++k) {
        if (q * D > n) --q;
        else if (n - q * D >= D) ++q;
    }
    return q;
}

}  // namespace robowire::detail
