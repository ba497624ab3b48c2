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
        const std::size_t k = len_++;
        buf_[k] = b;
        if (k == frame_size - 1) {  // earlier positions were checked as they came
            if (b == end2) {
                len_ = 0;
                ++frames_;
                on_frame(frame_bytes(buf_.data(), frame_size));
            } else {
                resync();  // leaves a shorter candidate: never a whole frame
            }
        } else if ((k == 1 && b != start2) || (k == 8 && b != end1)) {
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
    // A chunk of 10 bytes or more: start_finder finds the start byte, frames
    // are checked and reported in place, and where start bytes are dense,
    // scan_words takes 8 positions at a time. Out of line: a caller's loop
    // that feeds one byte at a time stays small.
    template <class OnFrame>
    ROBOWIRE_NOINLINE constexpr void feed_chunk(const std::uint8_t* p, std::size_t n, OnFrame& on_frame) {
        std::size_t i = len_ != 0 ? finish_held(p, on_frame) : 0;  // the next position to look at
        std::size_t mark = i;  // bytes from mark up to the next frame or held candidate are skipped
        const std::size_t last = n - (frame_size - 1);  // a window starting here or later ends past the chunk
        start_finder starts{p, n};
        std::size_t at = p[i] == start1 ? i : starts.next(i);  // after a held frame, often the next one
        while (at < last) {
            i = at;  // a start byte
            if (rest_of_frame(p + i)) {
                skipped_ += i - mark;
                do {  // frames back to back: one check each, no search
                    ++frames_;
                    on_frame(frame_bytes(p + i, frame_size));
                    i += frame_size;
                } while (i < last && frame_at(p + i));
                mark = i;
                // the last 9 positions are looked at one by one below
                at = i < last ? (p[i] == start1 ? i : starts.next(i)) : i;
                continue;
            }
            ++false_starts_;
            at = starts.next(++i);
            if (words_ok && at - i < dense_gap && at < last) {  // start bytes close together: 8 positions a step
                skipped_ += at - mark;
                i = mark = scan_words(p, at, n, on_frame);
                at = i < last && p[i] == start1 ? i : starts.next(i);
            }
        }
        // The last 9 positions: their windows end past the chunk. Keep the
        // first candidate that can still become a frame.
        for (i = at; i < n; ++i) {
            if (p[i] != start1) continue;
            const std::size_t m = n - i;  // at most 9
            if ((m < 2 || p[i + 1] == start2) && (m < 9 || p[i + 8] == end1)) {
                len_ = m;
                codec::copy_small(buf_.data(), p + i, m);
                break;
            }
            ++false_starts_;
        }
        skipped_ += i - mark;
    }

    static constexpr std::size_t word = 8;        // positions per step of scan_words
    static constexpr std::size_t dense_gap = 16;  // a start byte this close after a false start: scan_words
    using word_t = std::uint64_t;
    static constexpr word_t lanes(std::uint8_t b) noexcept { return word_t{b} * 0x0101010101010101u; }

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
    // Index of the next start byte in p[from..n), or n.
    static constexpr std::size_t find_start(const std::uint8_t* p, std::size_t from, std::size_t n) noexcept {
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
#if ROBOWIRE_SSE2
            return find_start_sse2(p, from, n);
#else
            const void* hit = std::memchr(p + from, start1, n - from);
            return hit ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(hit) - p) : n;
#endif
        }
        while (from < n && p[from] != start1) ++from;
        return from;
    }
    // The next start byte at or after `from` (no less than the last call's),
    // in a chunk of n bytes: with SSE2 and n >= 64, from a mask of the start
    // bytes in 64 bytes, kept between calls; else find_start.
    struct start_finder {
        const std::uint8_t* p;
        std::size_t n;
        std::size_t base = n;    // bits covers p[base, base + 64); none yet
        std::uint64_t bits = 0;  // bit k: p[base + k] is a start byte
        ROBOWIRE_ALWAYS_INLINE constexpr std::size_t next(std::size_t from) noexcept {
#if ROBOWIRE_SSE2
            if (!ROBOWIRE_CONSTANT_EVALUATED() && n >= 64) {
                if (from - base < 64) {  // in the block of the last call
                    if (const std::uint64_t m = bits & (~std::uint64_t{0} << (from - base)); m != 0)
                        return base + first_bit(m);
                    from = base + 64;
                }
                const block b = find_block(p, from, n);  // a value: the state stays in registers
                base = b.base;
                bits = b.bits;
                return bits != 0 ? base + first_bit(bits) : n;
            }
#endif
            return find_start(p, from, n);
        }
    };
