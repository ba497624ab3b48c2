// robowire/navbot/multiframe.hpp - messages longer than one frame: a
// fragmenter (no copy, no heap) and a caller-owned reassembler.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "frame.hpp"

namespace robowire::navbot {

// `remaining` is one byte: a message has at most 256 frames (3840 payload bytes).
inline constexpr std::size_t max_frames = 256;
inline constexpr std::size_t max_payload = max_frames * payload_size;

// Number of frames for `n` payload bytes (an empty payload still takes one frame).
constexpr std::size_t frames_for(std::size_t n) noexcept { return n == 0 ? 1 : (n + payload_size - 1) / payload_size; }

// The frames of one message. Holds a view of the payload (keep it alive);
// frames are built on demand. `remaining` counts down to 0, the last frame
// is zero-padded, every frame carries the same command.
// Byte is std::uint8_t (binary payloads) or char (text).
template <class Byte>
class basic_fragmenter {
public:
    // capacity_exceeded if the payload needs more than 256 frames.
    static constexpr result<basic_fragmenter> make(std::uint8_t command, std::span<const Byte> payload) noexcept {
        if (payload.size() > max_payload) return fail(errc::capacity_exceeded, max_payload);
        return basic_fragmenter(command, payload);
    }
    constexpr basic_fragmenter() noexcept = default;

    constexpr std::size_t size() const noexcept { return frames_for(payload_.size()); }
    // Frame i (0-based). Precondition: i < size().
    constexpr bytes<frame_size> operator[](std::size_t i) const noexcept {
        auto out = bytes<frame_size>::zeros(frame_size);
        out[0] = header1;
        out[1] = header2;
        out[2] = command_;
        out[3] = static_cast<std::uint8_t>(size() - 1 - i);
        const std::size_t from = i * payload_size;
        for (std::size_t k = 0; k < payload_size && from + k < payload_.size(); ++k) out[5 + k] = static_cast<std::uint8_t>(payload_[from + k]);
        return out;
    }

    class iterator {
    public:
        using value_type = bytes<frame_size>;
        using difference_type = std::ptrdiff_t;
        constexpr iterator() noexcept = default;
        constexpr iterator(const basic_fragmenter* f, std::size_t i) noexcept : f_(f), i_(i) {}
        constexpr value_type operator*() const noexcept { return (*f_)[i_]; }
        constexpr iterator& operator++() noexcept { ++i_; return *this; }
        constexpr iterator operator++(int) noexcept { auto t = *this; ++i_; return t; }
        friend constexpr bool operator==(const iterator& a, const iterator& b) noexcept { return a.i_ == b.i_; }

    private:
        const basic_fragmenter* f_ = nullptr;
        std::size_t i_ = 0;
    };
    constexpr iterator begin() const noexcept { return {this, 0}; }
    constexpr iterator end() const noexcept { return {this, size()}; }

private:
    constexpr basic_fragmenter(std::uint8_t command, std::span<const Byte> payload) noexcept
        : command_(command), payload_(payload) {}
    std::uint8_t command_ = 0;
    std::span<const Byte> payload_{};
};
using fragmenter = basic_fragmenter<std::uint8_t>;
using text_fragmenter = basic_fragmenter<char>;

// Frames of a binary payload (e.g. command::wifi).
constexpr result<fragmenter> make_frames(std::uint8_t command, std::span<const std::uint8_t> payload) noexcept {
    return fragmenter::make(command, payload);
}
// Frames of a JSON request (command 0x02). The text is sent as is (no NUL).
constexpr result<text_fragmenter> json_frames(std::string_view text) noexcept {
    return text_fragmenter::make(command::json, {text.data(), text.size()});
}

// What reassembler::push says about a frame.
enum class reassembly : std::uint8_t {
    need_more,  // part of a message; more frames to come
    complete,   // the message is complete: command(), payload(), text()
    discarded,  // dropped: part of a message already broken by an error
};

// Collects the frames of one message at a time, up to Capacity payload
// bytes (use a multiple of 15). Fixed size, owned by the caller.
//
// push() errors, each with the frame byte it is about:
//  - bad_header, too_short, too_long: not a frame; the state does not change.
//  - command_changed (2): a continuation frame carries another command.
//  - bad_sequence (3): `remaining` did not go down by one (a frame was lost
//    or the sender started over).
//  - capacity_exceeded (5): the message is longer than Capacity.
// After one of the last three, the partial message is dropped, and so are
// the frames after it up to the end of the broken message (the next frame
// with remaining 0; push says `discarded`); then a new message starts.
template <std::size_t Capacity>
class reassembler {
public:
    constexpr result<reassembly> push(std::span<const std::uint8_t> frame_bytes) noexcept {
        const auto f = robowire::decode<frame>(frame_bytes);
        if (!f) return f.error();
        return push(*f);
    }

    constexpr result<reassembly> push(const frame& f) noexcept {
        switch (state_) {
        case state::complete: clear(); [[fallthrough]];
        case state::idle:
            command_ = f.command;
            size_ = 0;
            return append(f);
        case state::discarding:
            if (f.remaining == 0) clear();
            return reassembly::discarded;
        case state::collecting:
            if (f.command != command_) return drop(f, errc::command_changed, 2);
            if (f.remaining + 1 != last_remaining_) return drop(f, errc::bad_sequence, 3);
            return append(f);
        }
        return reassembly::discarded;
    }

    // The completed message (valid after push returned `complete`, until the next push).
    constexpr std::uint8_t command() const noexcept { return command_; }
    // Payload bytes so far, with the last frame's zero padding (the wire does not carry the length).
    constexpr std::span<const std::uint8_t> payload() const noexcept { return {buf_.data(), size_}; }
    // The payload as text (e.g. a JSON reply), without the trailing zero padding.
    std::string_view text() const noexcept {
        std::size_t n = size_;
        while (n > 0 && buf_[n - 1] == 0) --n;
        return {reinterpret_cast<const char*>(buf_.data()), n};  // char may view any object's bytes
    }
    constexpr bool in_progress() const noexcept { return state_ == state::collecting; }
    static constexpr std::size_t capacity() noexcept { return Capacity; }
    // Drops any partial message.
    constexpr void clear() noexcept {
        state_ = state::idle;
        size_ = 0;
    }

private:
    enum class state : std::uint8_t { idle, collecting, complete, discarding };

    constexpr result<reassembly> append(const frame& f) noexcept {
        if (Capacity - size_ < payload_size) return drop(f, errc::capacity_exceeded, 5);
        for (std::size_t i = 0; i < payload_size; ++i) buf_[size_ + i] = f.payload[i];
        size_ += payload_size;
        last_remaining_ = f.remaining;
        state_ = f.remaining == 0 ? state::complete : state::collecting;
        return f.remaining == 0 ? reassembly::complete : reassembly::need_more;
    }
    constexpr result<reassembly> drop(const frame& f, errc code, std::size_t offset) noexcept {
        size_ = 0;
        state_ = f.remaining == 0 ? state::idle : state::discarding;
        return fail(code, offset);
    }

    std::array<std::uint8_t, Capacity> buf_{};
    std::size_t size_ = 0;
    std::uint8_t last_remaining_ = 0;  // `remaining` of the last frame taken
    std::uint8_t command_ = 0;
    state state_ = state::idle;
};

}  // namespace robowire::navbot
