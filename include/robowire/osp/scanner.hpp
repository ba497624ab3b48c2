// robowire/osp/scanner.hpp - finds OSP frames in a noisy byte stream.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <type_traits>

#include "frame.hpp"

// A type of the inline namespace of the size settings (config.hpp): its
// feed() depends on ROBOWIRE_OPTIMIZE_SIZE.
namespace robowire::osp::inline ROBOWIRE_MODE_NAMESPACE {

// Fixed-size stream scanner: feed bytes in chunks of any size (one at a time
// is fine); every frame with the right markers (FF AA .. 55 77) is reported
// byte-exact, whatever the chunking. After a false start it resumes at the
// next byte, so a valid frame that overlaps a failed candidate is never lost.
// A reported frame is consumed whole. State: at most one partial frame.
class scanner {
public:
    using frame_bytes = std::span<const std::uint8_t, frame_size>;

    // Feeds `chunk`; calls on_frame(frame_bytes) for each frame found. The
    // span is valid during the call only; the counters are up to date in it.
    template <class OnFrame>
    constexpr void feed(std::span<const std::uint8_t> chunk, OnFrame&& on_frame) {
        const std::uint8_t* p = chunk.data();
        const std::size_t n = chunk.size();
        if (!ROBOWIRE_OPTIMIZE_SIZE && n == 1) return push_byte(p[0], on_frame);  // one test, no loop to enter
        if (ROBOWIRE_OPTIMIZE_SIZE || n < frame_size) {  // short chunks (a UART's few bytes per read): byte by byte
            for (std::size_t k = 0; k < n; ++k) push_byte(p[k], on_frame);
            return;
        }
        if constexpr (!std::is_lvalue_reference_v<OnFrame> && std::is_trivially_copyable_v<OnFrame>) {
            // A temporary's copy, made here: a caller's loop need not keep the callback in memory for the byte paths.
            std::remove_cv_t<OnFrame> local = on_frame;
            feed_chunk(p, n, local);
        } else {
            feed_chunk(p, n, on_frame);
        }
    }

    // Pushes one byte; returns the frame it completes, if any.
    constexpr std::optional<std::array<std::uint8_t, frame_size>> push(std::uint8_t b) noexcept {
        std::optional<std::array<std::uint8_t, frame_size>> out;
        push_byte(b, [&](frame_bytes f) {
            out.emplace();
            for (std::size_t k = 0; k < frame_size; ++k) (*out)[k] = f[k];
        });
        return out;
    }

    // Pushes one byte; calls on_frame(frame_bytes) if it completes a frame.
    template <class OnFrame>
    constexpr void push_byte(std::uint8_t b, OnFrame&& on_frame) {
        if (len_ == 0) {
            if (b == start1) buf_[len_++] = b;
            else ++skipped_;
            return;
        }
        const std::size_t k = len_;
        buf_[k] = b;
        len_ = k + 1;               // after the byte: not reloaded below
        if (k == frame_size - 1) {  // earlier positions were checked as they came
            if (b == end2) {
                len_ = 0;
                ++frames_;
                on_frame(frame_bytes(buf_.data(), frame_size));
            } else {
                resync();  // leaves a shorter candidate: never a whole frame
            }
        } else if (k == 1) {
            if (b != start2) resync();
        } else if (k == 8 && b != end1) {
            resync();
        }
    }

