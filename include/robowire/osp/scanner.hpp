// robowire/osp/scanner.hpp - finds OSP frames in a noisy byte stream.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
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
    // span is valid during the call only.
    template <class OnFrame>
    constexpr void feed(std::span<const std::uint8_t> chunk, OnFrame&& on_frame) {
        const std::uint8_t* p = chunk.data();
        const std::size_t n = chunk.size();
        if (!ROBOWIRE_OPTIMIZE_SIZE && n == 1) return push_byte(p[0], on_frame);  // one test, no loop to enter
        if (ROBOWIRE_OPTIMIZE_SIZE || n < frame_size) {  // short chunks (a UART's few bytes per read): byte by byte
            for (std::size_t k = 0; k < n; ++k) push_byte(p[k], on_frame);
            return;
        }
        std::size_t i = 0;
        while (i < n) {
            if (len_ != 0) {  // a partial candidate: complete it in one go if the chunk has the rest
                const std::size_t had = len_, need = frame_size - had;
                if (n - i >= need) {
                    codec::copy_small(buf_.data() + had, p + i, need);
                    if (buf_[1] == start2 && buf_[8] == end1 && buf_[9] == end2) {
                        len_ = 0;
                        ++frames_;
                        i += need;
                        on_frame(frame_bytes(buf_.data(), frame_size));
                        continue;
                    }
                }
                push_byte(p[i++], on_frame);
                continue;
            }
            if (p[i] != start1) {  // skip noise up to the next start byte
                const std::size_t start = find_start(p, i + 1, n);
                skipped_ += start - i;
                i = start;
                if (i == n) break;
            }
            if (n - i < frame_size) {  // a short tail from a start byte: kept whole as the partial candidate
                len_ = n - i;
                codec::copy_small(buf_.data(), p + i, len_);
                if (!partial_ok()) resync();
                break;
            }
            if (p[i + 1] == start2 && p[i + 8] == end1 && p[i + 9] == end2) {  // a whole frame in the chunk
                ++frames_;
                on_frame(frame_bytes(p + i, frame_size));
                i += frame_size;
            } else {  // false start: resume at the next byte
                ++false_starts_;
                ++skipped_;
                ++i;
            }
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
    // Index of the next start byte in p[from..n), or n.
    static constexpr std::size_t find_start(const std::uint8_t* p, std::size_t from, std::size_t n) noexcept {
        if (from >= n) return n;
        if (!std::is_constant_evaluated()) {
            const void* hit = std::memchr(p + from, start1, n - from);
            return hit ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(hit) - p) : n;
        }
        while (from < n && p[from] != start1) ++from;
        return from;
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
            for (std::size_t k = from; k < len_; ++k) buf_[k - from] = buf_[k];
            len_ -= from;
            if (partial_ok()) return;
        }
    }

    std::array<std::uint8_t, frame_size> buf_{};
    std::size_t len_ = 0;
    std::uint64_t frames_ = 0, skipped_ = 0, false_starts_ = 0;
};

}  // namespace robowire::osp::inline ROBOWIRE_MODE_NAMESPACE
