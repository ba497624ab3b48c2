// The same codec calls, compiled in two files of one program at different
// size settings (size.cpp at -Os, speed.cpp at -O2): MIXED_MODES_FILE names
// the file's namespace. No Catch2 here: main.cpp checks what these return.
#include <robowire/buwizz3.hpp>
#include <robowire/navbot.hpp>
#include <robowire/osp.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <variant>

namespace MIXED_MODES_FILE {

namespace bw = robowire::buwizz3;
namespace nb = robowire::navbot;
namespace osp = robowire::osp;

// ROBOWIRE_OPTIMIZE_SIZE * 10 + ROBOWIRE_ARRAY_LOOPS, as this file was compiled.
int mode() { return ROBOWIRE_OPTIMIZE_SIZE * 10 + ROBOWIRE_ARRAY_LOOPS; }

// The bytes through a volatile copy, so that the codec runs at run time.
template <std::size_t N>
std::array<std::uint8_t, N> runtime(const std::array<std::uint8_t, N>& a) {
    std::array<std::uint8_t, N> out{};
    volatile std::uint8_t tmp = 0;
    for (std::size_t i = 0; i < N; ++i) {
        tmp = a[i];
        out[i] = tmp;
    }
    return out;
}

// Decodes and encodes through every kind of codec; returns the number of wrong results.
int failures() {
    int failed = 0;
    const auto expect = [&](bool ok) { failed += ok ? 0 : 1; };

    // BuWizz3 status (records, arrays, optional blocks): decode, then encode back.
    std::array<std::uint8_t, 54> s{};
    s[0] = 0x01;
    s[10] = 0x10; s[11] = 0x00; s[12] = 0xF0; s[13] = 0xFF; s[14] = 0xF0; s[15] = 0x7F;
    const std::uint8_t m3[8] = {0x4B, 0xFE, 0xA6, 0xFF, 0x18, 0xFC, 0xFF, 0xFF};
    for (std::size_t i = 0; i < 8; ++i) s[38 + i] = m3[i];
    const auto in = runtime(s);
    const auto st = robowire::decode<bw::status>(in);
    expect(st && st->accel_raw == std::array<std::int16_t, 3>{16, -16, 0x7FF0} &&
           st->pu_motors[2] == bw::pu_motor{0x4B, -2, -90, -1000});
    if (st) {
        const auto back = robowire::encode(*st);
        expect(back && back->size() == in.size() && std::equal(in.begin(), in.end(), back->begin()));
    }
    const auto n = bw::decode_notification(in);
    expect(n && n->index() == 0);
    // An error, with its offset: motor data power[3] is -128.
    const auto bad = runtime(std::array<std::uint8_t, 9>{0x30, 1, 2, 3, 0x80, 5, 6, 0, 0});
    expect(bw::decode_command(bad).code() == robowire::errc::value_out_of_range &&
           robowire::codec::unchecked_error(bw::decode_command(bad)).offset == 4);

    // OSP: dispatch, encode, and the stream scanner over a frame split in two chunks.
    const auto frame = runtime(std::array<std::uint8_t, 10>{0xFF, 0xAA, 0x02, 0x14, 0x03, 0x05, 0x00, 0x00, 0x55, 0x77});
    const auto d = osp::decode(frame);
    expect(d && d.frame() && d.frame()->command == 0x14);
    if (d) {
        const auto e = osp::encode(*d);
        expect(e && std::equal(frame.begin(), frame.end(), e->begin()));
    }
    osp::scanner sc;
    int found = 0;
    sc.feed(std::span<const std::uint8_t>(frame).first(3), [&](osp::scanner::frame_bytes) { ++found; });
    sc.feed(std::span<const std::uint8_t>(frame).subspan(3), [&](osp::scanner::frame_bytes) { ++found; });
    expect(found == 1 && sc.frames() == 1);

    // NAVBOT: a 40-byte payload in three frames, reassembled.
    std::array<std::uint8_t, 40> payload{};
    for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i + 1);
    const auto frames = nb::make_frames(0x03, payload);
    nb::reassembler<60> r;
    robowire::result<nb::reassembly> last = nb::reassembly::need_more;
    if (frames)
        for (const auto& f : *frames) last = r.push(f.span());
    expect(frames && frames->size() == 3 && last && *last == nb::reassembly::complete &&
           std::equal(payload.begin(), payload.end(), r.payload().begin()));
    return failed;
}

