// robowire.osp: 10-byte frames from osp::message, the stream scanner, units.
#include <robowire/osp.hpp>

#include "codec.hpp"
#include "protocols.hpp"

namespace rwpy {
namespace {
namespace osp = robowire::osp;

PyObject* protocol() {
    static PyObject* p = interned("osp");
    return p;
}

// Decodes a frame; raises DecodeError with osp::describe_error's line (a
// note gives the frame's DEV, CMD and parameters when the markers and length
// were right, as the command-line tool's hint does).
py::dict decode_span(std::span<const std::uint8_t> in) {
    const auto r = osp::decode(in);
    if (r) return variant_dict(protocol(), *r);
    std::vector<std::string> notes;
    if (const auto& f = r.frame())
        notes.push_back("DEV " + hex_of(std::span<const std::uint8_t>(&f->device, 1)) + " CMD " +
                        hex_of(std::span<const std::uint8_t>(&f->command, 1)) + " params " + hex_of(f->params));
    char buf[160];
    raise_decode(osp::describe_error(r.error(), in, buf), r.error(), notes);
}

py::dict decode(py::handle data, py::handle dir) {
    if (!dir.is_none()) throw py::value_error("direction applies to buwizz3 only");
    byte_input bytes(data);
    return decode_span(bytes.span());
}

py::bytes encode(py::handle message, py::kwargs fields) {
    const auto r = encode_args("osp", message, fields);
    py::bytes out;
    if (encode_named<osp::messages::to_device>(r.name, r.fields, r.from_dict, out)) return out;
    throw py::key_error("unknown message " + r.name + " of osp (messages: " + message_names<osp::messages::to_device>() + ")");
}

// The stream scanner: feed(chunk) -> list of message dicts and error dicts.
class scanner {
public:
    py::list feed(py::handle chunk) {
        byte_input bytes(chunk);
        py::list out;
        s_.feed(bytes.span(), [&](osp::scanner::frame_bytes f) {
            try {
                out.append(decode_span(f));
            } catch (py::error_already_set& e) {
                if (!e.matches(classes().decode)) throw;
                py::object err = e.value();
                py::dict d;
                d["type"] = "error";
                d["protocol"] = "osp";
                d["error"] = py::str(err);
                d["bytes"] = hex_of(f);
                d["code"] = err.attr("code");
                d["offset"] = err.attr("offset");
                d["field"] = err.attr("field");
                out.append(d);
            }
        });
        return out;
    }
    py::dict counters() const {
        py::dict d;
        d["type"] = "counters";
        d["frames"] = s_.frames();
        d["skipped_bytes"] = s_.skipped();
        d["false_starts"] = s_.false_starts();
        return d;
    }
    std::uint64_t frames() const { return s_.frames(); }
    std::uint64_t skipped() const { return s_.skipped(); }
    std::uint64_t false_starts() const { return s_.false_starts(); }
    std::size_t pending() const { return s_.pending(); }
    void reset() { s_.reset(); }

private:
    osp::scanner s_;
};

// The helper's value, or EncodeError "fn: arg: <error>" (int_arg's text).
template <class T>
T value_or_raise(const robowire::result<T>& r, std::string_view what) {
    if (!r) raise(classes().encode, std::string(what) + ": " + std::string(robowire::to_string(r.code())), r.code(), r.error().offset, {}, {});
    return *r;
}

}  // namespace

void init_osp(py::module_& m) {
    m.def("decode", decode_entry(&decode),
          "decode(data, direction=None) -> dict. Decodes one 10-byte frame into a dict (the command-line tool's JSON line).");
    m.def("encode", encode_entry(&encode), "encode(name, **fields) or encode(dict as decode returns it) -> bytes.");
    py::class_<scanner>(m, "Scanner", "Finds and decodes OSP frames in a byte stream fed in chunks of any size.")
        .def(py::init<>())
        .def("feed", &scanner::feed, py::arg("chunk"), "Feeds bytes; returns the frames they complete: message dicts and error dicts.")
        .def("counters", &scanner::counters, "{'type': 'counters', 'frames', 'skipped_bytes', 'false_starts'}")
        .def_property_readonly("frames", &scanner::frames)
        .def_property_readonly("skipped_bytes", &scanner::skipped)
        .def_property_readonly("false_starts", &scanner::false_starts)
        .def_property_readonly("pending", &scanner::pending)
        .def("reset", &scanner::reset);
    m.attr("frame_size") = osp::frame_size;

    py::enum_<osp::scale>(m, "scale", "Whose reading of a raw value: the OSP document's or the published firmware's.")
        .value("document", osp::scale::document)
        .value("published_firmware", osp::scale::published_firmware);
    const auto doc = osp::scale::document;
    // OBP-1 battery
    m.def("millivolts", [](const py::int_& raw, osp::scale s) { return osp::obp1::millivolts(int_arg<std::int16_t>(raw, "millivolts", "raw"), s); }, py::arg("raw"), py::arg("scale") = doc);
    m.def("milliamps", [](const py::int_& raw, osp::scale s) { return osp::obp1::milliamps(int_arg<std::int16_t>(raw, "milliamps", "raw"), s); }, py::arg("raw"), py::arg("scale") = doc);
    m.def("soc_basis_points", [](const py::int_& raw, osp::scale s) { return osp::obp1::soc_basis_points(int_arg<std::uint16_t>(raw, "soc_basis_points", "raw"), s); }, py::arg("raw"),
          py::arg("scale") = doc);
    m.def("volts", [](const py::int_& raw, osp::scale s) { return osp::obp1::volts(int_arg<std::int16_t>(raw, "volts", "raw"), s); }, py::arg("raw"), py::arg("scale") = doc);
    m.def("amps", [](const py::int_& raw, osp::scale s) { return osp::obp1::amps(int_arg<std::int16_t>(raw, "amps", "raw"), s); }, py::arg("raw"), py::arg("scale") = doc);
    m.def("soc_percent", [](const py::int_& raw, osp::scale s) { return osp::obp1::soc_percent(int_arg<std::uint16_t>(raw, "soc_percent", "raw"), s); }, py::arg("raw"),
          py::arg("scale") = doc);
    m.def("voltage_from_millivolts",
          [](const py::int_& mv, osp::scale s) {
              const char* fn = "voltage_from_millivolts";
              return value_or_raise(osp::obp1::voltage_from_millivolts(int_arg<std::int32_t>(mv, fn, "millivolts", true), s),
                                    "voltage_from_millivolts: millivolts");
          },
          py::arg("millivolts"), py::arg("scale") = doc);
    m.def("soc_from_basis_points",
          [](const py::int_& bp, osp::scale s) {
              const char* fn = "soc_from_basis_points";
              return value_or_raise(osp::obp1::soc_from_basis_points(int_arg<std::uint16_t>(bp, fn, "basis_points", true), s),
                                    "soc_from_basis_points: basis_points");
          },
          py::arg("basis_points"), py::arg("scale") = doc);
    m.def("soc_from_percent",
          [](double p, osp::scale s) { return value_or_raise(osp::obp1::soc_from_percent(p, s), "soc_from_percent: percent"); },
          py::arg("percent"), py::arg("scale") = doc);
    // ARM-1 arm
    m.def("angle_count", [](const py::int_& raw, osp::scale s) { return osp::arm1::angle_count(int_arg<std::uint16_t>(raw, "angle_count", "raw"), s); }, py::arg("raw"),
          py::arg("scale") = doc);
    m.def("angle_to_radians", [](const py::int_& raw, osp::scale s) { return osp::arm1::angle_to_radians(int_arg<std::uint16_t>(raw, "angle_to_radians", "raw"), s); }, py::arg("raw"),
          py::arg("scale") = doc);
    m.def("angle_from_radians",
          [](double rad, osp::scale s) { return value_or_raise(osp::arm1::angle_from_radians(rad, s), "angle_from_radians: radians"); },
          py::arg("radians"), py::arg("scale") = doc);
}

}  // namespace rwpy
