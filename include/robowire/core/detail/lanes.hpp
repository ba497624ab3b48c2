// robowire/core/detail/lanes.hpp - internal: the range checks of a message's
// one-byte fields (and fixed bytes the load holds) as one vector test, flag
// bytes as one word test (ROBOWIRE_SSE2, not under ROBOWIRE_OPTIMIZE_SIZE),
// sparse one-byte enums by a table. A byte is valid when
// (byte - lo) mod 256 <= width; the fields' bytes are loaded as 8 or 16
// lanes and tested at once. A failed test is followed by the exact checks,
// which find the first error.
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

// A field as lanes: each of its bytes valid when (byte - lo) mod 256 <=
// width. ok: every check it has is that test (or it has none: checked false).
struct byte_lanes {
    bool ok = false, checked = false;
    std::uint8_t lo = 0, width = 255;
    unsigned cost = 0;    // instructions its own checks take (estimate)
    std::size_t off = 0;  // wire offset
};
// What a field's shape S says: one-byte elements whose checks are a range
// (the table's, within the type they are checked in: [mmin, mmax] the
// member's for encode, [wmin, wmax] the wire's for decode; an enum's run of
// codes: fixed, in [lo, hi]).
struct lane_shape {
    bool ok = false, fixed = false;
    std::int64_t mmin = 0, mmax = 0, wmin = 0, wmax = 0, lo = 0, hi = 0;
};
template <class S>
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
                              std::numeric_limits<U>::min(),
                              std::numeric_limits<U>::max(),
                              enum_code_run_v<E>.lo,
                              enum_code_run_v<E>.hi};
    } else {
        using R = typename W::raw_type;
        return lane_shape{true,
                          false,
                          std::numeric_limits<E>::min(),
                          std::numeric_limits<E>::max(),
                          std::numeric_limits<R>::min(),
                          std::numeric_limits<R>::max(),
                          0,
                          0};
    }
}
// A field of that shape, valid in [min, max], at wire offset `off`, as lanes.
template <class = void>  // compiled where used
constexpr byte_lanes lanes_of(const lane_shape& s, bool member, std::int64_t min, std::int64_t max, std::size_t off,
                              std::size_t count) noexcept {
    if (!s.ok) return {};
    const std::int64_t tmin = member ? s.mmin : s.wmin, tmax = member ? s.mmax : s.wmax;
    std::int64_t lo = s.fixed ? s.lo : (min > tmin ? min : tmin);
    std::int64_t hi = s.fixed ? s.hi : (max < tmax ? max : tmax);
    if (!s.fixed && lo == tmin && hi == tmax) return {true, false, 0, 255, 0, off};  // no check
    if (lo > hi) return {};
    const unsigned each = lo == tmin || hi == tmax ? 2 : 4;  // one compare, or two
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
struct lane_window {
    std::size_t at[2] = {0, 0};  // wire offsets of the loads
    // 0: none; 1: 8 bytes at at[0]; 16: 16 at at[0]; 2: 8 at at[0], then `tail` bytes (1, 2, 4
    // or 8) at at[1] ending at the last byte tested: lane k holds wire byte at[0] + k, lanes
    // past the last byte hold 0
    unsigned loads = 0;
    unsigned tail = 0;
    // lane k valid: (signed char)(byte + add[k]) <= lim[k], that is byte - lo in [0, width]
    // (add = 0x80 - lo, lim = width - 0x80); a lane with no test: add 0, lim 127
    alignas(16) std::uint8_t add[16] = {};
    alignas(16) std::int8_t lim[16] = {127, 127, 127, 127, 127, 127, 127, 127, 127, 127, 127, 127, 127, 127, 127, 127};
    // Wire bytes the loads hold, from at[0] on.
    constexpr std::size_t length() const noexcept {
        return loads == 16 ? 16 : loads == 2 ? at[1] + tail - at[0] : loads == 1 ? 8 : 0;
    }
};
struct lane_plan {
    bool use = false;
    std::uint64_t covered = 0;
    std::uint64_t mirror = 0;  // encode: fields whose members must lie as their wire bytes (all a load reads)
    std::size_t anchor = 0;    // a covered field, the first tested (encode finds its member)
    std::size_t first = 0;     // its wire offset
    // The vector test: win[0]; encode of 8 bytes or less also win[1], the load
    // ending at the last byte tested (for the object whose end win[0] passes).
    lane_window win[2];
    bool fixed_in = false;  // decode: win[0] tests every fixed byte too (byte == value)
    // Words of 2 or 4 bytes at wire offset word_at[k] whose bits in word_mask[k] (little-endian)
    // must be 0: fields valid in [0, 2^b - 1], two or more a word, that the vector does not test.
    std::size_t words = 0;
    std::size_t word_at[4] = {};
    unsigned word_size[4] = {};
    std::uint32_t word_mask[4] = {};
};
// The plan: the 16-byte window of wire offsets, from a checked field on,
// whose fields' checks cost the most, if the test costs less. Limit: wire
// bytes readable (decode: the shortest input; encode: 0, the loads are placed
// at run time). f, count: M's n fields (each covers count[i] bytes).
template <class = void>  // compiled where used
constexpr lane_plan plan_lanes(const byte_lanes* f, const std::size_t* count, std::size_t n, std::size_t limit,
                               const fixed_byte* fixed = nullptr, std::size_t fixed_n = 0,
                               const std::size_t* offs = nullptr, const std::size_t* flat = nullptr) noexcept {
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
        const unsigned test = loads == 2 ? 8 : 6;  // the loads, add, compare, mask, test, branch
        if (cost > test && cost - test > best_gain) best = s, best_gain = cost - test, best_loads = loads;
    }
    lane_plan p{};
    if (best != n) {
        p.anchor = best;
        p.first = f[best].off;
    }
    std::size_t last = p.first;
    for (std::size_t i = 0; i < n && best != n; ++i)
        if (in_window(i, p.first)) {
            p.covered |= std::uint64_t{1} << i;
            if (f[i].checked && f[i].off + count[i] - 1 > last) last = f[i].off + count[i] - 1;
        }
    // the mask words, from the fields left
    const auto maskable = [&](std::size_t i) {
        return i < 64 && (p.covered >> i & 1) == 0 && f[i].ok && f[i].checked && f[i].lo == 0 && f[i].width != 255 &&
               ((f[i].width + 1) & f[i].width) == 0;
    };
    for (std::size_t s = 0; s < n && p.words < 4; ++s) {
        if (!maskable(s)) continue;
        const std::size_t a = f[s].off;
        unsigned size = limit == 0 || a + 4 <= limit ? 4 : 2;
        if (limit != 0 && a + size > limit) continue;
        std::size_t bytes = 0, end = a;
        for (std::size_t i = s; i < n; ++i)
            if (maskable(i) && f[i].off + count[i] <= a + size) bytes += count[i], end = f[i].off + count[i];
        if (bytes < 2) continue;
        if (end <= a + 2) size = 2;
        if (best == n && p.words == 0) p.anchor = s, p.first = a;
        for (std::size_t i = s; i < n; ++i)
            if (maskable(i) && f[i].off + count[i] <= a + size) {
                p.covered |= std::uint64_t{1} << i;
                for (std::size_t k = 0; k < count[i]; ++k)
                    p.word_mask[p.words] |= std::uint32_t{static_cast<std::uint8_t>(~f[i].width)}
                                            << 8 * (f[i].off + k - a);
            }
        p.word_at[p.words] = a;
        p.word_size[p.words++] = size;
    }
    p.use = best != n || p.words != 0;
    if (!p.use) return lane_plan{};
    const auto fill = [&](lane_window& w, unsigned loads, std::size_t at0, std::size_t at1) {
        w.loads = loads;
        w.at[0] = at0;
        w.at[1] = at1;
        if (loads == 2) {  // the bytes after the first 8, up to `last`, in the smallest load
            const std::size_t more = last + 1 - (at0 + 8);
            w.tail = more <= 1 ? 1 : more <= 2 ? 2 : more <= 4 ? 4 : 8;
            w.at[1] = last + 1 - w.tail;
        }
        for (std::size_t i = 0; i < n; ++i)
            if ((p.covered >> i & 1) && f[i].checked && in_window(i, p.first))
                for (std::size_t b = f[i].off; b < f[i].off + count[i]; ++b) {
                    const std::size_t lane = b - at0;
                    w.add[lane] = static_cast<std::uint8_t>(0x80 - f[i].lo);
                    w.lim[lane] = static_cast<std::int8_t>(f[i].width - 0x80);
                }
    };
    // Decode: one load of w bytes, placed to hold the fixed bytes too where it can.
    const auto place = [&](std::size_t w) {
        std::size_t lo = last + 1 >= w ? last + 1 - w : 0, hi = p.first < limit - w ? p.first : limit - w;
        std::size_t fmin = limit, fmax = 0;
        for (std::size_t k = 0; k < fixed_n; ++k) {
            fmin = fixed[k].offset < fmin ? fixed[k].offset : fmin;
            fmax = fixed[k].offset > fmax ? fixed[k].offset : fmax;
        }
        if (fixed_n != 0 && fmax + 1 >= w && fmax + 1 - w > lo) lo = fmax + 1 - w;
        if (fixed_n != 0 && fmin < hi) hi = fmin;
        const bool all = fixed_n != 0 && lo <= hi;
        const std::size_t at = all ? lo : (p.first + w <= limit ? p.first : limit - w);
        fill(p.win[0], static_cast<unsigned>(w == 16 ? 16 : 1), at, 0);
        for (std::size_t k = 0; k < fixed_n && all; ++k) {  // valid: byte - value in [0, 0]
            p.win[0].add[fixed[k].offset - at] = static_cast<std::uint8_t>(0x80 - fixed[k].value);
            p.win[0].lim[fixed[k].offset - at] = -128;
        }
        p.fixed_in = all;
    };
    if (best_loads == 16) place(16);
    else if (best_loads == 2) fill(p.win[0], 2, p.first, 0);
    else if (best_loads == 1 && limit != 0) place(8);
    else if (best_loads == 1) fill(p.win[0], 1, p.first, 0), fill(p.win[1], 1, last >= 7 ? last - 7 : 0, 0);
    if (limit == 0) {  // encode: a load reads only bytes of fields whose members are their wire bytes
        const auto held = [&](std::size_t from, std::size_t w, bool mark) {
            bool all = true;
            for (std::size_t b = from; b < from + w; ++b) {
                bool in = false;
                for (std::size_t i = 0; i < n && i < 64; ++i)
                    if (flat[i] != 0 && b >= offs[i] && b < offs[i] + flat[i]) {
                        in = true;
                        if (mark) p.mirror |= std::uint64_t{1} << i;
                    }
                all = all && in;
            }
            return all;
        };
        const auto window_held = [&](const lane_window& w, bool mark) {
            return w.loads == 0 || (held(w.at[0], 8, mark) && (w.loads != 2 || held(w.at[1], w.tail, mark)));
        };
        if (!window_held(p.win[1], false)) p.win[1] = lane_window{};
        if (!window_held(p.win[0], false)) p.win[0] = p.win[1], p.win[1] = lane_window{};
        if (best != n && p.win[0].loads == 0)  // no load left: the fields go back to their own checks
            for (std::size_t i = 0; i < n && i < 64; ++i)
                if (in_window(i, p.first)) p.covered &= ~(std::uint64_t{1} << i);
        for (std::size_t k = 0; k < p.words; ++k)
            if (!held(p.word_at[k], p.word_size[k], false)) return lane_plan{};  // rare: no plan
        (void)window_held(p.win[0], true), (void)window_held(p.win[1], true);
        for (std::size_t k = 0; k < p.words; ++k) (void)held(p.word_at[k], p.word_size[k], true);
        p.mirror |= p.covered;
        if (p.covered == 0) return lane_plan{};
    }
    return p;
}
template <class M, std::size_t... I>
constexpr lane_plan plan_of(bool member, std::size_t limit, std::index_sequence<I...>) noexcept {
    const byte_lanes f[] = {lanes_of(lane_shape_of<shape_t<M, I>>(), member, field_v<M, I>.valid.min,
                                     field_v<M, I>.valid.max, field_v<M, I>.offset, shape_t<M, I>::count)...};
    const std::size_t count[] = {shape_t<M, I>::count...};
    // a member that holds exactly its wire bytes: its size, else 0
    const std::size_t offs[] = {field_v<M, I>.offset...};
    const std::size_t flat[] = {
        (!shape_t<M, I>::is_optional && sizeof(typename shape_t<M, I>::member_type) == shape_t<M, I>::size
             ? shape_t<M, I>::size
             : 0)...};
    if (member) return plan_lanes(f, count, sizeof...(I), limit, nullptr, 0, offs, flat);
    return plan_lanes(f, count, sizeof...(I), limit, table_v<M>.fixed.data(), fixed_count_v<M>);
}
// M's plan: encode's (Member: the members, when their bytes lie as on the
// wire, checked at run time) or decode's (the wire bytes; the shortest input
// readable). Callers look at messages of three fields or more only (fewer
// never pay for the test).
template <class M, bool Member>
inline constexpr lane_plan lanes_v = plan_of<M>(Member, Member ? 0 : min_size_v<M>,
                                                std::make_index_sequence<field_count_v<M>>{});
