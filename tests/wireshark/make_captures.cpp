// Writes the dissector test captures into DIR, built with robowire's encoders,
// and next to each capture NAME.json: what robowire's own decoders make of
// every packet (message name, every field's values, and for bad packets the
// field the error is about). test_wireshark.py compares tshark's output with it.
#include <robowire/robowire.hpp>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <utility>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "capture_writer.hpp"

namespace bw = robowire::buwizz3;
namespace nb = robowire::navbot;
namespace osp = robowire::osp;
using capture::byte_vector;
using capture::dir;

namespace {

std::string json_string(std::string_view s) {
    std::string o = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') o += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
            o += buf;
        } else {
            o += c;
        }
    }
    return o + '"';
}
// Appends every piece to o (no temporaries chained with +).
template <class... S>
void put(std::string& o, const S&... pieces) {
    ((o += pieces), ...);
}
std::string real(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Field abbreviation -> values, in order (JSON texts).
using field_values = std::map<std::string, std::vector<std::string>>;

template <class M>
void collect(const M& m, const std::string& prefix, field_values& out);

template <class F, class E>
void collect_element(const F& f, const E& e, const std::string& abbr, field_values& out) {
    if constexpr (F::kind == robowire::wire_kind::record) {
        collect(e, abbr, out);
    } else if constexpr (F::kind == robowire::wire_kind::text) {
        out[abbr].push_back(json_string(e.view()));
    } else if constexpr (F::kind == robowire::wire_kind::tail) {
        if (e.size() == 0) return;  // nothing shown
        std::string hex;
        for (std::size_t i = 0; i < e.size(); ++i) {
            char buf[4];
            std::snprintf(buf, sizeof buf, i ? ":%02x" : "%02x", e[i]);
            hex += buf;
        }
        out[abbr].push_back(json_string(hex));
    } else {
        double raw = 0;
        if constexpr (std::is_enum_v<E>) raw = static_cast<double>(static_cast<std::underlying_type_t<E>>(e));
        else raw = static_cast<double>(e);
        out[abbr].push_back(real(raw));
        if (!f.unit.name.empty()) {
            std::string key;
            put(key, abbr, ".value");
            out[key].push_back(real(raw * f.unit.scale + f.unit.offset));
        }
    }
}

// M's named flag bits, or none.
template <class M>
constexpr auto flag_bits_or_none() {
    if constexpr (robowire::has_flag_bits<M>) return robowire::flag_bits_v<M>;
    else return std::array<robowire::flag_bit, 0>{};
}

template <class M>
void collect(const M& m, const std::string& prefix, field_values& out) {
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        std::string abbr;
        put(abbr, prefix, ".", f.name);
        const auto& member = m.*(f.member);
        auto value = [&](const auto& v) {
            if constexpr (F::is_array)
                for (const auto& e : v) collect_element(f, e, abbr, out);
            else
                collect_element(f, v, abbr, out);
        };
        if constexpr (F::is_optional) {
            if (member) value(*member);
        } else {
            value(member);
        }
        // The named bits of a flag byte (core/flag_bits.hpp), each its own field.
        if constexpr (F::kind == robowire::wire_kind::u8 && !F::is_array && !F::is_optional)
            for (const robowire::flag_bit& b : flag_bits_or_none<M>())
                if (b.field == f.name) {
                    std::string key;
                    put(key, abbr, ".", b.name);
                    const unsigned bits = (static_cast<unsigned>(member) >> b.lo) & ((1u << b.width) - 1u);
                    out[key].push_back(real(static_cast<double>(bits)));
                }
    });
}

// Name of the field of M at byte `offset` ("" if none), records as a.b.
template <class M>
std::string field_at(std::size_t offset, std::size_t base = 0, bool descend = true) {
    std::string found;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (!found.empty() || offset < base + f.offset || offset >= base + f.end()) return;
        found = std::string(f.name);
        if constexpr (F::kind == robowire::wire_kind::record) {
            if (!descend) return;
            const std::size_t k = (offset - base - f.offset) / F::element_size;
            const std::string inner =
                field_at<typename F::element_type>(offset, base + f.offset + k * F::element_size);
            if (!inner.empty()) put(found, ".", inner);
        }
    });
    return found;
}

// One packet's expectation: a list of messages (JSON objects).
struct expectations {
    std::map<std::size_t, std::vector<std::string>> packets;  // packet number (1-based) -> messages
    std::size_t count = 0;
    std::size_t noise = 0;
    std::string protocol;

