// robowire command-line tool: what its translation units share.
//   hex.cpp        hex text in every common spelling; hex/binary detection
//   render.cpp     a decoded message as text or JSON (nlohmann/json)
//   output.cpp     the output formats (--format): text, json
//   describe.hpp   templates over the library's tables (fields, lengths, errors, encode)
//   buwizz3.cpp, navbot.cpp, osp.cpp   one protocol each, driven by its std::variant of messages
//   buwizz3_encode.cpp                  BuWizz3's encoders (a translation unit of their own: compile time)
//   logs.cpp       hex lines and nRF Connect logs, line by line (decode --file, scan buwizz3|navbot)
//   main.cpp       commands and options (CLI11), scan and monitor
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace robowire::cli {

using byte_vector = std::vector<std::uint8_t>;

// Exit statuses.
inline constexpr int exit_ok = 0, exit_bad_input = 1, exit_usage = 2;

// ---- hex.cpp
// Parses hex as users paste it: "01 6D", "016d50", "0x01,0x6D", "0x1,0x6d" (one
// digit after 0x is one byte), "01-6D", "01:6D",
// nRF Connect's "(0x) 01-6D-50", line breaks. On failure: nullopt and `error`
// names the character and its position, or the token with an odd digit count.
std::optional<byte_vector> parse_hex_text(std::string_view text, std::string& error);
// Does `data` read as hex text (only hex digits, separators, "0x" and "(0x)")?
bool looks_like_hex_text(std::span<const std::uint8_t> data);
// "01 6D 50"
std::string hex_of(std::span<const std::uint8_t> bytes);

// ---- the decoded form of a message (built by describe.hpp, printed by render.cpp)
struct node {
    enum kind_t { null, integer, real, boolean, string, object, array } kind = null;
    std::string key;
    std::int64_t i = 0;
    double d = 0;
    bool b = false;
    std::string s;               // string leaves: enum names, text, hex bytes
    std::string text;            // leaves (and byte arrays): the text-output form
    std::optional<double> phys;  // physical value (fields with a unit)
    std::string unit;
    std::vector<std::pair<std::string, std::string>> bits;  // flag bit name -> "true"/"false" or a value name
    std::optional<std::string> payload_text;                // NAVBOT JSON payload as text
    std::vector<node> children;
};

// A decoded message or an error, as the protocol modules return them.
struct outcome {
    int status = exit_ok;            // exit_ok, exit_bad_input or exit_usage
    std::string error;               // one line (without "error: ")
    std::vector<std::string> hints;  // more lines for stderr (text) / "hints" (JSON)
    std::string message;             // message name (decoded)
    node fields;                     // decoded fields (an object)
    byte_vector bytes;               // encoded frame
};

// ---- render.cpp
// Text: "protocol message" then one row per field; notes after.
std::string render_text(std::string_view protocol, const outcome& o);
// One JSON object (no newline): {"type": "message", "protocol", "message", "fields", ...}.
std::string render_json(std::string_view protocol, const outcome& o);
// {"type": "error", "error": ..., plus extra string members}.
std::string render_json_error(std::string_view error, const std::vector<std::pair<std::string, std::string>>& extra);
// {"type": "counters", name: value..., "input": input (when not empty)}.
std::string render_json_counters(const std::vector<std::pair<std::string, std::uint64_t>>& counters,
                                 std::string_view input);

// ---- output.cpp: the output formats of decode, scan and monitor (--format, --json).
// What they print on stdout is a series of records, each given in two forms:
// its JSON object (one line, as docs/cli.md describes it; every record has
// one) and its text (lines with their newlines; empty: the record shows in
// text on stderr only). A format prints one of them, or its own form made
// from the JSON object. A new format is one entry in output.cpp's formats().
struct output_format {
    std::string_view name;
    std::string_view help;  // for --format's help
    // Prints one record and flushes stdout; true when it printed `text` (the
    // caller then leaves the record off stderr, where it would repeat it).
    bool (*print)(const std::string& json, const std::string& text);
};
std::span<const output_format> output_formats();  // the first is the default
// The format named (nullptr: none).
const output_format* find_output_format(std::string_view name);

// ---- one protocol (buwizz3.cpp, navbot.cpp, osp.cpp)
enum class direction { any, command, notification };
struct protocol {
    std::string_view name;
    std::string_view summary;          // one line for `list`
    bool has_directions;               // BuWizz3: command / notification
    std::string (*list)(bool fields);  // `list` output
    outcome (*decode)(std::span<const std::uint8_t> in, direction d);
    // values: name=value pairs in the order given (names checked, repeats refused here)
    outcome (*encode)(std::string_view message, const std::vector<std::pair<std::string, std::string>>& values);
};
// One per protocol, defined in tools/<protocol>.cpp (a new protocol needs only
// its entry, and its declaration, in protocols.cpp: the commands' protocol
// arguments, their help and the tool's messages come from protocols()).
const protocol& buwizz3_protocol();
outcome buwizz3_encode(std::string_view message,
                       const std::vector<std::pair<std::string, std::string>>& values);  // buwizz3_encode.cpp
const protocol& navbot_protocol();
const protocol& osp_protocol();
// Every protocol, in `list` order (protocols.cpp); nullptr for an unknown name.
std::span<const protocol* const> protocols();
const protocol* find_protocol(std::string_view name);
// Their names, "buwizz3, navbot or osp", for help texts and messages.
std::string protocol_names();

// ---- list_json.cpp
// `list --json`: every protocol's tables (or the one named) as one JSON document (tools/schema.hpp).
std::string list_json(std::string_view protocol);

// ---- logs.cpp: text input line by line (hex lines, nRF Connect logs of Android and desktop)
enum class link_direction { unknown, host_to_device, device_to_host };
// One line of an nRF Connect log that carries a value (decode takes it as an argument too)?
bool is_log_line(std::string_view text);
// Text rather than binary (no control byte but tab, CR and LF)?
bool looks_like_text(std::span<const std::uint8_t> data);
// Decodes every line of `text` that holds a frame, with `p` (nullptr: the
// characteristic UUID of each line picks the protocol). decode: results on
// stdout, errors and a summary on stderr. scan: errors on stdout too, NAVBOT
// messages reassembled, counters last. `name` names the input in messages.
int decode_lines(const protocol* p, std::string_view name, std::string_view text, const output_format& out,
                 direction forced, bool scan);

// ---- more subcommands
// Adds `robowire dissector <protocol> [--output DIR]` (dissector_command.cpp).
// Other subcommands are added the same way: a function taking the app,
// declared here, called from main.cpp's add_extra_commands().
void add_dissector_command(CLI::App& app);

}  // namespace robowire::cli
