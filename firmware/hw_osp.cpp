// Hand-written baseline for osp.cpp: decode of any frame, every encoder, the
// stream scanner (resumes at the next byte after a false start, counts frames,
// skipped bytes and false starts), serve(). The same work as robowire: the
// decoder keeps DEV, CMD and P1..P4 whenever the markers and the length are
// right (robowire's decode_result::frame()), the checks come in robowire's
// order (markers present in the input, then the length).
#include "handwritten.hpp"

namespace {
struct osp_msg {
    std::uint8_t frame[6];  // DEV, CMD, P1..P4 as received
    std::uint8_t b;         // joint, device type, state
    std::uint16_t a;        // angle, soc, voltage, current, flags
};
// Which check a bad frame failed: out of line, off the good path.
[[gnu::cold, gnu::noinline]] hw::error frame_error(const std::uint8_t* p, std::size_t n) {
    if (n > 0 && p[0] != 0xFF) return hw::fail(hw::bad_header, 0);
    if (n > 1 && p[1] != 0xAA) return hw::fail(hw::bad_header, 1);
    if (n > 8 && p[8] != 0x55) return hw::fail(hw::bad_trailer, 8);
    if (n > 9 && p[9] != 0x77) return hw::fail(hw::bad_trailer, 9);
    return hw::length(n, 10);
}

HW_CODEC hw::error decode(const std::uint8_t* p, std::size_t n, osp_msg& m) {
    if (n != 10 || p[0] != 0xFF || p[1] != 0xAA || p[8] != 0x55 || p[9] != 0x77) return frame_error(p, n);
    for (std::size_t k = 0; k < 6; ++k) m.frame[k] = p[2 + k];  // no memcpy call at -Os
    switch (p[2] << 8 | p[3]) {
    case 0x0001: case 0x0201: case 0x0202: case 0x0203: case 0x0204: return hw::good;
    case 0x0011: m.b = p[4]; return p[4] <= 3 ? hw::good : hw::fail(hw::invalid_enum, 4);
    case 0x0102: m.b = p[4]; m.a = hw::rd16(p + 5); return hw::good;
    case 0x0211: case 0x0212: case 0x0213: m.a = hw::rd16(p + 4); return hw::good;
    case 0x0214: m.b = p[4]; m.a = p[5]; return p[4] <= 4 ? hw::good : hw::fail(hw::invalid_enum, 4);
    default: return hw::fail(hw::unknown_message, 2);
    }
}
// Writes the frame for m (DEV and CMD in m.frame[0..1]) into out[10];
// validates enumerations as the decoder does.
HW_CODEC hw::error encode(const osp_msg& m, std::uint8_t* out) {
    const int key = m.frame[0] << 8 | m.frame[1];
    switch (key) {
    case 0x0011: if (m.b > 3) return hw::fail(hw::invalid_enum, 4); break;
    case 0x0214: if (m.b > 4) return hw::fail(hw::invalid_enum, 4); break;
    case 0x0001: case 0x0201: case 0x0202: case 0x0203: case 0x0204:
    case 0x0102: case 0x0211: case 0x0212: case 0x0213: break;
    default: return hw::fail(hw::unknown_message, 2);
    }
    out[0] = 0xFF; out[1] = 0xAA; out[2] = m.frame[0]; out[3] = m.frame[1];
    out[4] = out[5] = out[6] = out[7] = 0;
    out[8] = 0x55; out[9] = 0x77;
    switch (key) {
    case 0x0011: out[4] = m.b; break;
    case 0x0102: out[4] = m.b; hw::wr16(out + 5, m.a); break;
    case 0x0211: case 0x0212: case 0x0213: hw::wr16(out + 4, m.a); break;
    case 0x0214: out[4] = m.b; out[5] = static_cast<std::uint8_t>(m.a); break;
    default: break;
    }
    return hw::good;
}

// Byte-at-a-time scanner: each byte is checked as it comes; a candidate that
// fails drops its first byte and resumes at the next FF in what it holds, so a
// frame overlapping a false start is not lost. Counters as robowire's.
struct scanner {
    std::uint8_t buf[10];
    std::uint8_t len;
    std::uint64_t frames, skipped, false_starts;
    bool partial_ok() const { return (len < 2 || buf[1] == 0xAA) && (len < 9 || buf[8] == 0x55); }
    void resync() {
        do {
            ++false_starts;
            std::size_t from = 1;  // word-sized indices: no zero-extension per step
            while (from < len && buf[from] != 0xFF) ++from;
            skipped += from;
            for (std::size_t k = from; k < len; ++k) buf[k - from] = buf[k];
            len = static_cast<std::uint8_t>(len - from);
        } while (!partial_ok());
    }
    template <class F>
    void push(std::uint8_t b, F&& on_frame) {
        if (len == 0) {
            if (b == 0xFF) buf[len++] = b;
            else ++skipped;
            return;
        }
        const std::uint8_t k = len++;
        buf[k] = b;
        if (k == 9) {
            if (b == 0x77) {
                len = 0;
                ++frames;
                on_frame(buf);
            } else {
                resync();
            }
        } else if ((k == 1 && b != 0xAA) || (k == 8 && b != 0x55)) {
            resync();
        }
    }
};
}  // namespace

