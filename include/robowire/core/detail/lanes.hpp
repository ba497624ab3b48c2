// robowire/core/detail/lanes.hpp - internal: the range checks of a message's
// one-byte fields as one vector test (ROBOWIRE_SSE2, not under
// ROBOWIRE_OPTIMIZE_SIZE). A byte is valid when (byte - lo) mod 256 <= width;
// the fields' bytes are loaded as 8 or 16 lanes and tested at once. A failed
// test is followed by the exact checks, which find the first error.
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "../table.hpp"
#include "access.hpp"

namespace robowire::detail {

// A field of shape S valid in [Min, Max] as lanes: each of its bytes valid
// when (byte - lo) mod 256 <= width. ok: every check it has is that test (or
// it has none: checked false). T: the type its range is checked in (the
// member's for encode, the wire's for decode); shared by fields alike.
struct byte_lanes {
    bool ok = false, checked = false;
    std::uint8_t lo = 0, width = 255;
    unsigned cost = 0;    // instructions its own checks take (estimate)
    std::size_t off = 0;  // wire offset
};
// What a field's shape S says: one-byte elements whose checks are a range
// (the table's, within [tmin, tmax], the type they are checked in; an enum's
// run of codes: fixed, in [lo, hi]).
struct lane_shape {
    bool ok = false, fixed = false;
    std::int64_t tmin = 0, tmax = 0, lo = 0, hi = 0;
};
template <class S, bool Member>
constexpr lane_shape lane_shape_of() noexcept {
    using E = typename S::element_type;
    using W = typename S::wire_type;
    if constexpr (S::is_optional || !scalar_wire_v<W> || S::kind == wire_kind::f32le || !same_bytes_v<W, E> ||
                  sizeof(E) != 1 || S::element_size != 1) {
        return lane_shape{};
    } else if constexpr (std::is_enum_v<E>) {
        using U = std::underlying_type_t<E>;
        if constexpr (!enum_code_run_v<E>.found || std::is_signed_v<U> != std::is_signed_v<typename W::raw_type>)
            return lane_shape{};
        else
            return lane_shape{true,
                              true,
                              std::numeric_limits<U>::min(),
                              std::numeric_limits<U>::max(),
                              enum_code_run_v<E>.lo,
                              enum_code_run_v<E>.hi};
    } else {
        using T = std::conditional_t<Member, E, typename W::raw_type>;
        return lane_shape{true, false, std::numeric_limits<T>::min(), std::numeric_limits<T>::max(), 0, 0};
    }
}
// A field of that shape, valid in [min, max], at wire offset `off`, as lanes.
constexpr byte_lanes lanes_of(const lane_shape& s, std::int64_t min, std::int64_t max, std::size_t off,
                              std::size_t count) noexcept {
    if (!s.ok) return {};
    std::int64_t lo = s.fixed ? s.lo : (min > s.tmin ? min : s.tmin);
    std::int64_t hi = s.fixed ? s.hi : (max < s.tmax ? max : s.tmax);
    if (!s.fixed && lo == s.tmin && hi == s.tmax) return {true, false, 0, 255, 0, off};  // no check
    if (lo > hi) return {};
    const unsigned each = lo == s.tmin || hi == s.tmax ? 2 : 4;  // one compare, or two
    return {true,
            true,
            static_cast<std::uint8_t>(lo),
            static_cast<std::uint8_t>(hi - lo),
            static_cast<unsigned>(count) * each,
            off};
}

// The vector test of M: fields (bit I of `covered`) whose checks it makes,
// the bytes it loads (wire offsets of 8-byte halves, or one 16-byte load),
// and its constants per lane.
struct lane_plan {
    bool use = false;
    std::uint64_t covered = 0;
    std::size_t anchor = 0;      // a covered field, the first tested (encode finds its member)
    std::size_t first = 0;       // its wire offset
    std::size_t at[2] = {0, 0};  // wire offsets of the loads
    unsigned loads = 0;          // 1: 8 bytes at at[0]; 2: 8 at at[0], 8 at at[1]; 16: 16 at at[0]
    alignas(16) std::uint8_t lo[16] = {};
    alignas(16) std::uint8_t width[16] = {255, 255, 255, 255, 255, 255, 255, 255,
                                          255, 255, 255, 255, 255, 255, 255, 255};
};
// The plan: the 16-byte window of wire offsets, from a checked field on,
// whose fields' checks cost the most, if the test costs less. Limit: wire
// bytes readable (decode: the shortest input; encode: 0, the loads are placed
// at run time). f, count: M's n fields (each covers count[i] bytes).
constexpr lane_plan plan_lanes(const byte_lanes* f, const std::size_t* count, std::size_t n,
                               std::size_t limit) noexcept {
    const auto in_window = [&](std::size_t i, std::size_t from) {
        return i < 64 && f[i].ok && f[i].off >= from && f[i].off + count[i] <= from + 16;
    };
    std::size_t best = n;
    unsigned best_gain = 0, best_loads = 0;
    for (std::size_t s = 0; s < n; ++s) {
        if (!in_window(s, f[s].off) || !f[s].checked) continue;
        unsigned cost = 0;
        std::size_t last = f[s].off;
        for (std::size_t i = 0; i < n; ++i)
            if (in_window(i, f[s].off) && f[i].checked) {
                cost += f[i].cost;
                if (f[i].off + count[i] - 1 > last) last = f[i].off + count[i] - 1;
            }
        const std::size_t span = last - f[s].off + 1;
        const unsigned loads = span > 8 ? (limit >= 16 ? 16 : 2) : 1;
        if (loads == 1 && limit != 0 && limit < 8) continue;
        const unsigned test = loads == 2 ? 10 : 8;
        if (cost > test && cost - test > best_gain) best = s, best_gain = cost - test, best_loads = loads;
    }
    lane_plan p{};
    if (best == n) return p;
    p.use = true;
    p.anchor = best;
    p.first = f[best].off;
    p.loads = best_loads;
    std::size_t last = p.first;
    for (std::size_t i = 0; i < n; ++i)
        if (in_window(i, p.first)) {
            p.covered |= std::uint64_t{1} << i;
            if (f[i].checked && f[i].off + count[i] - 1 > last) last = f[i].off + count[i] - 1;
        }
    if (p.loads == 16) p.at[0] = p.first + 16 <= limit ? p.first : limit - 16;
    else if (p.loads == 1) p.at[0] = limit == 0 || p.first + 8 <= limit ? p.first : limit - 8;
    else p.at[0] = p.first, p.at[1] = last - 7;
    for (std::size_t i = 0; i < n; ++i)
        if ((p.covered >> i & 1) && f[i].checked)
            for (std::size_t w = f[i].off; w < f[i].off + count[i]; ++w) {
                // lane of wire byte w; a byte both halves hold is tested in the first
                const std::size_t lane = p.loads == 2 && w >= p.at[0] + 8 ? 8 + (w - p.at[1]) : w - p.at[0];
                p.lo[lane] = f[i].lo;
                p.width[lane] = f[i].width;
            }
    return p;
}
template <class M, bool Member, std::size_t... I>
constexpr lane_plan plan_of(std::size_t limit, std::index_sequence<I...>) noexcept {
    const byte_lanes f[] = {lanes_of(lane_shape_of<shape_t<M, I>, Member>(), field_v<M, I>.valid.min,
                                     field_v<M, I>.valid.max, field_v<M, I>.offset, shape_t<M, I>::count)...};
    const std::size_t count[] = {shape_t<M, I>::count...};
    return plan_lanes(f, count, sizeof...(I), limit);
}
// M's plan: encode's (Member: the members, when their bytes lie as on the
// wire, checked at run time) or decode's (the wire bytes; the shortest input
// readable). Callers look at messages of three fields or more only (fewer
// never pay for the test).
template <class M, bool Member>
inline constexpr lane_plan lanes_v = plan_of<M, Member>(Member ? 0 : min_size_v<M>,
                                                        std::make_index_sequence<field_count_v<M>>{});
inline constexpr std::size_t lanes_min_fields = 3;

#if ROBOWIRE_SSE2
// The test: every lane of the bytes at a (and b) valid. SSE2, through the
// compilers' vector types (no intrinsics header).
template <const lane_plan& P>
ROBOWIRE_ALWAYS_INLINE bool lanes_valid(const unsigned char* a, const unsigned char* b) noexcept {
    using v16 = unsigned char __attribute__((vector_size(16)));
    using u64x2 = unsigned long long __attribute__((vector_size(16)));
    using c16 = char __attribute__((vector_size(16)));
    v16 x;
    if constexpr (P.loads == 16) {
        std::memcpy(&x, a, 16);
    } else {
        unsigned long long lo = 0, hi = 0;
        std::memcpy(&lo, a, 8);
        if constexpr (P.loads == 2) std::memcpy(&hi, b, 8);
        x = reinterpret_cast<v16>(u64x2{lo, hi});
    }
    (void)b;
    v16 lo, width;
    std::memcpy(&lo, P.lo, 16);
    std::memcpy(&width, P.width, 16);
    const v16 d = x - lo;
    const v16 clamped = d < width ? d : width;
    return __builtin_ia32_pmovmskb128(reinterpret_cast<c16>(clamped == d)) == 0xFFFF;
}
#endif

}  // namespace robowire::detail
