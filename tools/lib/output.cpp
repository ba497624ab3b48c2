// The output formats of decode, scan and monitor and the buffer they write
// into (see tools.hpp). Messages are written by emit.hpp; errors and counters here.
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "tools.hpp"

namespace robowire::tools {
namespace {

constexpr output_format formats[] = {
    {"text", "a message as rows of fields", format_kind::text},
    {"json", "one JSON object per line, each with a \"type\" (docs/cli.md)", format_kind::json},
    {"csv", "one table per message type, physical values, time and line first (--message or --out-dir)",
     format_kind::csv},
};

// JSON text that needs no escaping: printable ASCII but '"' and '\\'.
bool plain(std::string_view s) {
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7F || c == '"' || c == '\\') return false;
    }
    return true;
}

void write_all(const buffer& b, FILE* f, std::string& error, const std::string& name) {
    const std::string_view s = b.view();
    if (s.empty() || !f) return;
    if (std::fwrite(s.data(), 1, s.size(), f) != s.size() && error.empty())
        error = "cannot write " + name + ": " + std::strerror(errno);
}

}  // namespace

std::span<const output_format> output_formats() { return formats; }

const output_format* find_output_format(std::string_view name) {
    for (const output_format& f : formats)
        if (f.name == name) return &f;
    return nullptr;
}

template <class Out>
void put_json_string(Out& o, std::string_view s) {
    if (plain(s)) {
        o.append("\"").append(s).append("\"");
        return;
    }
    // escaping and invalid UTF-8: nlohmann/json's writer
    o += nlohmann::json(std::string(s)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

template <class Out>
void put_csv_cell(Out& o, std::string_view s) {
    if (s.find_first_of(",\"\r\n") == std::string_view::npos) {
        o.append(s);
        return;
    }
    o += '"';
    for (const char c : s) {
        if (c == '"') o += '"';
        o += c;
    }
    o += '"';
}

const char* direction_key(link_direction d) {
    switch (d) {
    case link_direction::host_to_device: return "host_to_device";
    case link_direction::device_to_host: return "device_to_host";
    default: return "";
    }
}
const char* direction_text(link_direction d) {
    switch (d) {
    case link_direction::host_to_device: return "host to device";
    case link_direction::device_to_host: return "device to host";
    default: return "";
    }
}

template <class Out>
void put_json_head(Out& o, std::string_view type, const record_meta& meta) {
    o.append("{\"type\":\"").append(type).append("\"");
    if (meta.line) {
        o.append(",\"line\":").append(std::to_string(meta.line));
        if (!meta.time.empty()) o.append(",\"time\":\"").append(meta.time).append("\"");
    }
    if (meta.dir != link_direction::unknown) o.append(",\"direction\":\"").append(direction_key(meta.dir)).append("\"");
    if (!meta.uuid.empty()) {
        o += ",\"uuid\":";
        put_json_string(o, meta.uuid);
    }
    if (!meta.handle.empty()) {
        o += ",\"handle\":";
        put_json_string(o, meta.handle);
    }
}

template <class Out>
void put_text_prefix(Out& o, const record_meta& meta) {
    if (!meta.line) return;
    if (!meta.time.empty()) o.append(meta.time).append(" ");
    o.append("line ").append(std::to_string(meta.line));
    if (meta.dir != link_direction::unknown) o.append(" (").append(direction_text(meta.dir)).append(")");
    o += ": ";
}

#define ROBOWIRE_APPENDERS(Out)                                                   \
    template void put_json_string<Out>(Out&, std::string_view);                   \
    template void put_csv_cell<Out>(Out&, std::string_view);                      \
    template void put_json_head<Out>(Out&, std::string_view, const record_meta&); \
    template void put_text_prefix<Out>(Out&, const record_meta&);
ROBOWIRE_APPENDERS(buffer)
ROBOWIRE_APPENDERS(std::string)
#undef ROBOWIRE_APPENDERS

std::string shorten(std::string_view s, std::size_t max) {
    if (s.size() <= max) return std::string(s);
    return std::string(s.substr(0, max)) + " ... (" + std::to_string(s.size()) + " characters)";
}

// ---- the buffer
struct output::table {
    std::string protocol, message, path;
    buffer buf;
    FILE* f = nullptr;
};

output::output(format_kind k, bool line_buffered) : kind(k), line_buffered_(line_buffered) { buf.reserve(3 << 16); }

output::~output() {
    flush();
    for (table* t : tables_) {
        write_all(t->buf, t->f, write_error, t->path);
        if (t->f) std::fclose(t->f);
        delete t;
    }
}

void output::flush() {
    if (sink) {
        if (!buf.empty()) sink(buf.view());
    } else {
        write_all(buf, stdout, write_error, "stdout");
    }
    buf.clear();
    for (table* t : tables_) {
        write_all(t->buf, t->f, write_error, t->path);
        t->buf.clear();
    }
    if (!sink) std::fflush(stdout);
}

buffer* output::find_table(std::string_view protocol, std::string_view message, bool& found) {
    found = false;
    for (table* t : tables_) {
        if (t->message == message && t->protocol == protocol) {
            found = true;
            if (t->buf.size() >= (1u << 16)) {
                write_all(t->buf, t->f, write_error, t->path);
                t->buf.clear();
            }
            return t->f ? &t->buf : nullptr;
        }
    }
    return nullptr;
}

buffer* output::open_table(std::string_view protocol, std::string_view message, std::string_view header) {
    if (!csv_message.empty() && message != csv_message) return nullptr;
    auto t = std::make_unique<table>();
    t->protocol = protocol;
    t->message = message;
    t->path = out_dir + "/" + std::string(protocol) + "_" + std::string(message) + ".csv";
    t->f = std::fopen(t->path.c_str(), "wb");
    if (!t->f) {
        if (write_error.empty()) write_error = "cannot open " + t->path + ": " + std::strerror(errno);
    } else {
        t->buf.append(header);
        files.push_back(t->path);
    }
    tables_.push_back(t.release());
    return tables_.back()->f ? &tables_.back()->buf : nullptr;
}

bool output::error(const record_meta& meta, std::string_view error, std::string_view text,
                   const std::vector<std::pair<std::string_view, std::string_view>>& extra,
                   const std::vector<std::string>& hints) {
    switch (kind) {
    case format_kind::text:
        if (text.empty()) return false;
        buf.append(text);
        break;
    case format_kind::json:
        put_json_head(buf, "error", meta);
        buf += ",\"error\":";
        put_json_string(buf, error);
        for (const auto& [k, v] : extra) {
            buf.append(",\"").append(k).append("\":");
            put_json_string(buf, v);
        }
        if (!hints.empty()) {
            buf += ",\"hints\":[";
            for (std::size_t i = 0; i < hints.size(); ++i) {
                if (i) buf += ',';
                put_json_string(buf, hints[i]);
            }
            buf += ']';
        }
        buf += "}\n";
        break;
    case format_kind::csv: return false;
    }
    end_record();
    return true;
}

bool output::counters(const std::vector<std::pair<std::string, std::uint64_t>>& counters, std::string_view input,
                      std::string_view text) {
    switch (kind) {
    case format_kind::text: buf.append(text); break;
    case format_kind::json:
        buf += "{\"type\":\"counters\"";
        for (const auto& [k, v] : counters) buf.append(",\"").append(k).append("\":").append(std::to_string(v));
        if (!input.empty()) {
            buf += ",\"input\":";
            put_json_string(buf, input);
        }
        buf += "}\n";
        break;
    case format_kind::csv: return false;
    }
    end_record();
    return true;
}

}  // namespace robowire::tools
