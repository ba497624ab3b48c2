// robowire.navbot: 20-byte frames from navbot::message, the multi-frame
// reassembler and fragmenter, UUIDs and advertisement checks.
#include <robowire/navbot.hpp>

#include <cstdio>

#include "codec.hpp"
#include "protocols.hpp"
#include "text.hpp"

namespace rwpy {
namespace {
namespace nb = robowire::navbot;

PyObject* protocol() {
    static PyObject* p = interned("navbot");
    return p;
}

using robowire::tools::sign_magnitude_notes;  // the notes the command-line tool gives

// The payload of a JSON frame as text (up to the first zero byte).
std::string payload_text(const nb::frame& f) {
    std::string text;
    for (const std::uint8_t b : f.payload) {
        if (b == 0) break;
        text += static_cast<char>(b);
    }
    return text;
}

py::dict decode(py::handle data, py::handle dir) {
    if (!dir.is_none()) throw py::value_error("direction applies to buwizz3 only");
    byte_input bytes(data);
    const auto in = bytes.span();
    const auto r = nb::decode_frame(in);
    if (!r) {
        auto notes = sign_magnitude_notes(in);
        if (r.code() == robowire::errc::too_long || r.code() == robowire::errc::too_short)
            notes.insert(notes.begin(), std::string(nb::length_error_text(in.size())));
        char buf[160];
        raise_decode(nb::describe_error(r.error(), in, buf), r.error(), notes);
    }
    py::dict d = variant_dict(protocol(), *r);
    if (const auto* f = std::get_if<nb::frame>(&*r); f && f->command == nb::command::json) {
        py::dict fields = d["fields"];
        py::dict reordered;  // payload_text right after payload, as in the tool's JSON
        for (auto item : fields) {
            reordered[item.first] = item.second;
            if (py::str(item.first).cast<std::string>() == "payload") {
                const std::string t = payload_text(*f);
                reordered["payload_text"] =
                    steal(PyUnicode_DecodeUTF8(t.data(), static_cast<Py_ssize_t>(t.size()), "surrogateescape"));
            }
        }
        d["fields"] = reordered;
    }
    const auto notes = sign_magnitude_notes(in);
    if (!notes.empty()) {
        py::list n;
        for (const auto& s : notes) n.append(s);
        d["notes"] = n;
    }
    return d;
}

py::bytes encode(py::handle message, py::kwargs fields) {
    const auto r = encode_args("navbot", message, fields);
    py::bytes out;
    if (encode_named<nb::messages::to_device>(r.name, r.fields, r.from_dict, out)) return out;
    throw py::key_error("unknown message " + r.name + " of navbot (messages: " + message_names<nb::messages::to_device>() + ")");
}

// The frames of one message (fragmenter): payload bytes, or text (UTF-8).
py::list fragment(const py::int_& command_arg, py::handle payload) {
    const auto command = int_arg<std::uint8_t>(command_arg, "fragment", "command");
    py::bytes raw;
    if (PyUnicode_Check(payload.ptr())) raw = utf8_bytes(payload.ptr(), "fragment: payload");
    else raw = steal(PyBytes_FromObject(payload.ptr()));
    const auto* p = reinterpret_cast<const std::uint8_t*>(PyBytes_AS_STRING(raw.ptr()));
    const auto frames = nb::make_frames(command,
                                        std::span<const std::uint8_t>(p, static_cast<std::size_t>(PyBytes_GET_SIZE(raw.ptr()))));
    if (!frames) {
        const auto e = frames.error();
        raise(classes().encode,
              "fragment: " + std::string(robowire::to_string(e.code)) + " (at most " + std::to_string(nb::max_payload) + " payload bytes)",
              e.code, e.offset, {}, {});
    }
    py::list out;
    for (const auto& f : *frames) out.append(py::bytes(reinterpret_cast<const char*>(f.data()), f.size()));
    return out;
}

// A message taken from one frame or several: {"command", "payload", "text"}.
py::dict reassembled(std::uint8_t command, std::span<const std::uint8_t> payload, std::string_view text) {
    py::dict d;
    d["command"] = command;
    d["payload"] = py::bytes(reinterpret_cast<const char*>(payload.data()), payload.size());
    d["text"] = steal(PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape"));
    return d;
}

class reassembler {
public:
    py::tuple push(py::handle data) {
        byte_input bytes(data);
        const auto in = bytes.span();
        const auto r = r_.push(in);
        if (!r) {
            const auto e = r.error();
            char buf[160];
            raise_decode(nb::describe_error(e, in, buf), e);
        }
        static constexpr const char* names[] = {"need_more", "complete", "single", "duplicate", "restarted", "discarded"};
        const auto outcome = *r;
        py::object message = py::none();
        if (outcome == nb::reassembly::complete) {
            message = reassembled(r_.command(), r_.payload(), r_.text());
        } else if (outcome == nb::reassembly::single) {
            const auto f = robowire::decode<nb::frame>(in).value();
            std::string t = payload_text(f);
            message = reassembled(f.command, f.payload, t);
        }
        return py::make_tuple(names[static_cast<int>(outcome)], message);
    }
    // The text as `text` gives it: bytes that are not UTF-8 kept as surrogates.
    py::object json() const {
        const auto j = r_.json();
        if (!j) raise(classes().decode, std::string(robowire::to_string(j.code())) + " at byte " + std::to_string(j.error().offset), j.code(),
                      j.error().offset, {}, {});
        return steal(PyUnicode_DecodeUTF8(j->data(), static_cast<Py_ssize_t>(j->size()), "surrogateescape"));
    }
    bool in_progress() const { return r_.in_progress(); }
    void clear() { r_.clear(); }

private:
    nb::reassembler<nb::max_payload> r_;
};

std::string uuid_text(const robowire::uuid128& u) {
    const auto c = u.to_chars();
    return {c.data(), c.size()};
}

}  // namespace

void init_navbot(py::module_& m) {
    m.def("decode", decode_entry(&decode),
          "decode(data, direction=None) -> dict. Decodes one 20-byte frame into a dict (the command-line tool's JSON line).");
    m.def("encode", encode_entry(&encode), "encode(name, **fields) or encode(dict as decode returns it) -> bytes.");
    m.def("fragment", &fragment, py::arg("command"), py::arg("payload"),
          "The 20-byte frames of one message (payload: bytes, or str sent as UTF-8).");
    py::class_<reassembler>(m, "Reassembler", "Collects the frames of multi-frame messages (up to 256 frames).")
        .def(py::init<>())
        .def("push", &reassembler::push, py::arg("frame"),
             "Takes one frame: (outcome, message); message is a dict when outcome is 'complete' or 'single'.")
        .def("json", &reassembler::json, "The completed message's text if it is one whole JSON object.")
        .def_property_readonly("in_progress", &reassembler::in_progress)
        .def("clear", &reassembler::clear);

    m.attr("frame_size") = nb::frame_size;
    m.attr("payload_size") = nb::payload_size;
    m.attr("max_payload") = nb::max_payload;
    py::module_ types = py::module_::import("types");
    m.attr("command") = types.attr("SimpleNamespace")(py::arg("wifi") = nb::command::wifi, py::arg("json") = nb::command::json,
                                                      py::arg("maneuver") = nb::command::maneuver);
    m.attr("name_prefix") = std::string(nb::name_prefix);
    m.attr("service_uuid") = uuid_text(nb::service_uuid);
    m.attr("write_uuid") = uuid_text(nb::write_uuid);
    m.attr("notify_uuid") = uuid_text(nb::notify_uuid);
    m.def("is_navbot_name", [](const py::str& name) { return nb::is_navbot_name(name_of(name.ptr())); }, py::arg("name"));
    m.def(
        "matches_advertisement", [](py::handle adv) { return nb::matches_advertisement(byte_input(adv).span()); },
        py::arg("advertisement"));
}

}  // namespace rwpy