    constexpr std::uint64_t frames() const noexcept { return frames_; }              // frames reported
    constexpr std::uint64_t skipped() const noexcept { return skipped_; }            // bytes not in any frame
    constexpr std::uint64_t false_starts() const noexcept { return false_starts_; }  // candidates abandoned
    constexpr std::size_t pending() const noexcept { return len_; }                  // bytes of a partial candidate
    // Forgets the partial candidate and the counters.
    constexpr void reset() noexcept { *this = scanner{}; }

private:
    // A chunk of 10 bytes or more: masks of the start bytes over 64 or 16
    // positions a step, and of whole frames where a start byte is no frame.
    // Out of line: a caller's loop that feeds one byte at a time stays small.
    template <class OnFrame>
    ROBOWIRE_NOINLINE constexpr void feed_chunk(const std::uint8_t* p, std::size_t n, OnFrame& on_frame) {
        std::size_t i = len_ != 0 ? finish_held(p, on_frame) : 0;  // the next position to look at
        std::size_t mark = i;  // bytes from mark up to the next frame or held candidate are skipped
        const std::size_t last = n - (frame_size - 1);  // a window starting here or later ends past the chunk
        if (i < last && frame_at(p + i)) i = frames_from(p, i, last, mark, on_frame);  // often after a held frame
        while (i + 64 <= last) i = block<64>(p, i, starts64(p + i), last, mark, on_frame);
        if (i + 32 <= last && i + 64 >= n && equal_mask<16>(p + i, start1) == 0) {  // none in 16: any left?
            i += 16;
            if (!any_start(p, i, n)) {
                skipped_ += n - mark;
                return;
            }
        }
        while (i < last) {
            if (i + 16 <= last) {
                i = block<16>(p, i, equal_mask<16>(p + i, start1), last, mark, on_frame);
            } else if (n >= 25) {  // the 16 positions that end at last, those before i dropped
                const std::size_t base = last - 16;
                i = block<16, false>(p, base, equal_mask<16>(p + base, start1) >> (i - base) << (i - base), last, mark,
                                     on_frame);
            } else if (p[i] != start1) {
                ++i;
            } else if (frame_at(p + i)) {
                i = frames_from(p, i, last, mark, on_frame);
            } else {
                ++false_starts_;
                ++i;
            }
        }
        // The last 9 positions (and those of a frame that ends in them): the
        // first candidate that can still become a frame is held.
        const auto hold = [&](std::size_t at) {
            len_ = n - at;
            codec::copy_small(buf_.data(), p + at, n - at);
            skipped_ += at - mark;
        };
        if (i < n && p[i] == start1 && tail_ok(p, i, n)) return hold(i);
        if (i < n && n >= 16) {  // masks of the last 16 bytes: start bytes, and those followed by ST2
            const std::size_t base = n - 16, from = i - base;                  // from: 7 or more
            const std::uint64_t s = equal_mask<16>(p + base, start1) >> from;  // 9 bits at most
            if (s != 0 && tail_ok(p, i + first_bit(s), n)) return hold(i + first_bit(s));
            if (s != 0) {
                std::uint64_t ok =
                    s & (equal_mask<16>(p + base, start2) >> (from + 1) | std::uint64_t{1} << (15 - from));
                if (p[n - 1] != end1) ok &= ~(std::uint64_t{1} << 7 >> from);  // at last, EN1 is there too
                false_starts_ +=
                    bits9<>.n[static_cast<std::size_t>(ok != 0 ? s & ((std::uint64_t{1} << first_bit(ok)) - 1) : s)];
                if (ok != 0) return hold(i + first_bit(ok));
            }
        } else {
            for (; i < n; ++i) {
                if (p[i] != start1) continue;
                if (tail_ok(p, i, n)) return hold(i);
                ++false_starts_;
            }
        }
        skipped_ += n - mark;
    }

    // Frames back to back from the start byte at p[i], one check each; the
    // bytes from mark to i are skipped. Returns the position to go on from.
    template <class OnFrame>
    constexpr std::size_t frames_from(const std::uint8_t* p, std::size_t i, std::size_t last, std::size_t& mark,
                                      OnFrame& on_frame) {
        skipped_ += i - mark;
        do {
            ++frames_;
            on_frame(frame_bytes(p + i, frame_size));
            i += frame_size;
        } while (i < last && frame_at(p + i));
        mark = i;
        return i;
    }
    // The start bytes s of positions [base, base + W) (none before the one
    // to go on from): the first frame there is reported with those after it,
    // the start bytes before it are false starts. Returns where to go on.
    template <std::size_t W, bool All = true, class OnFrame>  // All: s holds every start byte there
    ROBOWIRE_ALWAYS_INLINE constexpr std::size_t block(const std::uint8_t* p, std::size_t base, std::uint64_t s,
                                                       std::size_t last, std::size_t& mark, OnFrame& on_frame) {
        if (s == 0) return base + W;
        std::size_t k = first_bit(s);
        if (!frame_at(p + base + k)) {
            if ((s & (s - 1)) == 0) {  // a lone false start
                ++false_starts_;
                return base + W;
            }
            const std::uint64_t f = frames_mask<W>(p + base) & s;
            if (f == 0) {
                false_starts_ += All ? count_starts<W>(p + base, s) : popcount(s);
                return base + W;
            }
            k = first_bit(f);
            false_starts_ += popcount(s & ((std::uint64_t{1} << k) - 1));
        }
        return frames_from(p, base + k, last, mark, on_frame);
    }
    // Can a candidate at p[at] (n - at < 10 bytes to the chunk's end) still become a frame.
    static constexpr bool tail_ok(const std::uint8_t* p, std::size_t at, std::size_t n) noexcept {
        return (n - at < 2 || p[at + 1] == start2) && (n - at < 9 || p[at + 8] == end1);
    }