ENTRY void hw_osp_decode(const std::uint8_t* p, std::size_t n) {
    osp_msg m{};
    const auto e = decode(p, n, m);
    sink = e.code ? static_cast<std::uint32_t>(e.code) : static_cast<std::uint32_t>(m.frame[1]);
}
ENTRY void hw_osp_encode(std::size_t which, std::uint16_t value) {
    static constexpr std::uint8_t keys[11][2] = {{0, 0x01}, {0, 0x11}, {1, 0x02}, {2, 0x01}, {2, 0x02}, {2, 0x03},
                                                 {2, 0x04}, {2, 0x11}, {2, 0x12}, {2, 0x13}, {2, 0x14}};
    const auto* k = keys[which < 11 ? which : 10];  // no division, as osp.cpp
    osp_msg m;  // the encoder reads DEV, CMD, b and a only
    m.frame[0] = k[0];
    m.frame[1] = k[1];
    m.b = static_cast<std::uint8_t>(value);
    m.a = k[1] == 0x14 ? static_cast<std::uint8_t>(value) : value;
    std::uint8_t f[10];
    if (encode(m, f).code == 0) hw::out(f, 10);
}
scanner scanner_state;
ENTRY void hw_osp_scan(const std::uint8_t* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) scanner_state.push(p[i], [](const std::uint8_t* f) { hw_osp_decode(f, 10); });
}
// A battery answering soc and voltage requests; other requests and bad frames
// get no answer (osp.cpp does not look at serve's error either).
ENTRY void hw_osp_serve(const std::uint8_t* p, std::size_t n) {
    osp_msg m{};
    if (decode(p, n, m).code) return;
    std::uint8_t cmd;
    switch (m.frame[0] << 8 | m.frame[1]) {
    case 0x0201: cmd = 0x11; break;
    case 0x0202: cmd = 0x12; break;
    default: return;
    }
    osp_msg a;  // the encoder reads DEV, CMD and a only
    a.frame[0] = 2;
    a.frame[1] = cmd;
    a.a = static_cast<std::uint16_t>(sink);
    std::uint8_t f[10];
    if (encode(a, f).code == 0) hw::out(f, 10);
}

int main() {
    const auto in = read_input<160>();
    const auto n = size_in(160);
    hw_osp_decode(in.data(), n);
    hw_osp_encode(in[0], static_cast<std::uint16_t>(in[1] | in[2] << 8));
    hw_osp_scan(in.data(), n);
    hw_osp_serve(in.data(), n);
    return 0;
}
