// robowire/core/divide.hpp - division by a constant without a divide
// instruction, for the integer unit helpers.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstdint>

namespace robowire::codec {

// The target has no integer divide instruction (Cortex-M0/M0+/M23 and other
// ARMv6-M/ARMv8-M baseline cores, RISC-V without the M extension's division):
// a division would link a library routine (__aeabi_uidiv: 266 bytes on
// Cortex-M0+, __aeabi_idiv: 460).
#if (defined(__arm__) && !defined(__ARM_FEATURE_IDIV)) || (defined(__riscv) && !defined(__riscv_div))
inline constexpr bool no_divide_instruction = true;
#else
inline constexpr bool no_divide_instruction = false;
#endif

// floor(n / D) for 0 <= n <= Max. by_multiply: exact, in 32-bit arithmetic,
// n x M >> S (M / 2^S close to 1 / D, Max x M < 2^32) is at most Fix off the
// quotient, and Fix compare-and-step corrections land on it. operator():
// by_multiply where the target has no divide instruction, else n / D (smaller
// there). Each divider is tested against the plain division over its whole
// input range.
template <std::uint32_t D, std::uint32_t Max, std::uint32_t M, unsigned S, unsigned Fix>
struct divider {
    static_assert(D > 1 && static_cast<std::uint64_t>(Max) * M < (std::uint64_t{1} << 32), "n x M must fit 32 bits");
    static constexpr std::uint32_t max = Max;
    [[nodiscard]] static constexpr std::uint32_t by_multiply(std::uint32_t n) noexcept {
        std::uint32_t q = n * M >> S;
        for (unsigned k = 0; k < Fix; ++k) {
            if (q * D > n) --q;
            else if (n - q * D >= D) ++q;
        }
        return q;
    }
    [[nodiscard]] constexpr std::uint32_t operator()(std::uint32_t n) const noexcept {
        if constexpr (no_divide_instruction) return by_multiply(n);
        else return n / D;
    }
};

}  // namespace robowire::codec
