// The output formats of decode, scan and monitor: what each prints of a record
// (its JSON object and its text, see cli.hpp). A new format: one entry in formats().
#include <cstdio>

#include "cli.hpp"

namespace robowire::cli {
namespace {

void out(const std::string& s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fflush(stdout);
}

bool print_text(const std::string&, const std::string& text) {
    out(text);
    return !text.empty();
}
bool print_json(const std::string& json, const std::string&) {
    out(json + "\n");
    return false;
}

constexpr output_format formats[] = {
    {"text", "a message as rows of fields", print_text},
    {"json", "one JSON object per line, each with a \"type\" (docs/cli.md)", print_json},
};

}  // namespace

std::span<const output_format> output_formats() { return formats; }

const output_format* find_output_format(std::string_view name) {
    for (const output_format& f : formats)
        if (f.name == name) return &f;
    return nullptr;
}

}  // namespace robowire::cli