    void none() { packets[++count]; }
    void next() { ++count; }
    template <class M>
    void message(const M& m, const std::string& extra = {}) {
        field_values values;
        const std::string name(robowire::table_v<M>.name);
        std::string prefix;
        put(prefix, protocol, ".", name);
        collect(m, prefix, values);
        std::string o;
        put(o, "{\"message\":", json_string(name), ",\"fields\":{");
        bool first = true;
        for (const auto& [k, v] : values) {
            put(o, first ? "" : ",", json_string(k), ":[");
            for (std::size_t i = 0; i < v.size(); ++i) put(o, i ? "," : "", v[i]);
            o += "]";
            first = false;
        }
        put(o, "}", extra, "}");
        packets[count].push_back(o);
    }
    // A packet robowire rejects: `message` (null: unknown) and the text the warning must contain.
    void bad(const std::string& message, const std::string& expert) {
        std::string o;
        put(o, "{\"message\":", message.empty() ? std::string("null") : json_string(message), ",\"expert\":",
            json_string(expert), "}");
        packets[count].push_back(o);
    }
    bool save(const std::string& path) const {
        std::string o;
        put(o, "{\"protocol\":", json_string(protocol), ",\"noise\":", std::to_string(noise), ",\"packets\":{");
        bool first = true;
        for (const auto& [n, msgs] : packets) {
            put(o, first ? "\"" : ",\"", std::to_string(n), "\":[");
            for (std::size_t i = 0; i < msgs.size(); ++i) put(o, i ? "," : "", msgs[i]);
            o += "]";
            first = false;
        }
        o += "}}\n";
        return capture::write_file(path, byte_vector(o.begin(), o.end()));
    }
};

// What a decode error is about: the field at its offset.
// (a length error: the field or block that is cut short, not a field inside it)
template <class M>
std::string error_field(const robowire::error& e) {
    return field_at<M>(e.offset, 0, e.code != robowire::errc::bad_length);
}

// ---------------------------------------------------------------- BLE sessions
constexpr std::uint16_t conn = 0x0040;

byte_vector acl(const byte_vector& att) {
    byte_vector o{0x02};
    capture::put_le(o, conn | 0x2000, 2);
    capture::put_le(o, att.size() + 4, 2);
    capture::put_le(o, att.size(), 2);
    capture::put_le(o, 0x0004, 2);
    o.insert(o.end(), att.begin(), att.end());
    return o;
}
byte_vector att(std::uint8_t opcode, std::uint16_t handle, std::span<const std::uint8_t> value) {
    byte_vector o{opcode};
    capture::put_le(o, handle, 2);
    o.insert(o.end(), value.begin(), value.end());
    return o;
}

// Both BLE capture formats at once.
struct ble_capture {
    capture::pcap pcap{201, true};
    capture::btsnoop snoop;
    expectations exp;
    void add(dir d, const byte_vector& h4) {
        pcap.add(d, h4);
        snoop.add(d, h4);
    }
    // Connection, MTU exchange and GATT discovery of the given characteristics (handle, UUID).
    void open(const std::vector<std::pair<std::uint16_t, robowire::uuid128>>& chars) {
        byte_vector ev{0x04, 0x3e, 19, 0x01, 0x00};
        capture::put_le(ev, conn, 2);
        byte_vector rest{0x00, 0x01, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x18, 0x00, 0x00, 0x00, 0xf4, 0x01, 0x00};
        ev.insert(ev.end(), rest.begin(), rest.end());
        add(dir::received, ev);
        exp.none();
        add(dir::sent, acl({0x02, 247, 0}));  // Exchange MTU Request
        exp.none();
        add(dir::received, acl({0x03, 247, 0}));
        exp.none();
        add(dir::sent, acl({0x08, 0x01, 0x00, 0xff, 0xff, 0x03, 0x28}));  // Read By Type: characteristics
        exp.none();
        byte_vector rsp{0x09, 21};
        for (const auto& [handle, uuid] : chars) {
            capture::put_le(rsp, handle - 1, 2);
            rsp.push_back(0x1e);  // write without response, write, notify, read
            capture::put_le(rsp, handle, 2);
            const auto b = uuid.on_air();
            rsp.insert(rsp.end(), b.begin(), b.end());
        }
        add(dir::received, acl(rsp));
        exp.none();
    }
};

