// robowire._robowire: the extension behind the robowire package. One
// submodule per protocol (buwizz3.cpp, navbot.cpp, osp.cpp, each its own
// translation unit so that they compile in parallel), plus the schema, the
// error codes and the log reader (logs.cpp, on the command-line tool's).
#include <robowire/protocols.hpp>

#include "codec.hpp"
#include "protocols.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_robowire, m) {
    m.doc() = "robowire's codecs, built from the library's tables (use the robowire package)";
    py::module_ errors = py::module_::import("robowire._errors");
    auto& c = rwpy::classes();
    c.decode = py::object(errors.attr("DecodeError")).release().ptr();
    c.encode = py::object(errors.attr("EncodeError")).release().ptr();

    m.def("schema_json", [](const std::string& protocol) { return robowire::schema::all(protocol).dump(); }, py::arg("protocol") = "",
          "The tables as JSON text (the format of `robowire list --json`).");
    py::dict codes;
    for (const auto& row : robowire::errc_table) {
        codes[py::str(std::string(row.name))] = py::str(std::string(row.text));
    }
    m.attr("error_codes") = codes;

    py::list names;  // the descriptors' names, in `list` order
    for (const auto* d : robowire::all_protocols) names.append(py::str(d->name.data(), d->name.size()));
    m.attr("protocols") = names;

    py::module_ buwizz3 = m.def_submodule("buwizz3", "BuWizz3");
    py::module_ navbot = m.def_submodule("navbot", "NAVBOT-ES02");
    py::module_ osp = m.def_submodule("osp", "OSP");
    rwpy::init_buwizz3(buwizz3);
    rwpy::init_navbot(navbot);
    rwpy::init_osp(osp);
    rwpy::init_logs(m);
}
