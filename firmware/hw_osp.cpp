// Hand-written baseline for osp.cpp: decode of any frame, every encoder, the
// stream scanner (resumes at the next byte after a false start), serve().
#include "handwritten.hpp"

namespace {
struct osp_msg {
    std::uint8_t dev, cmd;
    std::uint8_t b;   // joint, device type, state
    std::uint16_t a;  // angle, soc, voltage, current, flags
};

HW_CODEC hw::error decode(const std::uint8_t* p, std::size_t n, osp_msg& m) {
    if (auto e = hw::length(n, 10); e.code) return e;
    if (p[0] != 0xFF) return hw::fail(hw::bad_header, 0);
    if (p[1] != 0xAA) return hw::fail(hw::bad_header, 1);
    if (p[8] != 0x55) return hw::fail(hw::bad_trailer, 8);
    if (p[9] != 0x77) return hw::fail(hw::bad_trailer, 9);
    m.dev = p[2];
    m.cmd = p[3];
    switch (p[2] << 8 | p[3]) {
    case 0x0001: case 0x0201: case 0x0202: case 0x0203: case 0x0204: return hw::good;
    case 0x0011: m.b = p[4]; return p[4] <= 3 ? hw::good : hw::fail(hw::invalid_enum, 4);
    case 0x0102: m.b = p[4]; m.a = hw::rd16(p + 5); return hw::good;
    case 0x0211: case 0x0212: case 0x0213: m.a = hw::rd16(p + 4); return hw::good;
    case 0x0214: m.b = p[4]; m.a = p[5]; return p[4] <= 4 ? hw::good : hw::fail(hw::invalid_enum, 4);
    default: return hw::fail(hw::unknown_message, 2);
    }
}
// Writes the frame for m into out[10]; validates enumerations as the decoder does.
HW_CODEC hw::error encode(const osp_msg& m, std::uint8_t* out) {
    switch (m.dev << 8 | m.cmd) {
    case 0x0011: if (m.b > 3) return hw::fail(hw::invalid_enum, 4); break;
    case 0x0214: if (m.b > 4) return hw::fail(hw::invalid_enum, 4); break;
    case 0x0001: case 0x0201: case 0x0202: case 0x0203: case 0x0204:
    case 0x0102: case 0x0211: case 0x0212: case 0x0213: break;
    default: return hw::fail(hw::unknown_message, 2);
    }
    out[0] = 0xFF; out[1] = 0xAA; out[2] = m.dev; out[3] = m.cmd;
    out[4] = out[5] = out[6] = out[7] = 0;
    out[8] = 0x55; out[9] = 0x77;
    switch (m.dev << 8 | m.cmd) {
    case 0x0011: out[4] = m.b; break;
    case 0x0102: out[4] = m.b; hw::wr16(out + 5, m.a); break;
    case 0x0211: case 0x0212: case 0x0213: hw::wr16(out + 4, m.a); break;
    case 0x0214: out[4] = m.b; out[5] = static_cast<std::uint8_t>(m.a); break;
    default: break;
    }
    return hw::good;
}

// Byte-at-a-time scanner: a candidate that fails is shifted by one byte and
// re-checked, so a frame overlapping a false start is not lost.
struct scanner {
    std::uint8_t buf[10];
    std::uint8_t len;
    template <class F>
    void push(std::uint8_t b, F&& on_frame) {
        buf[len++] = b;
        for (;;) {
            bool ok = buf[0] == 0xFF && (len < 2 || buf[1] == 0xAA) && (len < 9 || buf[8] == 0x55) &&
                      (len < 10 || buf[9] == 0x77);
            if (ok) {
                if (len == 10) { on_frame(buf); len = 0; }
                return;
            }
            std::memmove(buf, buf + 1, --len);  // resume at the next byte
            if (len == 0) return;
        }
    }
};
}  // namespace

ENTRY void hw_osp_decode(const std::uint8_t* p, std::size_t n) {
    osp_msg m{};
    const auto e = decode(p, n, m);
    sink = e.code ? static_cast<std::uint32_t>(e.code) : static_cast<std::uint32_t>(m.cmd);
}
ENTRY void hw_osp_encode(std::size_t which, std::uint16_t value) {
    static constexpr std::uint8_t keys[11][2] = {{0, 0x01}, {0, 0x11}, {1, 0x02}, {2, 0x01}, {2, 0x02}, {2, 0x03},
                                                 {2, 0x04}, {2, 0x11}, {2, 0x12}, {2, 0x13}, {2, 0x14}};
    const auto* k = keys[which % 11];
    osp_msg m{k[0], k[1], static_cast<std::uint8_t>(value), value};
    if (k[1] == 0x11 && k[0] == 0) m.b = value & 3;
    if (k[1] == 0x14) { m.b = static_cast<std::uint8_t>(value % 5); m.a = static_cast<std::uint8_t>(value); }
    std::uint8_t f[10];
    if (encode(m, f).code == 0) hw::out(f, 10);
}
scanner scanner_state;
ENTRY void hw_osp_scan(const std::uint8_t* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) scanner_state.push(p[i], [](const std::uint8_t* f) { hw_osp_decode(f, 10); });
}
// A battery answering soc and voltage requests; other requests get no answer.
ENTRY void hw_osp_serve(const std::uint8_t* p, std::size_t n) {
    osp_msg m{};
    const auto e = decode(p, n, m);
    if (e.code) return hw::report(e);
    osp_msg a{2, 0, 0, static_cast<std::uint16_t>(sink)};
    switch (m.dev << 8 | m.cmd) {
    case 0x0201: a.cmd = 0x11; break;
    case 0x0202: a.cmd = 0x12; break;
    default: return hw::report(hw::fail(hw::unknown_message, 2));
    }
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