template <class M>
void bw_command(ble_capture& c, const M& m, bool with_response = false) {
    const auto bytes = robowire::encode(m);
    if (!bytes) std::abort();
    c.add(dir::sent, acl(att(with_response ? 0x12 : 0x52, 0x0011, bytes->span())));
    c.exp.next();
    const auto d = bw::decode_command(bytes->span());  // robowire's own decode of the same bytes
    if (!d) std::abort();
    std::visit([&](const auto& x) { c.exp.message(x); }, *d);
    if (with_response) {
        c.add(dir::received, acl({0x13}));
        c.exp.none();
    }
}
template <class M>
void bw_notify(ble_capture& c, const M& m) {
    const auto bytes = robowire::encode(m);
    if (!bytes) std::abort();
    c.add(dir::received, acl(att(0x1b, 0x0011, bytes->span())));
    c.exp.next();
    const auto d = bw::decode_notification(bytes->span());
    if (!d) std::abort();
    std::visit([&](const auto& x) { c.exp.message(x); }, *d);
}
// A command with one byte changed: robowire rejects it; the warning names the field.
template <class M>
void bw_bad_command(ble_capture& c, const M& m, std::size_t offset, std::uint8_t value) {
    auto bytes = robowire::encode(m);
    if (!bytes) std::abort();
    (*bytes)[offset] = value;
    c.add(dir::sent, acl(att(0x52, 0x0011, bytes->span())));
    c.exp.next();
    const auto d = bw::decode_command(bytes->span());
    if (d) std::abort();
    if (d.error().code == robowire::errc::unknown_message) c.exp.bad("", "unknown command");
    else c.exp.bad(std::string(robowire::table_v<M>.name), error_field<M>(d.error()));
}

bool buwizz3_session(const std::string& dir_path) {
    ble_capture c;
    c.exp.protocol = "buwizz3";
    c.open({{0x0011, bw::application_uuid}});
    bw_command(c, bw::set_device_name{"robowire"}, true);
    bw_command(c, bw::set_motion_wakeup{true, 600, 30});
    bw_command(c, bw::set_accel_calibration{{1.5f, -0.25f, 3.0f, 0.125f, -8.5f, 1e-3f}});
    bw_command(c, bw::read_accel_calibration{});
    bw_command(c, bw::set_motor_data{{127, -127, 0, 64, -1, 10}, 0x05, 0x3f});
    bw_command(c, bw::set_motor_data_extended{{100000, -100000, 0, 7}, {-50, 50}, 0x01, 0x02});
    bw_command(c, bw::set_data_period{25}, true);
    bw_command(c, bw::set_ramp_rates{{1, 2, 3, 4, 5, 6}, {10, 20, 30, 40, 50, 60}});
    bw_command(c, bw::set_motor_timeout{3});
    bw_command(c, bw::activate_watchdog{5});
    bw_command(c, bw::set_led_status{});
    bw_command(c, bw::set_led_status{std::array<bw::rgb, 4>{{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {1, 2, 3}}},
                                     std::nullopt});
    bw_command(c, bw::set_led_status{std::array<bw::rgb, 4>{{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {1, 2, 3}}},
                                     std::array<bw::blink, 4>{{{1, 2}, {15, 15}, {0, 7}, {8, 0}}}});
    bw_command(c, bw::set_accel_lpf{bw::lpf_setting::hz_6_25});
    bw_command(c, bw::set_current_limits{{10, 20, 30, 40, 50, 60}});
    bw_command(c, bw::set_uart_baudrate{2, 921600});
    bw_command(c, bw::set_pu_port_function{{bw::port_function::generic_pwm, bw::port_function::pu_speed_servo,
                                            bw::port_function::pu_position_servo,
                                            bw::port_function::pu_absolute_position_servo}});
    bw_command(c, bw::enable_pid_reporting{2});
    bw_command(c, bw::set_servo_reference{{1, -2, 360, -720}});
    bw_command(c, bw::set_pid_parameters{1, 0.5f, 0.25f, 0.75f, 2.5f, 0.01f, 0.2f, 100.0f, 3.5f, 127, 5, 10,
                                         bw::port_function::pu_position_servo});
    bw_command(c, bw::activate_shelf_mode{});
    bw_command(c, bw::check_charger_settings{});
    bw::status s{};
    s.flags = 0x5a;
    s.battery_voltage_raw = 80;  // 13.0 V
    s.motor_current_raw = {1, 2, 3, 100, 200, 255};
    s.temperature_c = 31;
    s.accel_raw = {-16, 16000, -32768};
    s.bootloader_response = {0x11, 0x22, {1, 2, 3}};
    s.charge_current_ma = 120;
    s.pu_motors = {{{0x26, -5, -180, -123456}, {0x30, 100, 179, 987654}, {0, 0, 0, 0}, {0x4b, -128, 90, 1}}};
    bw_notify(c, s);  // 54 bytes
    s.pid_state = bw::pid_state{12.5f, -0.5f, 99.0f, -3, 127};
    bw_notify(c, s);  // 68 bytes
    bw_notify(c, bw::accel_calibration{{1.0f, 2.0f, -3.0f, 0.5f, 0.0f, 1e6f}});
    bw::charger_settings cs{};
    for (std::uint8_t i = 0; i < 20; ++i) (void)cs.data.push_back(static_cast<std::uint8_t>(i * 7));
    bw_notify(c, cs);
    // Bad values: out of range, invalid enum, unknown command.
    bw_bad_command(c, bw::set_data_period{25}, 1, 5);
    bw_bad_command(c, bw::set_accel_lpf{}, 1, 0x07);
    bw_bad_command(c, bw::set_pid_parameters{}, 34, 0);
    bw_bad_command(c, bw::set_motor_data{}, 0, 0x99);
    {  // a status with a truncated PID block (60 bytes): wrong length
        auto bytes = robowire::encode(s);
        if (!bytes) std::abort();
        bytes->resize(60);
        c.add(dir::received, acl(att(0x1b, 0x0011, bytes->span())));
        c.exp.next();
        const auto d = bw::decode_notification(bytes->span());
        if (d || d.error().code != robowire::errc::bad_length) std::abort();
        c.exp.bad("status", error_field<bw::status>(d.error()));
    }
    return c.pcap.save(dir_path + "/buwizz3.pcap") && c.snoop.save(dir_path + "/buwizz3.btsnoop") &&
           c.exp.save(dir_path + "/buwizz3.json");
}

