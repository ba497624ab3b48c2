// NAVBOT multi-frame messages.
// 1. The input, cut into frames (a length byte before each), goes through a
//    small reassembler: sizes, outcomes and error offsets stay consistent.
// 2. A message is sent with other traffic driven by the input: single frames
//    of other commands, repeats, restarts (also one that first resends the
//    last frame with other bytes), lost frames. Whenever the reassembler says
//    `complete` for the message's command, the payload is the whole message:
//    never a truncated one. A second reassembler, of 4 frames, gets the same
//    frames: it completes the message only when it has at most 4 frames. A
//    third gets each frame decoded (push(frame)): its outcomes, errors and
//    payload are the first one's (push of the bytes).
// 3. The whole input, fragmented as one payload (make_frames refuses more than
//    max_payload bytes), reassembles to itself, and
//    json_object() never accepts text that does not start with '{' and end with '}'.
#include <robowire/navbot.hpp>

#include <array>
#include <vector>

#include "common.hpp"

namespace {
namespace nb = robowire::navbot;

void arbitrary_frames(std::span<const std::uint8_t> in) {
    robowire::fuzz::source r(in);
    nb::reassembler<60> small;
    while (!r.empty()) {
        const std::size_t len = r.byte() % 24;  // mostly 20, sometimes not a frame
        std::uint8_t frame[24] = {};
        for (std::size_t i = 0; i < len; ++i) frame[i] = r.byte();
        const auto before_size = small.payload().size();
        const bool before_progress = small.in_progress();
        const auto st = small.push(std::span<const std::uint8_t>(frame, len));
        fuzz::check_text(st);
        FUZZ_CHECK(small.payload().size() <= 60 && small.payload().size() % 15 == 0);
        if (!st) {
            FUZZ_CHECK(st.error().offset < 20 || len != 20);
            continue;
        }
        switch (*st) {
        case nb::reassembly::complete: FUZZ_CHECK(!small.payload().empty() && !small.in_progress()); break;
        case nb::reassembly::need_more: FUZZ_CHECK(small.in_progress()); break;
        case nb::reassembly::restarted: FUZZ_CHECK(small.in_progress() && small.payload().size() == 15); break;
        case nb::reassembly::single:  // the message in progress is kept
            FUZZ_CHECK(small.in_progress() && before_progress && small.command() != frame[2] && frame[3] == 0);
            FUZZ_CHECK(small.payload().size() == before_size);
            break;
        case nb::reassembly::duplicate: FUZZ_CHECK(small.payload().size() == before_size); break;
        case nb::reassembly::discarded: FUZZ_CHECK(!small.in_progress() || small.command() != frame[2]); break;
        }
    }
}

void message_with_traffic(std::span<const std::uint8_t> in) {
    robowire::fuzz::source r(in);
    const std::uint8_t cmd = r.byte();
    const std::size_t n = r.byte() % 200;
    std::vector<std::uint8_t> message(n);
    for (auto& b : message) b = r.byte();
    const auto frames = nb::make_frames(cmd, message).value();
    const std::size_t count = frames.size();
    std::vector<std::uint8_t> whole(count * nb::payload_size, 0);
    for (std::size_t i = 0; i < n; ++i) whole[i] = message[i];

    nb::reassembler<nb::max_payload> rx;
    std::size_t next = 0;  // index of the next frame to send
    bool lost = false;     // a frame was lost: outcomes are no longer predicted, completions still checked
    bool completed = false;
    nb::reassembler<60> small;  // room for 4 frames
    nb::reassembler<nb::max_payload> by_frame;  // the same frames decoded first: push(frame) as push(bytes)
    const auto push = [&](const robowire::bytes<nb::frame_size>& f) {
        const auto st = rx.push(f);
        const auto decoded = robowire::decode<nb::frame>(f);
        FUZZ_CHECK(decoded.has_value());
        const auto st_frame = by_frame.push(*decoded);
        FUZZ_CHECK(st.has_value() == st_frame.has_value());
        FUZZ_CHECK(st ? *st == *st_frame : st.error() == st_frame.error());
        FUZZ_CHECK(fuzz::same_bytes(rx.payload(), by_frame.payload()) && rx.in_progress() == by_frame.in_progress());
        if (st && *st == nb::reassembly::complete && rx.command() == cmd) {
            FUZZ_CHECK(rx.payload().size() == whole.size());  // whole, never a tail
            FUZZ_CHECK(fuzz::same_bytes(rx.payload(), whole));
            completed = true;
        }
        const auto in_small = small.push(f);
        FUZZ_CHECK(small.payload().size() <= 60);
        if (in_small && *in_small == nb::reassembly::complete && small.command() == cmd)
            FUZZ_CHECK(count <= 4 && fuzz::same_bytes(small.payload(), whole));
        return st;
    };
    for (std::size_t op = 0; op < 400 && !r.empty(); ++op) {
        const std::uint8_t b = r.byte();
        switch (b % 8) {
        case 4: {  // a one-frame message of another command
            auto f = robowire::bytes<nb::frame_size>::zeros(nb::frame_size);
            f[0] = nb::header1;
            f[1] = nb::header2;
            f[2] = static_cast<std::uint8_t>(cmd ^ (1 + b / 8));
            for (std::size_t i = 5; i < nb::frame_size; ++i) f[i] = r.byte();
            const auto st = push(f);
            FUZZ_CHECK(st.has_value());
            if (!lost) FUZZ_CHECK(*st == (next > 0 && next < count ? nb::reassembly::single : nb::reassembly::complete));
            break;
        }
        case 5:  // the last frame again
            if (next > 0) {
                const auto st = push(frames[next - 1]);
                if (!lost && count > 1) FUZZ_CHECK(st && *st == nb::reassembly::duplicate);
            }
            break;
        case 6: {  // the sender starts over
            // Bit 7: it first resends its last frame with other bytes (the same
            // `remaining`): that begins a new message, `restarted`.
            const bool changed = (b & 0x80) != 0 && next > 0 && next < count;
            if (changed) {
                auto other = frames[next - 1];
                other[5] = static_cast<std::uint8_t>(other[5] ^ 0xFF);
                const auto st = push(other);
                if (!lost) FUZZ_CHECK(st && *st == nb::reassembly::restarted);
            }
            const auto st = push(frames[0]);
            if (!lost) {
                FUZZ_CHECK(st.has_value());
                if (count == 1) FUZZ_CHECK(*st == nb::reassembly::complete);
                else if (next == 1 && !changed) FUZZ_CHECK(*st == nb::reassembly::duplicate);
                else if (next == 0 || next == count) FUZZ_CHECK(*st == nb::reassembly::need_more);
                else FUZZ_CHECK(*st == nb::reassembly::restarted);
            }
            next = 1;
            break;
        }
        case 7:  // a frame other than the first is lost
            if (next > 0 && next < count) {
                ++next;
                lost = true;
            }
            break;
        default: {  // the next frame
            if (next == count) next = 0;
            const auto st = push(frames[next]);
            ++next;
            if (!lost) FUZZ_CHECK(st && *st == (next == count ? nb::reassembly::complete : nb::reassembly::need_more));
            break;
        }
        }
    }
    if (!lost && next == count) FUZZ_CHECK(completed);
}

void fragment_and_json(std::span<const std::uint8_t> in) {
    // More than max_payload bytes do not fit in the frames of one message.
    const auto all = nb::make_frames(0x02, in);
    fuzz::check_text(all);
    FUZZ_CHECK(all.has_value() == (in.size() <= nb::max_payload));
    if (!all) FUZZ_CHECK(all.error().code == robowire::errc::capacity_exceeded && all.error().offset == nb::max_payload);
    const auto payload = in.first(in.size() < nb::max_payload ? in.size() : nb::max_payload);
    const auto frames = nb::make_frames(0x02, payload);
    FUZZ_CHECK(frames.has_value());
    nb::reassembler<nb::max_payload> big;
    std::size_t i = 0;
    for (const auto& f : *frames) {
        const auto st = big.push(f);
        FUZZ_CHECK(st.has_value());
        FUZZ_CHECK(*st == (++i == frames->size() ? nb::reassembly::complete : nb::reassembly::need_more));
    }
    FUZZ_CHECK(big.payload().size() == frames->size() * 15);
    FUZZ_CHECK(fuzz::same_bytes(big.payload().first(payload.size()), payload));

    const std::string_view text(reinterpret_cast<const char*>(payload.data()), payload.size());
    const auto j = nb::json_object(text);
    fuzz::check_throws(j);
    if (j) {
        const auto first = text.find_first_not_of(" \t\r\n");
        const auto last = text.find_last_not_of(" \t\r\n");
        FUZZ_CHECK(first != std::string_view::npos && text[first] == '{' && text[last] == '}');
    } else {
        FUZZ_CHECK(j.error().code == robowire::errc::bad_json && j.error().offset <= text.size());
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> in(data, size);
    arbitrary_frames(in);
    message_with_traffic(in);
    fragment_and_json(in);
    return 0;
}