// What a codec makes of `in`: "E<code>@<offset>" for an error, else the
// alternative's index and the bytes its value encodes to (or the encode's
// error). `which` picks the codec: 0 BuWizz3 commands, 1 notifications,
// 2 decode<status>, 3 decode_into<status> (an error must leave the object as
// it was), 4 and 5 a NAVBOT maneuver in each sign encoding, 6 decode_frame,
// 7 OSP, 8 a stream of NAVBOT frames through a reassembler.
inline std::string error_text(robowire::error e) {
    return "E" + std::to_string(static_cast<int>(e.code)) + "@" + std::to_string(e.offset);
}
template <class R>
std::string error_text(const R& r) {
    return error_text(robowire::codec::unchecked_error(r));
}
template <class W>
std::string encoded_text(const W& w) {
    if (!w) return "encode " + error_text(w);
    return std::string(reinterpret_cast<const char*>(w->data()), w->size());
}
template <class R>
std::string variant_text(const R& r) {
    if (!r) return error_text(r);
    return std::visit([&](const auto& m) { return std::to_string(r->index()) + ":" + encoded_text(robowire::encode(m)); },
                      *r);
}
// A stream of 60 NAVBOT frames made from the input's bytes through a
// reassembler: each push's outcome or error, and each completed payload.
// Mostly messages counting down (the speed file takes their next frames in
// place), with frames lost, repeated, of another command, cut short or with
// a broken header.
inline std::string reassembly_text(std::span<const std::uint8_t> in) {
    std::uint32_t state = 2166136261u;  // FNV-1a of the input: the stream's seed
    for (const std::uint8_t b : in) state = (state ^ b) * 16777619u;
    const auto next = [&] {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return state;
    };
    nb::reassembler<60> r;
    std::string out;
    int remaining = -1;
    std::uint8_t command = 2;
    std::array<std::uint8_t, 22> b{};
    bool repeat = false;
    for (int k = 0; k < 60; ++k) {
        if (!repeat && (remaining < 0 || next() % 16 == 0)) {
            command = static_cast<std::uint8_t>(next() % 4 == 0 ? 1 + next() % 3 : 2);
            remaining = static_cast<int>(next() % 6);
        }
        if (!repeat) {  // a repeat sends the last frame's bytes again
            for (auto& x : b) x = static_cast<std::uint8_t>(next());
            b[0] = 0x55, b[1] = 0xAA, b[2] = command, b[3] = static_cast<std::uint8_t>(remaining);
        }
        std::size_t n = 20;
        switch (next() % 32) {
        case 0: b[next() % 2] ^= 0x01; break;
        case 1: n = next() % 23; break;
        case 2: b[3] = static_cast<std::uint8_t>(next() % 8); break;
        default: break;
        }
        const auto st = r.push(std::span<const std::uint8_t>(b.data(), n));
        out += st ? std::to_string(static_cast<int>(*st)) : error_text(st);
        if (st && *st == nb::reassembly::complete) out += "=" + std::string(r.text());
        out += ",";
        repeat = next() % 8 == 0;
        if (!repeat) --remaining;
    }
    return out;
}
std::string outcome(int which, std::span<const std::uint8_t> in) {
    switch (which) {
    case 0: return variant_text(bw::decode_command(in));
    case 1: return variant_text(bw::decode_notification(in));
    case 2: {
        const auto r = robowire::decode<bw::status>(in);
        return r ? encoded_text(robowire::encode(*r)) + (r->pid_state ? "+pid" : "") : error_text(r);
    }
    case 3: {
        bw::status s{};
        s.flags = 0x5A;
        s.pid_state = bw::pid_state{1.5f, 2.5f, 3.5f, 4, 5};
        s.ignored_trailing_bytes = 77;
        const bw::status before = s;
        const robowire::error e = robowire::decode_into(s, in);
        if (e.code != robowire::errc::ok)
            return error_text(e) + (s == before ? "" : " changed");
        return encoded_text(robowire::encode(s)) + (s.pid_state ? "+pid" : "") +
               std::to_string(s.ignored_trailing_bytes);
    }
    case 4:
    case 5: {
        const auto enc = which == 4 ? nb::sign_encoding::twos_complement : nb::sign_encoding::sign_magnitude;
        const auto r = nb::decode_maneuver(in, enc);
        return r ? encoded_text(nb::encode(*r, enc)) : error_text(r);
    }
    case 6: return variant_text(nb::decode_frame(in));
    case 7: return variant_text(osp::decode(in));
    default: return reassembly_text(in);
    }
}

// Addresses of the codecs' out-of-line functions as this file calls them: the
// two files of a program must call their own (different addresses).
std::array<std::uintptr_t, 3> codec_addresses() {
    using encoded = robowire::result<robowire::bytes<robowire::max_size_v<bw::status>>>;
    encoded (*const encode_status)(const bw::status&) noexcept = &robowire::encode<bw::status>;
    return {reinterpret_cast<std::uintptr_t>(&robowire::decode<bw::status>),
            reinterpret_cast<std::uintptr_t>(encode_status),
            reinterpret_cast<std::uintptr_t>(&osp::decode<osp::message>)};
}

}  // namespace MIXED_MODES_FILE