// NAVBOT: writes on 0x0011 (write UUID), echoes notified on 0x0013 (notify UUID).
void nb_frame(ble_capture& c, std::span<const std::uint8_t> bytes, bool notify, const std::string& json_text = {}) {
    c.add(notify ? dir::received : dir::sent, acl(att(notify ? 0x1b : 0x52, notify ? 0x0013 : 0x0011, bytes)));
    c.exp.next();
    const auto d = nb::decode_frame(bytes);
    if (!d) std::abort();
    std::string extra;
    if (!json_text.empty()) put(extra, ",\"json\":", json_string(json_text));
    std::visit([&](const auto& x) { c.exp.message(x, extra); }, *d);
}

bool navbot_session(const std::string& dir_path) {
    ble_capture c;
    c.exp.protocol = "navbot";
    c.open({{0x0011, nb::write_uuid}, {0x0013, nb::notify_uuid}});
    const nb::maneuver moves[] = {
        {},
        {-100, 100, 100, -100, nb::switch_a::start, nb::switch_b::mark, nb::switch_c::lock, nb::switch_d::ball_poise, -5, 5},
        {10, 50, -10, 0, nb::switch_a::start_touch_panel, nb::switch_b::posture, nb::switch_c::unlock,
         nb::switch_d::pitch_adjust, 3, -3},
    };
    for (const auto& m : moves) {
        const auto b = nb::encode(m);
        if (!b) std::abort();
        nb_frame(c, b->span(), false);
        nb_frame(c, b->span(), true);  // the robot echoes it
    }
    // A multi-frame JSON request and a three-frame reply, each reassembled by robowire.
    for (const auto& [text, notify] : {std::pair<std::string_view, bool>{R"({"type":"get_device_info"})", false},
                                       {R"({"type":"device_info","fw":"1.2.3","battery":87})", true}}) {
        const auto frames = nb::json_frames(text);
        if (!frames) std::abort();
        nb::reassembler<240> r;
        for (const auto f : *frames) {
            const auto state = r.push(f.span());
            if (!state) std::abort();
            nb_frame(c, f.span(), notify, *state == nb::reassembly::complete ? std::string(r.text()) : std::string());
        }
    }
    // Bad values: roll out of range, invalid switch A.
    for (const auto& [offset, value] : {std::pair<std::size_t, std::uint8_t>{5, 120}, {9, 5}}) {
        auto b = nb::encode(nb::maneuver{});
        if (!b) std::abort();
        (*b)[offset] = value;
        c.add(dir::sent, acl(att(0x52, 0x0011, b->span())));
        c.exp.next();
        const auto d = nb::decode_frame(b->span());
        if (d) std::abort();
        c.exp.bad("maneuver", error_field<nb::maneuver>(d.error()));
    }
    return c.pcap.save(dir_path + "/navbot.pcap") && c.snoop.save(dir_path + "/navbot.btsnoop") &&
           c.exp.save(dir_path + "/navbot.json");
}

