// Hand-written baseline for navbot.cpp: maneuver encode/decode (both sign
// encodings), frame dispatch, fragmenter and reassembler.
#include "handwritten.hpp"

namespace {
struct maneuver {
    std::int8_t roll;
    std::uint8_t height;
    std::int8_t pitch, yaw;
    std::uint8_t switch_a, switch_b, switch_c, switch_d;
    std::int8_t ball_x, ball_y;
};
struct frame {
    std::uint8_t command, remaining;
    std::uint8_t payload[15];
};
static_assert(sizeof(maneuver) == 10, "the maneuver's members are wire bytes 5..14, in order");
bool in(int v, int lo, int hi) { return v >= lo && v <= hi; }
// Signed channels: byte offsets 5, 7, 8, 13, 14.
bool is_signed(std::size_t i) { return i == 5 || i == 7 || i == 8 || i == 13 || i == 14; }

hw::error check(const maneuver& m) {
    if (!in(m.roll, -100, 100)) return hw::fail(hw::value_out_of_range, 5);
    if (m.height > 100) return hw::fail(hw::value_out_of_range, 6);
    if (!in(m.pitch, -100, 100)) return hw::fail(hw::value_out_of_range, 7);
    if (!in(m.yaw, -100, 100)) return hw::fail(hw::value_out_of_range, 8);
    if (m.switch_a > 2) return hw::fail(hw::invalid_enum, 9);
    if (m.switch_b > 1) return hw::fail(hw::invalid_enum, 10);
    if (m.switch_c > 1) return hw::fail(hw::invalid_enum, 11);
    if (m.switch_d > 2) return hw::fail(hw::invalid_enum, 12);
    if (!in(m.ball_x, -5, 5)) return hw::fail(hw::value_out_of_range, 13);
    if (!in(m.ball_y, -5, 5)) return hw::fail(hw::value_out_of_range, 14);
    return hw::good;
}
HW_CODEC hw::error encode(const maneuver& m, bool sign_magnitude, std::uint8_t* out) {
    if (auto e = check(m); e.code) return e;
    std::memset(out, 0, 20);
    out[0] = 0x55; out[1] = 0xAA; out[2] = 0x10;
    std::memcpy(out + 5, &m, 10);
    if (sign_magnitude)
        for (std::size_t i = 5; i < 15; ++i)
            if (is_signed(i) && (out[i] & 0x80)) out[i] = static_cast<std::uint8_t>(0x80 | (256 - out[i]));
    return hw::good;
}
// Which fixed byte (55 AA, then for a maneuver 10 00) or the length failed:
// robowire's order (each fixed byte the input holds, then the length).
// Out of line, off the good path.
[[gnu::cold, gnu::noinline]] hw::error fixed_error(const std::uint8_t* p, std::size_t n, std::size_t count) {
    static constexpr std::uint8_t fixed[4] = {0x55, 0xAA, 0x10, 0x00};
    static constexpr hw::err code[4] = {hw::bad_header, hw::bad_header, hw::bad_command, hw::bad_sequence};
    for (std::size_t i = 0; i < count && i < n; ++i)
        if (p[i] != fixed[i]) return hw::fail(code[i], i);
    return hw::length(n, 20);
}
HW_CODEC hw::error decode_frame(const std::uint8_t* p, std::size_t n, frame& f) {
    if (n != 20 || p[0] != 0x55 || p[1] != 0xAA) return fixed_error(p, n, 2);
    f.command = p[2];
    f.remaining = p[3];
    std::memcpy(f.payload, p + 5, 15);
    return hw::good;
}
HW_CODEC hw::error decode_maneuver(const std::uint8_t* p, std::size_t n, bool sign_magnitude, maneuver& m) {
    if (n != 20 || p[0] != 0x55 || p[1] != 0xAA || p[2] != 0x10 || p[3] != 0) return fixed_error(p, n, 4);
    std::memcpy(&m, p + 5, 10);
    if (sign_magnitude) {
        auto* b = reinterpret_cast<std::uint8_t*>(&m);
        for (std::size_t i = 5; i < 15; ++i)
            if (is_signed(i) && (b[i - 5] & 0x80)) b[i - 5] = static_cast<std::uint8_t>(-(b[i - 5] & 0x7F));
    }
    return check(m);
}

enum outcome : std::uint8_t { need_more, complete, single, duplicate, restarted, discarded };
// The same rules as robowire's reassembler: repeats of the last frame are
// ignored, a one-frame message of another command passes through, a sender
// starting over restarts the message, and after an error the rest of the
// broken message is discarded.
struct reassembler {
    std::uint8_t buf[120];
    std::uint8_t size, last_remaining, command;
    std::uint8_t state;  // 0 idle, 1 collecting, 2 complete
    bool has_last, skipping;
    std::uint8_t skip_command;
    frame last;
    void remember(const frame& f) { has_last = true; last = f; }
    void skip(std::uint8_t c) { skipping = true; skip_command = c; }
    hw::error append(const frame& f, outcome& o) {
        std::memcpy(buf + size, f.payload, 15);
        size = static_cast<std::uint8_t>(size + 15);
        if (f.remaining != 0 || size > 15) remember(f);
        last_remaining = f.remaining;
        state = f.remaining == 0 ? 2 : 1;
        o = f.remaining == 0 ? complete : need_more;
        return hw::good;
    }
    hw::error start(const frame& f, outcome& o) {
        state = 0;
        size = 0;
        command = f.command;
        if (f.remaining + 1u > sizeof buf / 15) {
            has_last = false;
            if (f.remaining != 0) { remember(f); skip(f.command); }
            return hw::fail(hw::capacity_exceeded, 3);
        }
        return append(f, o);
    }
    HW_CODEC hw::error push(const std::uint8_t* p, std::size_t n, outcome& o) {
        frame f;
        if (auto e = decode_frame(p, n, f); e.code) return e;
        if (has_last && std::memcmp(&f, &last, sizeof f) == 0) { o = duplicate; return hw::good; }
        if (state == 2) { state = 0; size = 0; }
        if (skipping && f.command == skip_command) {
            if (f.remaining == 0) skipping = false;
            remember(f);
            o = discarded;
            return hw::good;
        }
        if (state == 0) return start(f, o);
        if (f.command != command) {
            if (f.remaining == 0) { o = single; return hw::good; }
            const std::uint8_t broken = command;
            if (auto e = start(f, o); e.code) return e;
            skip(broken);
            return hw::fail(hw::command_changed, 2);
        }
        if (f.remaining >= last_remaining) {
            if (auto e = start(f, o); e.code) return e;
            o = restarted;
            return hw::good;
        }
        if (f.remaining + 1 != last_remaining) {  // frames lost
            state = 0;
            size = 0;
            remember(f);
            if (f.remaining != 0) skip(f.command);
            return hw::fail(hw::bad_sequence, 3);
        }
        return append(f, o);
    }
};
}  // namespace

