// robowire.buwizz3: commands (host -> device) and notifications (device ->
// host) from the descriptor's buwizz3::messages (commands, notifications); units, UUIDs, the
// advertisement parser.
#include <robowire/buwizz3.hpp>

#include <cstdio>

#include "codec.hpp"
#include "protocols.hpp"

namespace rwpy {
namespace {
namespace bw = robowire::buwizz3;
using commands = bw::messages::to_device;
using notifications = bw::messages::from_device;

PyObject* protocol() {
    static PyObject* p = interned("buwizz3");
    return p;
}

using robowire::tools::hex2;

// The message of variant V whose command byte is `cmd`.
struct candidate {
    bool found = false;
    bool fits = false;  // the length is within the message's min..max input
    std::string name, lengths;
};
template <class V>
candidate by_command(std::uint8_t cmd, std::size_t len) {
    candidate c;
    const std::uint8_t key[] = {cmd};
    robowire::with_alternative<V>(robowire::alternative_by_key<V, 0>(key), [&](auto t) {
        using M = typename decltype(t)::type;
        constexpr auto& tab = robowire::table_v<M>;
        c = {true, len >= tab.min_size() && len <= tab.max_input(), std::string(tab.name), valid_lengths<M>()};
    });
    return c;
}

enum class direction { any, command, notification };

// Decodes in one direction; DecodeError: describe_error's line, `note` (the
// other direction's reading of the command byte) as a note.
py::dict decode_as(std::span<const std::uint8_t> in, direction d, std::string note = {}) {
    std::vector<std::string> notes;
    if (!note.empty()) notes.push_back(std::move(note));
    char buf[160];
    if (d == direction::command) {
        const auto r = bw::decode_command(in);
        if (!r) raise_decode(robowire::describe_error<commands>(r.error(), in, buf), r.error(), notes);
        return variant_dict(protocol(), *r);
    }
    const auto r = bw::decode_notification(in);
    if (!r) raise_decode(robowire::describe_error<notifications>(r.error(), in, buf), r.error(), notes);
    return variant_dict(protocol(), *r);
}

// The direction as the command-line tool works it out: given, or by the
// command byte, or (0x23, 0xAC) by the length.
py::dict decode(py::handle data, py::handle dir) {
    byte_input bytes(data);
    const auto in = bytes.span();
    direction d = direction::any;
    if (!dir.is_none()) {
        const auto s = PyUnicode_Check(dir.ptr()) ? name_of(dir.ptr()) : std::string();
        if (s == "command") d = direction::command;
        else if (s == "notification") d = direction::notification;
        else throw py::value_error("direction: 'command', 'notification' or None, got " + shorten(py::repr(dir).cast<std::string>()));
    }
    if (in.empty()) return decode_as(in, d == direction::any ? direction::command : d);
    const auto c = by_command<commands>(in[0], in.size());
    const auto n = by_command<notifications>(in[0], in.size());
    if (d == direction::command)
        return decode_as(in, d, !c.found && n.found ? hex2(in[0]) + " is the notification " + n.name : "");
    if (d == direction::notification)
        return decode_as(in, d, !n.found && c.found ? hex2(in[0]) + " is the command " + c.name : "");
    if (c.found && !n.found) return decode_as(in, direction::command);
    if (n.found && !c.found) return decode_as(in, direction::notification);
    if (!c.found && !n.found)
        return decode_as(in, direction::command, hex2(in[0]) + " is no BuWizz3 command or notification");
    if (c.fits && !n.fits) return decode_as(in, direction::command);
    if (n.fits && !c.fits) return decode_as(in, direction::notification);
    const std::string which = hex2(in[0]) + " is the command " + c.name + " (" + c.lengths + ") and the notification " + n.name +
                              " (" + n.lengths + "); " + std::to_string(in.size()) + (in.size() == 1 ? " byte" : " bytes") + " given";
    if (c.fits && n.fits) throw py::value_error(which + ": pass direction='command' or direction='notification'");
    return decode_as(in, direction::command, which);
}

py::bytes encode(py::handle message, py::kwargs fields) {
    const auto r = encode_args("buwizz3", message, fields);
    py::bytes out;
    if (encode_named<commands>(r.name, r.fields, r.from_dict, out)) return out;
    if (encode_named<notifications>(r.name, r.fields, r.from_dict, out)) return out;
    throw py::key_error("unknown message " + r.name + " of buwizz3 (commands: " + message_names<commands>() +
                        "; notifications: " + message_names<notifications>() + ")");
}

template <class T>
T value_or_raise(const robowire::result<T>& r, std::string_view what) {
    if (!r) raise(classes().encode, std::string(what) + ": " + std::string(robowire::to_string(r.code())), r.code(), r.error().offset, {}, {});
    return *r;
}

bw::lpf_setting lpf_of(py::handle setting) {
    if (PyUnicode_Check(setting.ptr())) {
        if (const auto e = robowire::enum_from_name<bw::lpf_setting>(name_of(setting.ptr()))) return *e;
    } else if (PyLong_Check(setting.ptr())) {
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(setting.ptr(), &overflow);
        if (!overflow && v >= 0 && v <= 255 && robowire::is_valid_enum(static_cast<bw::lpf_setting>(v))) return static_cast<bw::lpf_setting>(v);
    } else {
        throw py::type_error("setting: a name such as 'hz_50' or a code");
    }
    raise(classes().encode, "lpf_hz: setting: value is not a valid code", robowire::errc::invalid_enum, 1, {}, {});
}

std::string uuid_text(const robowire::uuid128& u) {
    const auto c = u.to_chars();
    return {c.data(), c.size()};
}

}  // namespace

void init_buwizz3(py::module_& m) {
    m.def("decode", decode_entry(&decode),
          "decode(data, direction=None) -> dict. Decodes a command or a notification into a dict (the command-line tool's JSON line).");
    m.def("encode", encode_entry(&encode),
          "encode(name, **fields) or encode(dict as decode returns it) -> bytes.");

    // units (status report)
    m.def("battery_volts", [](const py::int_& raw) { return bw::battery_volts(int_arg<std::uint8_t>(raw, "battery_volts", "raw")); }, py::arg("raw"));
    m.def("motor_amps", [](const py::int_& raw) { return bw::motor_amps(int_arg<std::uint8_t>(raw, "motor_amps", "raw")); }, py::arg("raw"));
    m.def("accel_count", [](const py::int_& word) { return bw::accel_count(int_arg<std::int16_t>(word, "accel_count", "word")); }, py::arg("word"));
    m.def("accel_milli_g", [](const py::int_& word) { return bw::accel_milli_g(int_arg<std::int16_t>(word, "accel_milli_g", "word")); }, py::arg("word"));
    m.def("battery_millivolts", [](const py::int_& raw) { return bw::battery_millivolts(int_arg<std::uint8_t>(raw, "battery_millivolts", "raw")); }, py::arg("raw"));
    m.def("motor_milliamps", [](const py::int_& raw) { return bw::motor_milliamps(int_arg<std::uint8_t>(raw, "motor_milliamps", "raw")); }, py::arg("raw"));
    m.def("accel_micro_g", [](const py::int_& word) { return bw::accel_micro_g(int_arg<std::int16_t>(word, "accel_micro_g", "word")); }, py::arg("word"));
    m.def("accel_milli_g_rounded", [](const py::int_& word) { return bw::accel_milli_g_rounded(int_arg<std::int16_t>(word, "accel_milli_g_rounded", "word")); }, py::arg("word"));
    // units (commands)
    m.def("lpf_hz", [](py::handle s) { return bw::lpf_hz(lpf_of(s)); }, py::arg("setting"));
    m.def("lpf_from_hz", [](double hz) { return std::string(robowire::enum_name(value_or_raise(bw::lpf_from_hz(hz), "lpf_from_hz: hz"))); },
          py::arg("hz"));
    m.def("ramp_rate_from_seconds", [](double s) { return value_or_raise(bw::ramp_rate_from_seconds(s), "ramp_rate_from_seconds: seconds"); },
          py::arg("seconds"));
    m.def("ramp_seconds", [](const py::int_& rate) { return bw::ramp_seconds(int_arg<std::uint8_t>(rate, "ramp_seconds", "rate")); }, py::arg("rate"));
    m.def("current_limit_raw",
          [](double ma, double step) { return value_or_raise(bw::current_limit_raw(ma, step), "current_limit_raw: milliamps"); },
          py::arg("milliamps"), py::arg("step_ma") = bw::default_current_step_ma);
    m.def("current_limit_ma", [](const py::int_& raw, double step) { return bw::current_limit_ma(int_arg<std::uint8_t>(raw, "current_limit_ma", "raw"), step); }, py::arg("raw"),
          py::arg("step_ma") = bw::default_current_step_ma);
    m.def("k_lp_from_cutoff", [](double f) { return value_or_raise(bw::k_lp_from_cutoff(f), "k_lp_from_cutoff: hz"); }, py::arg("hz"));
    m.attr("default_current_step_ma") = bw::default_current_step_ma;
    m.def("position_servo_preset", [](const py::int_& port) { return message_dict(protocol(), bw::position_servo_preset(int_arg<std::uint8_t>(port, "position_servo_preset", "port", true))); },
          py::arg("port"));
    m.def("speed_servo_preset", [](const py::int_& port) { return message_dict(protocol(), bw::speed_servo_preset(int_arg<std::uint8_t>(port, "speed_servo_preset", "port", true))); },
          py::arg("port"));
    m.def("generic_pid_preset",
          [](const py::int_& port, py::handle mode) {
              bw::port_function f{};
              const auto bad = [] {
                  raise(classes().encode, "generic_pid_preset: mode: value is not a valid code", robowire::errc::invalid_enum, 37, {}, {});
              };
              if (PyUnicode_Check(mode.ptr())) {
                  const auto e = robowire::enum_from_name<bw::port_function>(name_of(mode.ptr()));
                  if (!e) bad();
                  f = *e;
              } else if (PyLong_Check(mode.ptr())) {
                  int overflow = 0;
                  const long long v = PyLong_AsLongLongAndOverflow(mode.ptr(), &overflow);
                  if (overflow || v < 0 || v > 255 || !robowire::is_valid_enum(static_cast<bw::port_function>(v))) bad();
                  f = static_cast<bw::port_function>(v);
              } else {
                  throw py::type_error("generic_pid_preset: mode: a name such as 'pid_position' or a code, got " + type_name(mode.ptr()));
              }
              return message_dict(protocol(), bw::generic_pid_preset(int_arg<std::uint8_t>(port, "generic_pid_preset", "port", true), f));
          },
          py::arg("port"), py::arg("mode"));
    m.def("default_current_limits", [] { return message_dict(protocol(), bw::default_current_limits); });

    // UUIDs
    m.attr("service_uuid") = uuid_text(bw::service_uuid);
    m.attr("application_uuid") = uuid_text(bw::application_uuid);
    m.attr("bootloader_uuid") = uuid_text(bw::bootloader_uuid);
    m.def("uart_characteristic", [](const py::int_& n) {
              const char* fn = "uart_characteristic";
              return uuid_text(value_or_raise(bw::uart_characteristic(int_arg<int>(n, fn, "port", true)), "uart_characteristic: port"));
          },
          py::arg("port"));

    // advertisement
    m.def(
        "parse_advertisement",
        [](py::handle adv, py::handle scan_response) -> py::object {
            byte_input a(adv);
            std::optional<byte_input> s;
            if (!scan_response.is_none()) s.emplace(scan_response);
            const auto r = bw::parse_advertisement(a.span(), s ? s->span() : std::span<const std::uint8_t>{});
            if (!r) {
                const auto e = r.error();
                raise(classes().decode,
                      "advertisement: " + std::string(robowire::to_string(e.code)) + " at byte " + std::to_string(e.offset), e.code, e.offset,
                      {}, {});
            }
            if (!*r) return py::none();
            const auto& x = **r;
            static constexpr const char* modes[] = {"unknown", "application", "bootloader"};
            py::dict d;
            d["mode"] = modes[static_cast<int>(x.mode)];
            d["firmware_version"] = py::make_tuple(x.firmware_version[0], x.firmware_version[1]);
            d["serial_low16"] = x.serial_low16;
            d["has_manufacturer_data"] = x.has_manufacturer_data;
            d["has_service_uuid"] = x.has_service_uuid;
            if (x.local_name) {
                const auto n = x.local_name->view();  // any bytes: not necessarily UTF-8
                d["local_name"] = steal(PyUnicode_DecodeUTF8(n.data(), static_cast<Py_ssize_t>(n.size()), "replace"));
            } else {
                d["local_name"] = py::none();
            }
            return d;
        },
        py::arg("advertisement"), py::arg("scan_response") = py::none(),
        "A BuWizz3's advertisement (and scan response) as a dict, or None when it is not a BuWizz3.");
}

}  // namespace rwpy