    // The held candidate and the chunk's first 9 bytes, which complete every
    // window that starts in the held bytes: reports the first frame there or
    // drops the held bytes. Returns the position in the chunk to go on from.
    template <class OnFrame>
    constexpr std::size_t finish_held(const std::uint8_t* p, OnFrame& on_frame) {
        const std::size_t held = len_;
        std::array<std::uint8_t, 2 * frame_size - 1> c;  // every byte read is written
        codec::copy_small(c.data(), buf_.data(), frame_size);
        codec::copy_small(c.data() + held, p, frame_size - 1);
        len_ = 0;
        for (std::size_t q = 0; q < held; ++q) {
            if (c[q] != start1) continue;
            if (frame_at(c.data() + q)) {
                skipped_ += q;
                ++frames_;
                on_frame(frame_bytes(c.data() + q, frame_size));
                return q + frame_size - held;
            }
            ++false_starts_;
        }
        skipped_ += held;
        return 0;
    }

    // Masks over W positions (16 or 64): bit k for p + k.
    template <std::size_t W>  // p[k] == b
    static constexpr std::uint64_t equal_mask(const std::uint8_t* p, std::uint8_t b) noexcept {
        std::uint64_t m = 0;
#if ROBOWIRE_SSE2
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            for (std::size_t k = 0; k < W; k += 16) m |= std::uint64_t{mask16(load16(p + k) == b)} << k;
            return m;
        }
#endif
        for (std::size_t k = 0; k < W; k += 8) m |= zeros8(le8(p + k) ^ lanes(b)) << k;
        return m;
    }
    template <std::size_t W>  // a frame at p + k (reads p[0, W + 9))
    static constexpr std::uint64_t frames_mask(const std::uint8_t* p) noexcept {
#if ROBOWIRE_SSE2
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            std::uint64_t m = 0;
            for (std::size_t k = 0; k < W; k += 16)
                m |= std::uint64_t{mask16((load16(p + k) == start1) & (load16(p + k + 1) == start2) &
                                          (load16(p + k + 8) == end1) & (load16(p + k + 9) == end2))}
                     << k;
            return m;
        }
#endif
        return equal_mask<W>(p, start1) & equal_mask<W>(p + 1, start2) & equal_mask<W>(p + 8, end1) &
               equal_mask<W>(p + 9, end2);
    }
    template <std::size_t W>  // the bits of s, the start bytes of p[0, W)
    static constexpr std::uint64_t count_starts([[maybe_unused]] const std::uint8_t* p, std::uint64_t s) noexcept {
#if ROBOWIRE_SSE2
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            v16 t{};  // lane k: the start bytes at p[k + 16 j]
            for (std::size_t k = 0; k < W; k += 16) t -= reinterpret_cast<v16>(load16(p + k) == start1);
            const auto sums = __builtin_ia32_psadbw128(reinterpret_cast<c16>(t), c16{});
            return static_cast<std::uint64_t>(sums[0] + sums[1]);
        }
#endif
        return popcount(s);
    }
    static constexpr std::uint64_t starts64(const std::uint8_t* p) noexcept {
#if ROBOWIRE_SSE2  // start1 is 0xFF, the largest byte: none in the 64 if none in their maximum
        if (!ROBOWIRE_CONSTANT_EVALUATED() &&
            mask16(max16(max16(load16(p), load16(p + 16)), max16(load16(p + 32), load16(p + 48))) == start1) == 0)
            return 0;
#endif
        return equal_mask<64>(p, start1);
    }
    // Any start byte in p[i, n), n - i in [16, 64].
    static constexpr bool any_start(const std::uint8_t* p, std::size_t i, std::size_t n) noexcept {
        const std::size_t e = n - 16, b = i + 16 < e ? i + 16 : e, c = i + 32 < e ? i + 32 : e;
#if ROBOWIRE_SSE2
        if (!ROBOWIRE_CONSTANT_EVALUATED())
            return mask16(max16(max16(load16(p + i), load16(p + b)), max16(load16(p + c), load16(p + e))) == start1) !=
                   0;
#endif
        return (equal_mask<16>(p + i, start1) | equal_mask<16>(p + b, start1) | equal_mask<16>(p + c, start1) |
                equal_mask<16>(p + e, start1)) != 0;
    }