#if ROBOWIRE_SSE2
    struct block {
        std::size_t base;    // bits covers p[base, base + 64)
        std::uint64_t bits;  // bit k: p[base + k] is a start byte; 0: none from `from` to n
    };
    // The first 64 bytes from `from` (n >= 64) that hold a start byte, as a mask.
    static block find_block(const std::uint8_t* p, std::size_t from, std::size_t n) noexcept {
        for (; from <= n - 64; from += 64) {
            const v16 a = load16(p + from), b = load16(p + from + 16), c = load16(p + from + 32),
                      d = load16(p + from + 48);
            if (start_lanes(max16(max16(a, b), max16(c, d))) != 0) return {from, lanes64(a, b, c, d)};
        }
        if (from >= n) return {n, 0};
        const std::size_t base = n - 64;  // the last 64 bytes, from on
        return {base, lanes64(load16(p + base), load16(p + base + 16), load16(p + base + 32), load16(p + base + 48)) &
                          (~std::uint64_t{0} << (from - base))};
    }
    // SSE2 (inline; no call per start byte as with memchr).
    using v16 = unsigned char __attribute__((vector_size(16)));
    static v16 load16(const std::uint8_t* p) noexcept {
        v16 v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    static unsigned start_lanes(v16 v) noexcept {  // bit k: lane k holds a start byte
        using c16 = char __attribute__((vector_size(16)));
        return static_cast<unsigned>(__builtin_ia32_pmovmskb128((c16)(v == start1)));
    }
    static v16 max16(v16 a, v16 b) noexcept { return a > b ? a : b; }    // start1 is 0xFF: FF where either is
    static std::uint64_t lanes64(v16 a, v16 b, v16 c, v16 d) noexcept {  // bit k: lane k % 16 of the (k / 16)th
        return start_lanes(a) | std::uint64_t{start_lanes(b)} << 16 | std::uint64_t{start_lanes(c)} << 32 |
               std::uint64_t{start_lanes(d)} << 48;
    }
    static std::size_t first_bit(std::uint64_t m) noexcept { return static_cast<std::size_t>(std::countr_zero(m)); }
    // 16 bytes a step, then one 16-byte load that ends at n.
    static std::size_t find_start_sse2(const std::uint8_t* p, std::size_t from, std::size_t n) noexcept {
        if (n - from < 16) {
            while (from < n && p[from] != start1) ++from;
            return from;
        }
        for (; n - from >= 16; from += 16)
            if (const unsigned m = start_lanes(load16(p + from)); m != 0) return from + first_bit(m);
        const unsigned m = start_lanes(load16(p + n - 16)) >> (16 - (n - from));  // the last n - from bytes
        return m != 0 ? from + first_bit(m) : n;
    }
#endif
    static constexpr bool frame_at(const std::uint8_t* w) noexcept {  // the four markers, two words at run time
        if (!ROBOWIRE_CONSTANT_EVALUATED() &&
            (std::endian::native == std::endian::little || std::endian::native == std::endian::big)) {
            return load2(w) == pair(start1, start2) && load2(w + 8) == pair(end1, end2);
        }
        return w[0] == start1 && w[1] == start2 && w[8] == end1 && w[9] == end2;
    }
    static constexpr bool rest_of_frame(const std::uint8_t* w) noexcept { return frame_at(w); }  // after a start byte
    static std::uint16_t load2(const std::uint8_t* p) noexcept {
        std::uint16_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    static constexpr std::uint16_t pair(std::uint8_t first, std::uint8_t second) noexcept {  // as load2 reads them
        return static_cast<std::uint16_t>(std::endian::native == std::endian::little ? first | second << 8
                                                                                     : first << 8 | second);
    }
    // Eight positions at a time (where start bytes are dense, as in long
    // runs of FF or FF AA): from i, reports the frames and counts the other
    // start bytes as false starts, until 16 positions in a row hold no start
    // byte or a frame follows the last one directly (the caller checks such
    // frames one by one, more cheaply). Returns the position to go on from;
    // the bytes from i up to it in no frame are counted as skipped.
    static constexpr bool words_ok =
        std::endian::native == std::endian::little || std::endian::native == std::endian::big;
    template <class OnFrame>
    ROBOWIRE_NOINLINE constexpr std::size_t scan_words(const std::uint8_t* p, std::size_t i, std::size_t n,
                                                       OnFrame& on_frame) {
        constexpr word_t low7 = lanes(0x7F), high = lanes(0x80);
        std::size_t mark = i;
        bool reported = false, empty = false;
        while (i + word + frame_size - 1 <= n) {  // the windows of the 8 positions lie in the chunk
            const word_t w0 = load(p + i);
            const word_t ff = ((w0 & low7) + lanes(0x01)) & w0 & high;  // lanes holding FF
            if (ff == 0) {  // 16 positions without a start byte end the step
                i += word;
                if (empty) break;
                empty = true;
                continue;
            }
            empty = false;
            // a lane of z is 0 where ST2, EN1 and EN2 follow
            const word_t z =
                (load(p + i + 1) ^ lanes(start2)) | (load(p + i + 8) ^ lanes(end1)) | (load(p + i + 9) ^ lanes(end2));
            const word_t hit = ff & ~(((z & low7) + low7) | z);  // lanes where a frame starts
            if (hit == 0) {
                false_starts_ += count(ff);
                i += word;
                continue;
            }
            const std::size_t k = first_lane(hit);
            if (k == 0 && reported && i == mark) break;  // frames back to back: the caller's loop takes them
            false_starts_ += count(ff & before(k));
            i += k;
            skipped_ += i - mark;
            ++frames_;
            on_frame(frame_bytes(p + i, frame_size));
            i += frame_size;
            mark = i;
            reported = true;
        }
        skipped_ += i - mark;
        return i;
    }
    // 8 bytes in host order (lane k: the byte at p + k).
    static constexpr word_t load(const std::uint8_t* p) noexcept {
        word_t w = 0;
        if (ROBOWIRE_CONSTANT_EVALUATED()) {
            for (std::size_t k = 0; k < word; ++k)
                w |= word_t{p[k]} << (std::endian::native == std::endian::little ? 8 * k : 56 - 8 * k);
        } else {
            std::memcpy(&w, p, sizeof w);
        }
        return w;
    }
    // Lanes are marked by their high bit.
    static constexpr std::size_t first_lane(word_t m) noexcept {
        return static_cast<std::size_t>(std::endian::native == std::endian::little ? std::countr_zero(m)
                                                                                   : std::countl_zero(m)) /
               8;
    }
    static constexpr word_t before(std::size_t k) noexcept {  // the lanes before lane k
        return std::endian::native == std::endian::little ? (word_t{1} << (8 * k)) - 1 : ~(~word_t{0} >> (8 * k));
    }
    static constexpr std::uint64_t count(word_t m) noexcept { return ((m >> 7) * lanes(1)) >> 56; }

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
