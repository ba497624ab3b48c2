// robowire/osp/scanner.hpp - finds OSP frames in a noisy byte stream.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "frame.hpp"

namespace robowire::osp {

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
        std::size_t i = 0;
        while (i < n) {
            if (len_ != 0) {  // finish the partial candidate first
                if (auto f = push(p[i++])) on_frame(frame_bytes(f->data(), frame_size));
                continue;
            }
            // Fast path: search the chunk itself for a start byte.
            std::size_t j = i;
            while (j < n && p[j] != start1) ++j;
            skipped_ += j - i;
            i = j;
            if (i == n) break;
            if (n - i < frame_size) {  // not enough left: keep the tail as a candidate
                while (i < n)
                    if (auto f = push(p[i++])) on_frame(frame_bytes(f->data(), frame_size));
                break;
            }
            if (p[i + 1] == start2 && p[i + 8] == end1 && p[i + 9] == end2) {
                ++frames_;
                on_frame(frame_bytes(p + i, frame_size));
                i += frame_size;
            } else {
                ++false_starts_;
                ++skipped_;
                ++i;
            }
        }
    }

    // Pushes one byte; returns the frame it completes, if any.
    constexpr std::optional<std::array<std::uint8_t, frame_size>> push(std::uint8_t b) noexcept {
        if (len_ == 0) {
            if (b == start1) buf_[len_++] = b;
            else ++skipped_;
            return std::nullopt;
        }
        buf_[len_++] = b;
        if (!prefix_ok(len_ - 1)) resync();
        if (len_ == frame_size) {
            len_ = 0;
            ++frames_;
            return buf_;
        }
        return std::nullopt;
    }

    constexpr std::uint64_t frames() const noexcept { return frames_; }          // frames reported
    constexpr std::uint64_t skipped() const noexcept { return skipped_; }        // bytes not in any frame
    constexpr std::uint64_t false_starts() const noexcept { return false_starts_; }  // candidates abandoned
    constexpr std::size_t pending() const noexcept { return len_; }              // bytes of a partial candidate
    // Forgets the partial candidate and the counters.
    constexpr void reset() noexcept { *this = scanner{}; }

private:
    // Is buf_[k] what a frame has at position k (start and end markers)?
    constexpr bool prefix_ok(std::size_t k) const noexcept {
        switch (k) {
        case 0: return buf_[0] == start1;
        case 1: return buf_[1] == start2;
        case 8: return buf_[8] == end1;
        case 9: return buf_[9] == end2;
        default: return true;
        }
    }
    // The candidate failed: drop its first byte and resume at the next start byte.
    constexpr void resync() noexcept {
        ++false_starts_;
        std::size_t from = 1;
        for (;;) {
            while (from < len_ && buf_[from] != start1) ++from;
            skipped_ += from;  // the dropped bytes
            for (std::size_t k = from; k < len_; ++k) buf_[k - from] = buf_[k];
            len_ -= from;
            bool ok = true;
            for (std::size_t k = 0; k < len_ && ok; ++k) ok = prefix_ok(k);
            if (ok) return;
            ++false_starts_;
            from = 1;
        }
    }

    std::array<std::uint8_t, frame_size> buf_{};
    std::size_t len_ = 0;
    std::uint64_t frames_ = 0, skipped_ = 0, false_starts_ = 0;
};

}  // namespace robowire::osp