// ---------------------------------------------------------------- OSP stream
template <std::size_t... I>
void osp_bad(expectations& exp, const osp::frame& f, const robowire::error& e, std::index_sequence<I...>) {
    auto one = [&](auto index) {
        using M = std::variant_alternative_t<decltype(index)::value, osp::message>;
        const auto& fx = robowire::table_v<M>.fixed;
        if (fx[2].value == f.device && fx[3].value == f.command)
            exp.bad(std::string(robowire::table_v<M>.name), error_field<M>(e));
    };
    (one(std::integral_constant<std::size_t, I>{}), ...);
}

struct osp_stream {
    capture::pcapng file{147};
    expectations exp;
    osp::scanner host_rx, device_rx;  // one per direction
    void add(dir d, const byte_vector& chunk) {
        file.add(d, chunk);
        exp.next();
        exp.packets[exp.count];
        auto& sc = d == dir::received ? host_rx : device_rx;
        const auto skipped = sc.skipped();
        sc.feed(chunk, [&](osp::scanner::frame_bytes f) {
            const auto r = osp::decode(f);
            if (r) {
                std::visit([&](const auto& x) { exp.message(x); }, *r);
            } else if (r.error().code == robowire::errc::unknown_message) {
                exp.bad("", "unknown command");
            } else if (r.frame()) {
                // a field error: the message its DEV and CMD name
                osp_bad(exp, *r.frame(), r.error(), std::make_index_sequence<std::variant_size_v<osp::message>>{});
            } else {
                std::abort();
            }
        });
        exp.noise += static_cast<std::size_t>(sc.skipped() - skipped);
    }
};

template <class M>
byte_vector osp_bytes(const M& m) {
    const auto b = robowire::encode(m);
    if (!b) std::abort();
    return byte_vector(b->begin(), b->end());
}
byte_vector cat(std::initializer_list<byte_vector> parts) {
    byte_vector o;
    for (const auto& p : parts) o.insert(o.end(), p.begin(), p.end());
    return o;
}

bool osp_session(const std::string& dir_path) {
    osp_stream s;
    s.exp.protocol = "osp";
    // Host -> device requests; one frame per record, then several, then split.
    s.add(dir::sent, osp_bytes(osp::generic::request_device_type{}));
    s.add(dir::received, osp_bytes(osp::generic::device_type{osp::device_type::obp1}));
    s.add(dir::sent, cat({osp_bytes(osp::obp1::request_soc{}), osp_bytes(osp::obp1::request_voltage{}),
                          osp_bytes(osp::obp1::request_current{}), osp_bytes(osp::obp1::request_status{})}));
    // Device -> host answers with noise and a false start, one frame split across three records.
    const byte_vector soc = osp_bytes(osp::obp1::soc{49151});
    const byte_vector volts = osp_bytes(osp::obp1::voltage{-1234});
    const byte_vector amps = osp_bytes(osp::obp1::current{32767});
    s.add(dir::received, cat({{0x00, 0x13, 0xff, 0x00}, soc, {0xff, 0xaa, 0x02}}));
    s.add(dir::received, cat({{0x11, 0x00, 0x00, 0x00, 0x00, 0x00, 0x12}, byte_vector(volts.begin(), volts.begin() + 4)}));
    s.add(dir::sent, osp_bytes(osp::arm1::set_angle{3, 16384}));
    s.add(dir::received, byte_vector(volts.begin() + 4, volts.begin() + 7));
    s.add(dir::received, cat({byte_vector(volts.begin() + 7, volts.end()), amps,
                              osp_bytes(osp::obp1::status{osp::obp1::state::charging, 0x05})}));
    // Bad values: an invalid device type, an unknown command.
    auto bad = osp_bytes(osp::generic::device_type{});
    bad[4] = 9;
    s.add(dir::received, bad);
    s.add(dir::sent, byte_vector{0xff, 0xaa, 0x02, 0x7e, 0, 0, 0, 0, 0x55, 0x77});
    return s.file.save(dir_path + "/osp.pcapng") && s.exp.save(dir_path + "/osp.json");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fputs("usage: robowire_wireshark_captures DIR\n", stderr);
        return 2;
    }
    const std::string dir_path = argv[1];
    if (!buwizz3_session(dir_path) || !navbot_session(dir_path) || !osp_session(dir_path)) {
        std::fputs("cannot write the captures\n", stderr);
        return 1;
    }
    return 0;
}