#if ROBOWIRE_SSE2
    using v16 = unsigned char __attribute__((vector_size(16)));
    using c16 = char __attribute__((vector_size(16)));
    static v16 load16(const std::uint8_t* p) noexcept {
        v16 v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    template <class V>
    static unsigned mask16(V v) noexcept {  // bit k: lane k is all ones
        return static_cast<unsigned>(__builtin_ia32_pmovmskb128(reinterpret_cast<c16>(v)));
    }
    static v16 max16(v16 a, v16 b) noexcept { return a > b ? a : b; }
#endif
    // 8 bytes, p[k] in byte k; bit k of zeros8: byte k is 0.
    static constexpr std::uint64_t le8(const std::uint8_t* p) noexcept {
        std::uint64_t w = 0;
        for (std::size_t k = 0; k < 8; ++k) w |= std::uint64_t{p[k]} << 8 * k;
        return w;
    }
    static constexpr std::uint64_t lanes(std::uint8_t b) noexcept { return b * std::uint64_t{0x0101010101010101u}; }
    static constexpr std::uint64_t zeros8(std::uint64_t x) noexcept {
        const std::uint64_t high = ~(((x & lanes(0x7F)) + lanes(0x7F)) | x) & lanes(0x80);  // exact: no carries
        return (high >> 7) * 0x0102040810204080u >> 56;
    }
    static constexpr std::uint64_t popcount(std::uint64_t x) noexcept {  // no POPCNT instruction needed
        x -= (x >> 1) & lanes(0x55);
        x = (x & lanes(0x33)) + ((x >> 2) & lanes(0x33));
        return ((x + (x >> 4)) & lanes(0x0F)) * lanes(1) >> 56;
    }
    struct bit_counts {  // a plain array: each call of std::array's operator[] costs g++ compile memory
        std::uint8_t n[512];
    };
    template <class = void>  // bits set in each 9-bit value (made where a chunk is scanned)
    static constexpr bit_counts bits9 = [] {
        bit_counts t{};
        for (std::size_t v = 1; v < 512; ++v) t.n[v] = static_cast<std::uint8_t>(t.n[v & (v - 1)] + 1);
        return t;
    }();
    static constexpr std::size_t first_bit(std::uint64_t m) noexcept {
        return static_cast<std::size_t>(std::countr_zero(m));
    }
    static constexpr bool frame_at(const std::uint8_t* w) noexcept {  // the four markers, two words at run time
        if (!ROBOWIRE_CONSTANT_EVALUATED() &&
            (std::endian::native == std::endian::little || std::endian::native == std::endian::big)) {
            return load2(w) == pair(start1, start2) && load2(w + 8) == pair(end1, end2);
        }
        return w[0] == start1 && w[1] == start2 && w[8] == end1 && w[9] == end2;
    }
    static std::uint16_t load2(const std::uint8_t* p) noexcept {
        std::uint16_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    static constexpr std::uint16_t pair(std::uint8_t first, std::uint8_t second) noexcept {  // as load2 reads them
        return static_cast<std::uint16_t>(std::endian::native == std::endian::little ? first | second << 8
                                                                                     : first << 8 | second);
    }

    // Can the partial candidate (shorter than a frame, starting with ST1)
    // still become a frame: its ST2 and EN1, where it has them.
    constexpr bool partial_ok() const noexcept {
        return (len_ < 2 || buf_[1] == start2) && (len_ < 9 || buf_[8] == end1);
    }
    // The candidate failed: drop its first byte and resume at the next start
    // byte, until what is left can still become a frame.
    constexpr void resync() noexcept {
        for (;;) {
            ++false_starts_;
            std::size_t from = 1;
            while (from < len_ && buf_[from] != start1) ++from;
            skipped_ += from;  // the dropped bytes
            if (!ROBOWIRE_OPTIMIZE_SIZE && !ROBOWIRE_CONSTANT_EVALUATED()) {
                if (from != len_) {  // bytes left: fixed-size copies, read first
                    std::uint64_t lo;
                    std::uint16_t hi;
                    std::memcpy(&lo, buf_.data() + from, sizeof lo);
                    std::memcpy(&hi, buf_.data() + from + sizeof lo, sizeof hi);
                    std::memcpy(buf_.data(), &lo, sizeof lo);
                    std::memcpy(buf_.data() + sizeof lo, &hi, sizeof hi);
                }
            } else {
                for (std::size_t k = from; k < len_; ++k) buf_[k - from] = buf_[k];
            }
            len_ -= from;
            if (partial_ok()) return;
        }
    }

    // The candidate, and room for resync()'s fixed-size copies (from
    // buf_[9] at most, 10 bytes) where they are used.
    std::array<std::uint8_t, ROBOWIRE_OPTIMIZE_SIZE ? frame_size : 2 * frame_size - 1> buf_{};
    std::size_t len_ = 0;
    std::uint64_t frames_ = 0, skipped_ = 0, false_starts_ = 0;
};

}  // namespace robowire::osp::inline ROBOWIRE_MODE_NAMESPACE
