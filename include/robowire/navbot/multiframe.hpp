// robowire/navbot/multiframe.hpp - messages longer than one frame: a
// fragmenter (no copy, no heap) and a caller-owned reassembler.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>

#include "frame.hpp"

namespace robowire::navbot {

// `remaining` is one byte: a message has at most 256 frames (3840 payload bytes).
inline constexpr std::size_t max_frames = 256;
inline constexpr std::size_t max_payload = max_frames * payload_size;

// Number of frames for `n` payload bytes (an empty payload still takes one frame).
constexpr std::size_t frames_for(std::size_t n) noexcept { return n == 0 ? 1 : (n + payload_size - 1) / payload_size; }

// The fragmenter and the reassembler are types of the inline namespace of the
// size settings (config.hpp): their code depends on ROBOWIRE_OPTIMIZE_SIZE.
inline namespace ROBOWIRE_MODE_NAMESPACE {
// The frames of one message. Holds a view of the payload (keep it alive);
// frames are built on demand. `remaining` counts down to 0, the last frame
// is zero-padded, every frame carries the same command.
// Byte is std::uint8_t (binary payloads) or char (text).
template <class Byte>
class basic_fragmenter {
    // A bytes<20> is its size (one byte), then its bytes, and words are
    // little-endian: a frame's size and first bytes are stored as one word.
    static constexpr bool head_fits() noexcept {
        return std::endian::native == std::endian::little && bytes<frame_size>::size_byte_then_data();
    }
    static constexpr bool head_store = !ROBOWIRE_OPTIMIZE_SIZE && head_fits();

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
        const std::size_t from = i * payload_size;
        return make_frame(command_, static_cast<std::uint8_t>(size() - 1 - i), payload_.data() + from,
                          from < payload_.size() ? payload_.size() - from : 0);
    }

    // An iterator holds its own position and the frame's first bytes (not a
    // pointer to the fragmenter): a loop that hands each frame to a driver
    // keeps them in registers. Frames one byte at a time (ROBOWIRE_OPTIMIZE_SIZE):
    class frame_iterator {
    public:
        using value_type = bytes<frame_size>;
        using difference_type = std::ptrdiff_t;
        constexpr frame_iterator() noexcept = default;
        constexpr value_type operator*() const noexcept {
            return make_frame(command_, static_cast<std::uint8_t>(frames_ - 1), end_ - left_, left_);
        }
        constexpr frame_iterator& operator++() noexcept {
            left_ -= payload_size;  // wraps past the last frame, where only frames_ is read
            --frames_;
            return *this;
        }
        constexpr frame_iterator operator++(int) noexcept {
            auto t = *this;
            ++*this;
            return t;
        }
        friend constexpr bool operator==(const frame_iterator& a, const frame_iterator& b) noexcept {
            return a.frames_ == b.frames_;
        }

    private:
        friend class basic_fragmenter;
        constexpr frame_iterator(const Byte* end, std::size_t left, std::size_t frames, std::uint8_t command) noexcept
            : end_(end), left_(left), frames_(frames), command_(command) {}
        const Byte* end_ = nullptr;  // end of the payload
        std::size_t left_ = 0;       // payload bytes from this frame's on (end_ - left_ is its first)
        std::size_t frames_ = 0;     // frames from this one on (0: end)
        std::uint8_t command_ = 0;
    };
    // With a frame's size and first bytes as one word (head_store):
    class word_iterator {
    public:
        using value_type = bytes<frame_size>;
        using difference_type = std::ptrdiff_t;
        constexpr word_iterator() noexcept = default;
        constexpr value_type operator*() const noexcept {
            if (ROBOWIRE_CONSTANT_EVALUATED())
                return make_frame(static_cast<std::uint8_t>(head_ >> 24), static_cast<std::uint8_t>(head_ >> 32),
                                  last_ + at_, static_cast<std::size_t>(static_cast<std::ptrdiff_t>(tail_) - at_));
            return head_frame(head_, last_ + at_, at_ == 0 ? tail_ : payload_size);
        }
        constexpr word_iterator& operator++() noexcept {
            at_ += static_cast<std::ptrdiff_t>(payload_size);  // past the last frame: payload_size, the end
            head_ -= std::uint64_t{1} << 32;                   // remaining, byte 4 of the word
            return *this;
        }
        constexpr word_iterator operator++(int) noexcept {
            auto t = *this;
            ++*this;
            return t;
        }
        friend constexpr bool operator==(const word_iterator& a, const word_iterator& b) noexcept {
            return a.at_ == b.at_;
        }

    private:
        friend class basic_fragmenter;
        constexpr word_iterator(const Byte* last, std::size_t at_last, std::size_t tail, std::uint64_t head) noexcept
            : last_(last), at_(-static_cast<std::ptrdiff_t>(at_last)), tail_(tail), head_(head) {}
        const Byte* last_ = nullptr;                                     // the last frame's payload
        std::ptrdiff_t at_ = static_cast<std::ptrdiff_t>(payload_size);  // this frame's payload: last_ + at_ (<= 0)
        std::size_t tail_ = 0;                                           // payload bytes of the last frame (0..15)
        std::uint64_t head_ =
            0;  // a bytes<20>'s first 8 bytes: size 20, 55 AA command remaining 00, 2 payload bytes (0)
    };
    using iterator = std::conditional_t<head_store, word_iterator, frame_iterator>;
    constexpr iterator begin() const noexcept {
        if constexpr (head_store) {
            const std::size_t last = (size() - 1) * payload_size;  // the last frame's first payload byte
            return {payload_.data() + last, last, payload_.size() - last,
                    frame_size | std::uint64_t{header1} << 8 | std::uint64_t{header2} << 16 |
                        std::uint64_t{command_} << 24 | std::uint64_t{size() - 1} << 32};
        } else {
            return {payload_.data() + payload_.size(), payload_.size(), size(), command_};
        }
    }
    constexpr iterator end() const noexcept { return {}; }

private:
    constexpr basic_fragmenter(std::uint8_t command, std::span<const Byte> payload) noexcept
        : command_(command), payload_(payload) {}
    // A frame whose payload is the first min(left, 15) bytes at `from`, zero-padded.
    static constexpr bytes<frame_size> make_frame(std::uint8_t command, std::uint8_t remaining, const Byte* from,
                                                  std::size_t left) noexcept {
        auto out = bytes<frame_size>::zeros(frame_size);
        out[0] = header1;
        out[1] = header2;
        out[2] = command;
        out[3] = remaining;
        if (ROBOWIRE_CONSTANT_EVALUATED() || ROBOWIRE_OPTIMIZE_SIZE) {
            for (std::size_t k = 0; k < payload_size && k < left; ++k) out[5 + k] = static_cast<std::uint8_t>(from[k]);
        } else if (left >= payload_size) {  // a whole frame's payload: a constant-size copy
            std::memcpy(out.data() + 5, from, payload_size);
        } else {  // the last frame's: two fixed-size copies, not a byte loop that checks the end at every byte
            codec::copy_small(out.data() + 5, reinterpret_cast<const std::uint8_t*>(from), left);
        }
        return out;
    }
    // A frame from its size and first bytes as one word (head_store), and the
    // first n <= 15 bytes at `from` (n < 15: the last frame, zero-padded).
    static bytes<frame_size> head_frame(std::uint64_t head, const Byte* from, std::size_t n) noexcept {
        bytes<frame_size> out(codec::unset_t{});
        std::memcpy(static_cast<void*>(&out), &head, sizeof head);  // its last two bytes: the payload's, written next
        if (n == payload_size) [[likely]] {                         // a whole frame's payload: a constant-size copy
            std::memcpy(out.data() + 5, from, payload_size);
        } else {  // the last frame's: zeros, then two fixed-size copies
            std::memset(out.data() + 5, 0, payload_size);
            codec::copy_small(out.data() + 5, reinterpret_cast<const std::uint8_t*>(from), n);
        }
        return out;
    }
    std::uint8_t command_ = 0;
    std::span<const Byte> payload_{};
};
using fragmenter = basic_fragmenter<std::uint8_t>;
using text_fragmenter = basic_fragmenter<char>;

// Frames of a binary payload (e.g. command::wifi): a result<fragmenter>.
// (Templates: a file that includes this header but makes no frames
// instantiates no fragmenter.)
template <class Deferred = void>
constexpr auto make_frames(std::uint8_t command, std::span<const std::uint8_t> payload) noexcept {
    return codec::deferred_t<fragmenter, Deferred>::make(command, payload);
}
// Frames of a JSON request (command 0x02), a result<text_fragmenter>. The
// text is sent as is (no NUL).
template <class Deferred = void>
constexpr auto json_frames(std::string_view text) noexcept {
    return codec::deferred_t<text_fragmenter, Deferred>::make(command::json, {text.data(), text.size()});
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

// Checks that `text` is one complete JSON object: optional white space, an
// object whose braces and brackets balance and whose strings are closed,
// then only white space. Returns the text, or bad_json with the offset of the
// first character that breaks the rule (text.size() when the text ends too
// early). A structural check, not a full JSON parser: what it accepts still
// needs a parser; what it rejects is surely not one whole message.
constexpr result<std::string_view> json_object(std::string_view text) noexcept {
    constexpr auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    std::size_t i = 0;
    while (i < text.size() && space(text[i])) ++i;
    if (i == text.size() || text[i] != '{') return fail(errc::bad_json, i);
    std::array<char, 64> open{};  // closers expected, innermost last
    std::size_t depth = 0;
    bool in_string = false;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;  // the escaped character cannot close the string
            else if (c == '"') in_string = false;
            else if (static_cast<unsigned char>(c) < 0x20) return fail(errc::bad_json, i);  // raw control character
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '{' || c == '[') {
            if (depth == open.size()) return fail(errc::bad_json, i);  // nested deeper than 64
            open[depth++] = c == '{' ? '}' : ']';
        } else if (c == '}' || c == ']') {
            if (depth == 0 || open[depth - 1] != c) return fail(errc::bad_json, i);
            if (--depth == 0) break;
        }
    }
    if (depth != 0 || i >= text.size()) return fail(errc::bad_json, text.size());  // ends inside the object
    for (std::size_t k = i + 1; k < text.size(); ++k)
        if (!space(text[k])) return fail(errc::bad_json, k);  // more after the object
    return text;
}