inline constexpr std::size_t lanes_min_fields = 3;

// The indices below N that are not in Skip (bit k: index k), as an
// index_sequence: the fields a plan's tests leave to check_record.
template <std::uint64_t Skip, std::size_t N>
struct kept_fields {
    static constexpr auto list = [] {
        std::array<std::size_t, N + 1> r{};  // r[N]: how many
        for (std::size_t k = 0; k < N; ++k)
            if (k >= 64 || (Skip >> k & 1) == 0) r[r[N]++] = k;
        return r;
    }();
    template <std::size_t... K>
    static constexpr auto seq(std::index_sequence<K...>) noexcept {
        return std::index_sequence<list[K]...>{};
    }
    using type = decltype(seq(std::make_index_sequence<list[N]>{}));
};
template <std::uint64_t Skip, std::size_t N>
using kept_fields_t = typename kept_fields<Skip, N>::type;

#if ROBOWIRE_SSE2
// The mask words' test: no bit of a word_mask set in the bytes at p + base + word_at.
template <const lane_plan& P, std::size_t... K>
ROBOWIRE_ALWAYS_INLINE bool words_valid(const unsigned char* p, std::size_t base, std::index_sequence<K...>) noexcept {
    const auto word_ok = [p, base](std::size_t at, unsigned size, std::uint32_t mask) {
        if (size == 2) {
            std::uint16_t w;
            std::memcpy(&w, p + (base + at), 2);
            return (w & mask) == 0;
        }
        std::uint32_t w;
        std::memcpy(&w, p + (base + at), 4);
        return (w & mask) == 0;
    };
    (void)word_ok;
    return (word_ok(P.word_at[K], P.word_size[K], P.word_mask[K]) && ...);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push  // g++ 12 warns of the load of a window that the caller's test (plan_fits) rules out
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
using lane_bytes = unsigned char __attribute__((vector_size(16)));  // SSE2 register, through vector types
// Window W's lanes from the bytes at p + base + its wire offsets: lane k
// holding wire byte at[0] + k.
template <const lane_plan& Plan, std::size_t W>
ROBOWIRE_ALWAYS_INLINE lane_bytes lanes_load(const unsigned char* p, std::size_t base) noexcept {
    constexpr const lane_window& P = Plan.win[W];
    using u64x2 = unsigned long long __attribute__((vector_size(16)));
    const unsigned char* const a = p + (base + P.at[0]);
    lane_bytes x;
    if constexpr (P.loads == 16) {
        std::memcpy(&x, a, 16);
    } else {
        unsigned long long lo = 0, hi = 0;
        std::memcpy(&lo, a, 8);
        if constexpr (P.loads == 2) {  // the tail's bytes from lane 8 on (its load ends at the last byte)
            const unsigned char* const b = p + (base + P.at[1]);
            constexpr unsigned drop = 8 * (P.tail - (P.at[1] + P.tail - P.at[0] - 8));
            if constexpr (P.tail == 2) {  // pinsrw
                using u16x8 = unsigned short __attribute__((vector_size(16)));
                std::uint16_t t;
                std::memcpy(&t, b, 2);
                u16x8 h = reinterpret_cast<u16x8>(u64x2{lo, 0});
                h[4] = t;
                return reinterpret_cast<lane_bytes>(h);
            } else if constexpr (P.tail == 1) {
                hi = *b;
            } else if constexpr (P.tail == 4) {
                std::uint32_t t;
                std::memcpy(&t, b, 4);
                hi = t >> drop;
            } else {
                std::memcpy(&hi, b, 8);
                hi >>= drop;
            }
        }
        x = reinterpret_cast<lane_bytes>(u64x2{lo, hi});
    }
    return x;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
// The test of window W's lanes x: each valid.
template <const lane_plan& Plan, std::size_t W>
ROBOWIRE_ALWAYS_INLINE bool lanes_test(lane_bytes x) noexcept {
    constexpr const lane_window& P = Plan.win[W];
    using c16 = signed char __attribute__((vector_size(16)));
    lane_bytes add;
    c16 lim;
    std::memcpy(&add, P.add, 16);
    std::memcpy(&lim, P.lim, 16);
    return __builtin_ia32_pmovmskb128(reinterpret_cast<c16>(x + add) > lim) == 0;
}
// Every test of P on the bytes at p + base + wire offset, its vector test
// with window W (plan_fits).
template <const lane_plan& P, std::size_t W = 0>
ROBOWIRE_ALWAYS_INLINE bool plan_valid(const unsigned char* p, std::size_t base) noexcept {
    constexpr const lane_window& w = P.win[W];
    if constexpr (w.loads != 0)
        if (!lanes_test<P, W>(lanes_load<P, W>(p, base))) return false;
    if constexpr (P.words != 0) return words_valid<P>(p, base, std::make_index_sequence<P.words>{});
    return true;
}
// The window of P whose loads stay within an object of `size` bytes at
// object offset base + wire offset (modulo 2^N): 0 or 1, else 2 (none).
template <class = void>  // compiled where used
constexpr std::size_t plan_fits(const lane_plan& p, std::size_t base, std::size_t size) noexcept {
    const auto fits = [&](std::size_t at, std::size_t n) { return size >= n && base + at <= size - n; };
    bool words = true;
    for (std::size_t k = 0; k < p.words; ++k) words = words && fits(p.word_at[k], p.word_size[k]);
    for (std::size_t k = 0; k < 2 && words; ++k) {
        const lane_window& w = p.win[k];
        if (k == 1 && w.loads == 0) break;
        if (w.loads == 0 || (fits(w.at[0], w.loads == 16 ? 16 : 8) && (w.loads != 2 || fits(w.at[1], w.tail))))
            return k;
    }
    return 2;
}
#endif

// Encode of a message whose every field is a lane of window W's register
// (one-byte fields whose members lie as their wire bytes): the frame built
// from that register. D: the output, the size byte first when `lead`, then
// the wire bytes (`size`, 16 to 32 bytes with it). Stores: the constant words
// first (fixed bytes, zeros, the size), then the register moved up `shift`
// lanes (k or-ed in) as 16 bytes at D offset `at`; the words may reach into
// those 16 bytes, which the last store overwrites.
struct frame_image {
    bool use = false;
    std::size_t at = 0;
    unsigned shift = 0;
    bool add = false;
    alignas(16) std::uint8_t k[16] = {};
    std::size_t words = 0;
    std::size_t word_at[4] = {};
    unsigned word_size[4] = {};
    std::uint64_t word[4] = {};
};
template <class = void>  // compiled where used
constexpr frame_image image_of(const lane_plan& p, std::size_t w, std::size_t lead, std::size_t size,
                               const fixed_byte* fixed, std::size_t fixed_n, std::size_t n) noexcept {
    frame_image r{};
    const lane_window& win = p.win[w];
    const std::size_t len = win.length();
    const std::size_t d_size = lead + size, f0 = lead + win.at[0];
    const bool all = n < 64 && p.covered == (std::uint64_t{1} << n) - 1;
    if (!p.use || !all || p.words != 0 || (win.loads != 1 && win.loads != 2) || d_size < 16 || d_size > 32 ||
        f0 + len > d_size)
        return r;
    std::uint8_t c[32] = {};  // the frame, 0 at the fields' bytes
    if (lead) c[0] = static_cast<std::uint8_t>(size);
    for (std::size_t k = 0; k < fixed_n; ++k) {
        if (lead + fixed[k].offset >= f0 && lead + fixed[k].offset < f0 + len) return r;  // (never: lanes are fields)
        c[lead + fixed[k].offset] = fixed[k].value;
    }
    const std::size_t lo = f0 + len > 16 ? f0 + len - 16 : 0, hi = f0 < d_size - 16 ? f0 : d_size - 16;
    if (lo > hi) return r;
    r.at = hi;
    for (std::size_t at = hi + 1; at-- > lo;) {  // a store needing no OR, the last first
        bool zero = true;
        for (std::size_t j = at; j < at + 16; ++j) zero = zero && c[j] == 0;
        if (zero) {
            r.at = at;
            break;
        }
    }
    r.shift = static_cast<unsigned>(f0 - r.at);
    for (std::size_t j = 0; j < 16; ++j) r.add = (r.k[j] = c[r.at + j]) != 0 || r.add;
    const auto cover = [&](std::size_t u, std::size_t v) {  // [u, v) by words of 1, 2, 4 or 8 bytes
        while (u < v && r.words < 4) {
            const std::size_t left = v - u, wd = left > 4 ? 8 : left > 2 ? 4 : left;
            const std::size_t at = u + wd <= d_size ? u : d_size - wd;
            std::uint64_t word = 0;
            for (std::size_t j = wd; j-- > 0;) word = word << 8 | c[at + j];
            r.word_at[r.words] = at, r.word_size[r.words] = static_cast<unsigned>(wd), r.word[r.words++] = word;
            u = at + wd;
        }
        return u >= v;
    };
    r.use = cover(0, r.at) && cover(r.at + 16, d_size);
    return r;
}
template <class M, std::size_t W, std::size_t Lead>
inline constexpr frame_image image_v = image_of(lanes_v<M, true>, W, Lead, max_size_v<M>, table_v<M>.fixed.data(),
                                                fixed_count_v<M>, field_count_v<M>);
#if ROBOWIRE_SSE2
// Writes image I with the register x (window W's lanes) to d.
template <const frame_image& I, std::size_t... J>
ROBOWIRE_ALWAYS_INLINE void store_image(unsigned char* d, lane_bytes x, std::index_sequence<J...>) noexcept {
    for (std::size_t k = 0; k < I.words; ++k) {  // unrolled: constants
        if (I.word_size[k] == 8) std::memcpy(d + I.word_at[k], &I.word[k], 8);
        else if (I.word_size[k] == 4) {
            const auto v = static_cast<std::uint32_t>(I.word[k]);
            std::memcpy(d + I.word_at[k], &v, 4);
        } else if (I.word_size[k] == 2) {
            const auto v = static_cast<std::uint16_t>(I.word[k]);
            std::memcpy(d + I.word_at[k], &v, 2);
        } else {
            d[I.word_at[k]] = static_cast<unsigned char>(I.word[k]);
        }
    }
    lane_bytes y = __builtin_shufflevector(x, lane_bytes{}, (J >= I.shift ? J - I.shift : 16 + J)...);  // pslldq
    if constexpr (I.add) {
        lane_bytes k;
        std::memcpy(&k, I.k, 16);
        y |= k;
    }
    std::memcpy(d + I.at, &y, 16);
}
#endif

// Decode of a message whose every field is a lane of its test's register
// (one-byte fields; members in wire order from the first field's wire
// offset on, checked at run time): the lanes to move the register down so
// that it holds the message's bytes, or -1 (no such plan).
template <class M, std::size_t... I>
constexpr int decoded_image(std::index_sequence<I...>) noexcept {
    const lane_plan& p = lanes_v<M, false>;
    const lane_window& w = p.win[0];
    constexpr std::size_t n = sizeof...(I);
    if (!p.use || p.words != 0 || n >= 64 || p.covered != (std::uint64_t{1} << n) - 1 || w.loads == 0) return -1;
    const std::size_t len = w.length();
    const std::size_t offs[] = {field_v<M, I>.offset...}, count[] = {shape_t<M, I>::count...};
    std::size_t first = offs[0];
    for (std::size_t i = 0; i < n; ++i) {
        if (offs[i] < w.at[0] || offs[i] + count[i] > w.at[0] + len) return -1;
        first = offs[i] < first ? offs[i] : first;
    }
    return static_cast<int>(first - w.at[0]);
}
template <class M>
inline constexpr int decoded_image_v = decoded_image<M>(std::make_index_sequence<field_count_v<M>>{});
#if ROBOWIRE_SSE2
// Writes the message's bytes (decoded_image_v<M>) from `in` (checked by its
// test; the same load, which the compiler shares) as 16 bytes to `to`.
template <class M, std::size_t... J>
ROBOWIRE_ALWAYS_INLINE void store_decoded(unsigned char* to, const unsigned char* in,
                                          std::index_sequence<J...>) noexcept {
    constexpr const lane_plan& p = lanes_v<M, false>;
    constexpr std::size_t down = static_cast<std::size_t>(decoded_image_v<M>);
    const lane_bytes x = lanes_load<p, 0>(in, 0);
    const lane_bytes y = __builtin_shufflevector(x, lane_bytes{}, (J + down < 16 ? J + down : 16)...);  // psrldq
    std::memcpy(to, &y, 16);
}
#endif

// Codes of a one-byte enum whose codes are not one run, 1 where valid: one
// load in place of a range and a bit test (speed builds; 256 bytes).
template <class E>
inline constexpr auto enum_code_bytes_v = [] {
    std::array<std::uint8_t, 256> t{};
    for (const auto& entry : enum_table_v<E>)
        t[static_cast<std::uint8_t>(static_cast<std::underlying_type_t<E>>(entry.value))] = 1;
    return t;
}();
inline namespace ROBOWIRE_MODE_NAMESPACE {
// is_valid_enum, with that table where it takes fewer instructions.
template <class E>
ROBOWIRE_ALWAYS_INLINE constexpr bool valid_enum(E e) noexcept {
    if constexpr (!ROBOWIRE_OPTIMIZE_SIZE && sizeof(E) == 1 && !enum_code_run_v<E>.found) {
        if (!ROBOWIRE_CONSTANT_EVALUATED())
            return enum_code_bytes_v<E>[static_cast<std::uint8_t>(static_cast<std::underlying_type_t<E>>(e))] != 0;
    }
    return is_valid_enum(e);
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire::detail