ENTRY void hw_navbot_encode_maneuver(const std::uint8_t* b) {
    // every channel from the input, as navbot.cpp
    const maneuver m{static_cast<std::int8_t>(b[0]), b[1], static_cast<std::int8_t>(b[2]), static_cast<std::int8_t>(b[3]),
                     b[4], b[5], b[6], b[7], static_cast<std::int8_t>(b[8]), static_cast<std::int8_t>(b[9])};
    std::uint8_t out[20];
    if (encode(m, b[10] & 1, out).code == 0) hw::out(out, 20);
}
ENTRY void hw_navbot_decode_frame(const std::uint8_t* p, std::size_t n) {
    frame f{};
    maneuver m;
    auto e = decode_frame(p, n, f);
    if (e.code == 0 && f.command == 0x10) e = decode_maneuver(p, n, false, m);
    if (e.code != 0) sink = e.code;  // every field of what was decoded
    else if (f.command == 0x10) hw::out(reinterpret_cast<const std::uint8_t*>(&m), sizeof m);
    else hw::out(reinterpret_cast<const std::uint8_t*>(&f), sizeof f);
    if (decode_maneuver(p, n, true, m).code == 0) hw::out(reinterpret_cast<const std::uint8_t*>(&m), sizeof m);
}
reassembler reassembler_state;
ENTRY void hw_navbot_reassemble(const std::uint8_t* p, std::size_t n) {
    outcome o;
    const auto e = reassembler_state.push(p, n, o);
    if (e.code == 0 && o == complete) hw::out(reassembler_state.buf, reassembler_state.size);
}
ENTRY void hw_navbot_fragment(const std::uint8_t* payload, std::size_t n) {
    const std::size_t frames = n == 0 ? 1 : (n + 14) / 15;
    if (frames > 256) return;
    for (std::size_t k = 0; k < frames; ++k) {
        std::uint8_t f[20] = {0x55, 0xAA, 0x02, static_cast<std::uint8_t>(frames - 1 - k), 0};
        const std::size_t m = n - 15 * k < 15 ? n - 15 * k : 15;
        for (std::size_t i = 0; i < 15; ++i)  // no memcpy call for a variable length
            f[5 + i] = i < m ? payload[15 * k + i] : 0;
        hw::out(f, 20);
    }
}

int main() {
    const auto in = read_input<160>();
    const auto n = size_in(40);
    hw_navbot_encode_maneuver(in.data());
    hw_navbot_decode_frame(in.data(), n);
    hw_navbot_reassemble(in.data(), n);
    hw_navbot_fragment(in.data(), size_in(120));
    return 0;
}