// What reassembler::push says about a frame.
enum class reassembly : std::uint8_t {
    need_more,  // part of a message; more frames to come
    complete,   // the message is complete: command(), payload(), text(), json()
    single,     // a one-frame message of another command arrived while a message is in
                // progress: it is a whole message, read it from the frame you pushed;
                // the message in progress is kept
    duplicate,  // an exact repeat of the last frame of a multi-frame message: ignored
    restarted,  // the sender started the message over (same command, `remaining` higher
                // than expected): the partial message was dropped, this frame begins the new one
    discarded,  // dropped: part of a message already broken by an error
};

inline namespace ROBOWIRE_MODE_NAMESPACE {
// Collects the frames of one message at a time, up to Capacity payload
// bytes (use a multiple of 15). Fixed size, owned by the caller.
//
// push() errors, each with the frame byte it is about:
//  - bad_header, too_short, too_long: not a frame; the state does not change.
//  - bad_sequence (3): `remaining` went down by more than one (frames lost).
//  - capacity_exceeded (3): the message (this frame's `remaining` + 1 frames)
//    is longer than Capacity.
//  - command_changed (2): a frame of another command with `remaining` > 0
//    (another multi-frame message) arrived mid-message; this frame starts
//    a new message.
// After an error the partial message is dropped, and every later frame of
// the broken message (its command, up to the frame with remaining 0) is
// `discarded`; frames of other commands are taken as usual meanwhile.
//
// A receiver cannot tell a message's first frame from a later one: if it
// starts listening mid-message, the tail comes out `complete`. json()
// rejects such a tail (not one whole JSON object).
template <std::size_t Capacity>
class reassembler {
    static_assert(Capacity >= payload_size && Capacity % payload_size == 0,
                  "reassembler<Capacity>: Capacity is payload bytes, a multiple of 15 (payload_size)");

public:
    constexpr result<reassembly> push(std::span<const std::uint8_t> frame_bytes) noexcept {
        if constexpr (!ROBOWIRE_OPTIMIZE_SIZE) {
            if (!ROBOWIRE_CONSTANT_EVALUATED() && frame_bytes.size() == frame_size &&
                codec::fixed_bytes_match<frame>(codec::deferred<reassembler>(frame_bytes))) {
                const std::uint8_t* p = frame_bytes.data();
                // collecting, the last frame kept the last appended, and command
                // and remaining against now_.command and now_.last_remaining - 1:
                // one 32-bit word (collecting: last_remaining is not 0, no carry)
                const std::uint32_t key = load_le<std::uint16_t>(p + 2);
                const std::uint32_t now = load_le<std::uint32_t>(reinterpret_cast<const std::uint8_t*>(&now_));
                if ((key << 8) + 0x02010001u == now) [[likely]]
                    return append_in_place(p, key, now);
            }
        }
        const auto f = codec::decode_at<frame>(codec::deferred<reassembler>(frame_bytes).data(), frame_bytes.size());
        return to_result(f ? take(*f) : codec::unchecked_error(f));
    }

    constexpr result<reassembly> push(const frame& f) noexcept { return to_result(take(f)); }

    // The completed message (valid after push returned `complete`, until the next push).
    constexpr std::uint8_t command() const noexcept { return now_.command; }
    // Payload bytes so far, with the last frame's zero padding (the wire does not carry the length).
    constexpr std::span<const std::uint8_t> payload() const noexcept { return {buf_.data(), size_}; }
    // The payload as text (e.g. a JSON reply), without the trailing zero padding.
    std::string_view text() const noexcept {
        std::size_t n = size_;
        while (n > 0 && buf_[n - 1] == 0) --n;
        return {reinterpret_cast<const char*>(buf_.data()), n};  // char may view any object's bytes
    }
    // The completed message's text if it is one whole JSON object (see
    // json_object), else bad_json; too_short while no message is complete.
    result<std::string_view> json() const noexcept {
        if (now_.phase != state::complete) return fail(errc::too_short, size_);
        return json_object(text());
    }
    constexpr bool in_progress() const noexcept { return now_.phase == state::collecting; }
    static constexpr std::size_t capacity() noexcept { return Capacity; }
    // Forgets everything: partial message, the message being discarded, the last frame.
    constexpr void clear() noexcept {
        drop();
        now_.last = kept::none;
        skipping_ = false;
    }

private:
    enum class state : std::uint8_t { idle, collecting, complete };
    // Where the last frame of a multi-frame message is: none, the last frame
    // appended (command, last_remaining, the last 15 bytes of buf_), or last_.
    enum class kept : std::uint8_t { none, stored, appended };

    // An outcome as take() returns it: errc::ok, the outcome in the offset.
    static constexpr error outcome(reassembly r) noexcept { return {errc::ok, static_cast<std::uint16_t>(r)}; }
    static constexpr result<reassembly> to_result(error e) noexcept {
        if (e.code != errc::ok) return e;
        return static_cast<reassembly>(e.offset);
    }
    // push(frame)'s work; its outcome as one word (a register on every target).
    constexpr error take(const frame& f) noexcept {
        if (is_last(f)) return outcome(reassembly::duplicate);  // a completed message stays readable
        if (now_.phase == state::complete) drop();
        if (skipping_ && f.command == skip_command_) {
            if (f.remaining == 0) skipping_ = false;
            remember(f);  // so that a repeat of it is not taken for a new message
            return outcome(reassembly::discarded);
        }
        if (now_.phase == state::idle) return start(f);
        // collecting
        if (f.command != now_.command) {
            if (f.remaining == 0) return outcome(reassembly::single);
            const auto broken = now_.command;
            if (const error e = start(f)) return e;
            skip(broken);  // the rest of the broken message
            return fail(errc::command_changed, 2);
        }
        if (f.remaining >= now_.last_remaining) {  // the sender started over
            if (const error e = start(f)) return e;
            return outcome(reassembly::restarted);
        }
        if (f.remaining + 1 != now_.last_remaining) {  // frames lost
            drop();
            remember(f);
            if (f.remaining != 0) skip(f.command);
            return fail(errc::bad_sequence, 3);
        }
        return append(f);
    }
    // The first frame of a message (the partial one, if any, is dropped).
    constexpr error start(const frame& f) noexcept {
        drop();
        now_.command = f.command;
        if ((std::size_t{f.remaining} + 1) > Capacity / payload_size) {
            now_.last = kept::none;
            if (f.remaining != 0) {
                remember(f);
                skip(f.command);
            }
            return fail(errc::capacity_exceeded, 3);
        }
        return append(f);
    }
    constexpr error append(const frame& f) noexcept {
        // one fixed-size copy at run time, from `at` kept in a register (the copy's stores may alias size_)
        const std::size_t at = size_;
        if (ROBOWIRE_CONSTANT_EVALUATED() || ROBOWIRE_OPTIMIZE_SIZE) {
            for (std::size_t i = 0; i < payload_size; ++i) buf_[at + i] = f.payload[i];
        } else {
            std::memcpy(buf_.data() + at, f.payload.data(), payload_size);
        }
        size_ = at + payload_size;
        // repeats are recognised for frames of multi-frame messages only: a
        // one-frame message sent twice (e.g. the same maneuver) is two messages
        if (f.remaining != 0 || size_ > payload_size) {
            if constexpr (ROBOWIRE_OPTIMIZE_SIZE) remember(f);
            else now_.last = kept::appended;  // copied to last_ when the message is dropped
        }
        now_.last_remaining = f.remaining;
        now_.phase = f.remaining == 0 ? state::complete : state::collecting;
        return outcome(f.remaining == 0 ? reassembly::complete : reassembly::need_more);
    }
    // The next frame of the message being collected, from its bytes: what
    // push(frame) does with it. While collecting, a message being discarded
    // has another command (skip() follows the start of another command, or
    // leaves the state idle), and the last frame remembered is the last one
    // appended (its `remaining` is now_.last_remaining) or one of the discarded
    // command: neither a repeat nor a frame to discard can be this one.
    // key: the frame's command and remaining, as push loaded them.
    // now: now_ as one word, as push loaded it.
    result<reassembly> append_in_place(const std::uint8_t* p, std::uint32_t key, std::uint32_t now) noexcept {
        const std::size_t at = size_;
        std::memcpy(buf_.data() + at, p + 5, payload_size);
        size_ = at + payload_size;
        // phase complete (2) or collecting (1), last_remaining the frame's,
        // the last frame still the last appended (more than one frame's: remembered)
        const std::uint32_t done = key < 0x100;  // remaining 0
        store_le(reinterpret_cast<std::uint8_t*>(&now_), now - 0x10000u + done);
        static_assert(static_cast<int>(state::collecting) == 1 && static_cast<int>(state::complete) == 2 &&
                      static_cast<int>(kept::appended) == 2 && static_cast<int>(reassembly::need_more) == 0 &&
                      static_cast<int>(reassembly::complete) == 1);
        return static_cast<reassembly>(done);  // complete or need_more
    }
    // f is the last frame remembered.
    constexpr bool is_last(const frame& f) const noexcept {
        if (now_.last == kept::stored) return f == last_;
        if constexpr (ROBOWIRE_OPTIMIZE_SIZE) return false;
        return now_.last == kept::appended && f.command == now_.command && f.remaining == now_.last_remaining &&
               equal_bytes(f.payload, std::span<const std::uint8_t>(buf_.data() + size_ - payload_size, payload_size));
    }
    // Drops the message; the last frame appended, if remembered, is copied to last_.
    constexpr void drop() noexcept {
        if (!ROBOWIRE_OPTIMIZE_SIZE && now_.last == kept::appended) {
            last_.command = now_.command;
            last_.remaining = now_.last_remaining;
            const std::uint8_t* from = buf_.data() + size_ - payload_size;
            if (ROBOWIRE_CONSTANT_EVALUATED()) {
                for (std::size_t i = 0; i < payload_size; ++i) last_.payload[i] = from[i];
            } else {
                std::memcpy(last_.payload.data(), from, payload_size);
            }
            now_.last = kept::stored;
        }
        now_.phase = state::idle;
        size_ = 0;
    }
    constexpr void remember(const frame& f) noexcept {
        now_.last = kept::stored;
        last_ = f;
    }
    constexpr void skip(std::uint8_t command) noexcept {
        skipping_ = true;
        skip_command_ = command;
    }

    std::array<std::uint8_t, Capacity> buf_{};
    std::size_t size_ = 0;
    frame last_{};     // the last frame seen of a multi-frame message (if now_.last is stored)
    struct progress {  // one 32-bit word for push()
        state phase = state::idle;
        std::uint8_t command = 0;
        std::uint8_t last_remaining = 0;  // `remaining` of the last frame taken
        kept last = kept::none;           // the last frame seen of a multi-frame message
    };
    static_assert(sizeof(progress) == 4);
    progress now_{};
    std::uint8_t skip_command_ = 0;  // command of the broken message being discarded
    bool skipping_ = false;
};
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire::navbot
