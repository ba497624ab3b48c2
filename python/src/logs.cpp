// robowire._robowire.LogReader: the command-line tool's log reader
// (tools/lib/logs.cpp, tools/lib/input.cpp, tools/lib/output.cpp, compiled into the
// extension) fed line by line, its records handed to Python as they are
// decoded: JSON lines (read_log) or CSV text (to_csv). Memory: one block of
// input, one line and the records of one line.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include "tools.hpp"
#include "protocols.hpp"

namespace rwpy {
namespace {
namespace py = pybind11;
namespace tools = robowire::tools;

class log_reader {
public:
    log_reader(const py::object& source, const std::string& protocol, const std::optional<std::string>& since,
               const std::optional<std::string>& until, const std::string& format, const std::string& message)
        : out_(format == "csv" ? tools::format_kind::csv : tools::format_kind::json, false) {
        if (format != "json" && format != "csv") throw py::value_error("format: json or csv, not '" + format + "'");
        if (!protocol.empty()) {
            p_ = tools::find_protocol(protocol);
            if (!p_)
                throw py::value_error("unknown protocol '" + protocol + "' (" + tools::protocol_names() + ")");
        }
        auto time_of = [](const std::optional<std::string>& t, const char* what) -> std::optional<tools::time_point> {
            if (!t) return std::nullopt;
            auto tp = tools::parse_time_point(*t);
            if (!tp)
                throw py::value_error(std::string(what) + ": '" + *t +
                                      "' is no time (YYYY-MM-DD[THH:MM[:SS[.mmm]]] or HH:MM[:SS[.mmm]])");
            return tp;
        };
        opt_.since = time_of(since, "since");
        opt_.until = time_of(until, "until");
        opt_.quiet = true;
        out_.csv_message = message;
        if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__")) {
            const std::string path = py::str(py::module_::import("os").attr("fspath")(source));
            std::string error;
            if (!in_.open(path, error)) {
                PyErr_SetString(PyExc_OSError, error.c_str());
                throw py::error_already_set();
            }
        } else if (py::hasattr(source, "read")) {
            file_ = source;
            std::string name = "file";
            if (py::hasattr(source, "name")) name = py::str(source.attr("name"));
            in_.open_source([this](char* p, std::size_t n) { return read_file(p, n); }, name);
        } else {
            throw py::type_error("read_log takes a path or a file object (with read()), not " +
                                 std::string(py::str(py::type::of(source).attr("__name__"))));
        }
        out_.sink = [this](std::string_view records) { records_.append(records); };
        decoder_ = std::make_unique<tools::line_decoder>(p_, in_.name, out_, opt_);
    }

    // The records of the next lines that have any ("" at the end of the input):
    // JSON lines, or CSV rows (the header first) in blocks of about 64 KB.
    py::str next() {
        const std::size_t want = out_.kind == tools::format_kind::csv ? (1u << 16) : 1;
        while (records_.size() < want && !done_) {
            step();
            out_.flush();  // (to records_)
        }
        if (error_) {
            error_->restore();
            error_.reset();
            throw py::error_already_set();
        }
        py::str s(records_.data(), records_.size());
        records_.clear();
        return s;
    }
    // The exit status robowire decode --file would have (None until the end).
    py::object status() const { return done_ ? py::object(py::int_(status_)) : py::object(py::none()); }
    std::string name() const { return in_.name; }

private:
    void step() {
        std::string_view line;
        std::size_t length = 0;
        bool ended = true;
        if (!stopped_ && in_.next_line(line, length, ended)) {
            if (!decoder_->feed(++num_, line, length, ended)) stopped_ = true;
            return;
        }
        done_ = true;
        if (error_) return;
        if (!in_.error.empty()) {
            PyErr_SetString(PyExc_OSError, in_.error.c_str());
            error_ = std::make_unique<py::error_already_set>();
            return;
        }
        status_ = decoder_->finish();
    }
    // input_stream's source for a Python file object (bytes, or text as UTF-8).
    std::size_t read_file(char* p, std::size_t n) {
        if (error_) return 0;
        try {
            while (pending_.size() - pending_at_ == 0) {
                pending_.clear();
                pending_at_ = 0;
                py::object chunk = file_.attr("read")(n);
                if (py::isinstance<py::str>(chunk)) {
                    pending_ = chunk.cast<std::string>();
                } else {
                    const py::buffer_info b = py::buffer(chunk).request();
                    pending_.assign(static_cast<const char*>(b.ptr), static_cast<std::size_t>(b.size));
                }
                if (pending_.empty()) return 0;
            }
        } catch (py::error_already_set& e) {
            error_ = std::make_unique<py::error_already_set>(std::move(e));
            return 0;
        }
        const std::size_t k = std::min(n, pending_.size() - pending_at_);
        std::memcpy(p, pending_.data() + pending_at_, k);
        pending_at_ += k;
        return k;
    }

    const tools::protocol* p_ = nullptr;
    tools::log_options opt_;
    tools::output out_;
    tools::input_stream in_;
    std::unique_ptr<tools::line_decoder> decoder_;
    py::object file_;
    std::string pending_, records_;
    std::size_t pending_at_ = 0, num_ = 0;
    std::unique_ptr<py::error_already_set> error_;
    bool done_ = false, stopped_ = false;
    int status_ = 0;
};

}  // namespace

void init_logs(py::module_& m) {
    py::class_<log_reader>(m, "LogReader",
                           "The log reader of `robowire decode --file` (use robowire.read_log and robowire.to_csv).")
        .def(py::init<const py::object&, const std::string&, const std::optional<std::string>&,
                      const std::optional<std::string>&, const std::string&, const std::string&>(),
             py::arg("source"), py::arg("protocol") = "", py::arg("since") = py::none(),
             py::arg("until") = py::none(), py::arg("format") = "json", py::arg("message") = "")
        .def("next", &log_reader::next, "The next records as text (\"\" at the end of the input).")
        .def_property_readonly("status", &log_reader::status, "The exit status of robowire decode --file (None until the end).")
        .def_property_readonly("name", &log_reader::name, "The input's name.");
}

}  // namespace rwpy
