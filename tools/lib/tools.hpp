// robowire's tools library: what the command-line tool, the Python package
// and the other bindings share (namespace robowire::tools).
//   hex.cpp        hex text in every common spelling; hex/binary detection
//   emit.hpp       a decoded message written straight out: text rows, JSON, CSV (templates)
//   output.cpp     the output formats (--format): text, json, csv; the output buffer
//   input.cpp      input read in blocks as it arrives, line by line (CR, LF, CRLF)
//   describe.hpp   templates over the library's tables (lengths, errors, list, encode)
//   buwizz3.cpp, navbot.cpp, osp.cpp   one protocol each, driven by its std::variant of messages
//   buwizz3_encode.cpp                  BuWizz3's encoders (a translation unit of their own: compile time)
//   logs.cpp       hex lines and nRF Connect logs, line by line (decode --file, scan buwizz3|navbot)
//   list_json.cpp  the schema as JSON (schema.hpp)
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace robowire::tools {

using byte_vector = std::vector<std::uint8_t>;
class output;

// Exit statuses.
inline constexpr int exit_ok = 0, exit_bad_input = 1, exit_usage = 2;

// ---- hex.cpp
// Parses hex as users paste it: "01 6D", "016d50", "0x01,0x6D", "0x1,0x6d" (one
// digit after 0x is one byte), "01-6D", "01:6D",
// nRF Connect's "(0x) 01-6D-50", line breaks. On failure: nullopt and `error`
// names the character and its position, or the token with an odd digit count.
std::optional<byte_vector> parse_hex_text(std::string_view text, std::string& error);
// The same into `out` (its capacity kept): false and `error` on failure.
bool parse_hex_into(std::string_view text, byte_vector& out, std::string& error);
// nRF Connect's "01-6D-50" at the start of `text`, ended by the end of text or
// a character that is neither a hex digit, '-', ':' nor a space: its bytes into
// `out` and their length in `used`; false for anything else (then nothing is decided).
bool parse_dashed_hex(std::string_view text, byte_vector& out, std::size_t& used);
// Does `data` read as hex text (only hex digits, separators, "0x" and "(0x)")?
bool looks_like_hex_text(std::span<const std::uint8_t> data);
// "01 6D 50"
std::string hex_of(std::span<const std::uint8_t> bytes);

// An output buffer: appends with one bounds check (most of the tool's time
// goes to writing records into it).
class buffer {
public:
    buffer() { reserve(1 << 12); }
    ~buffer() { delete[] data_; }
    buffer(const buffer&) = delete;
    buffer& operator=(const buffer&) = delete;
    [[gnu::always_inline]] buffer& append(const char* s, std::size_t n) {
        if (n > cap_ - size_) reserve(size_ + n);
        char* d = data_ + size_;
        // short pieces (most of them) with fixed-size copies, overlapping, rather than a call to memcpy
        if (n >= 8 && n <= 16) {
            copy<8>(d, s);
            copy<8>(d + n - 8, s + n - 8);
        } else if (n >= 4 && n < 8) {
            copy<4>(d, s);
            copy<4>(d + n - 4, s + n - 4);
        } else if (n > 0 && n < 4) {
            d[0] = s[0];
            d[n / 2] = s[n / 2];
            d[n - 1] = s[n - 1];
        } else if (n) {
            copy_long(d, s, n);
        }
        size_ += n;
        return *this;
    }
    buffer& append(const char* b, const char* e) { return append(b, static_cast<std::size_t>(e - b)); }
    [[gnu::always_inline]] buffer& append(std::string_view s) { return append(s.data(), s.size()); }
    buffer& append(std::size_t n, char c) {
        if (n > cap_ - size_) reserve(size_ + n);
        std::memset(data_ + size_, c, n);
        size_ += n;
        return *this;
    }
    template <std::size_t N>
    buffer& operator+=(const char (&s)[N]) {
        return append(s, N - 1);
    }
    buffer& operator+=(std::string_view s) { return append(s); }
    [[gnu::always_inline]] buffer& operator+=(char c) {
        if (size_ == cap_) reserve(size_ + 1);
        data_[size_++] = c;
        return *this;
    }
    void insert(std::size_t pos, std::string_view s) {
        append(s);
        std::rotate(data_ + pos, data_ + size_ - s.size(), data_ + size_);
    }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    void clear() { size_ = 0; }
    std::string_view view() const { return {data_, size_}; }
    void reserve(std::size_t n) {
        if (n <= cap_) return;
        const std::size_t c = std::max(n, 2 * cap_);
        char* d = new char[c];
        if (size_) std::memcpy(d, data_, size_);
        delete[] data_;
        data_ = d;
        cap_ = c;
    }

private:
    // (not inlined: g++ 12 -O3 then warns of bounds it cannot see, -Warray-bounds)
    [[gnu::noinline]] static void copy_long(char* d, const char* s, std::size_t n) { std::memcpy(d, s, n); }
    template <std::size_t N>
    static void copy(char* d, const char* s) {
        char t[N];
        std::memcpy(t, s, N);
        std::memcpy(d, t, N);
    }
    char* data_ = nullptr;
    std::size_t size_ = 0, cap_ = 0;
};

// An error (or a failed encode), as the protocol modules return it.
struct outcome {
    int status = exit_ok;            // exit_ok, exit_bad_input or exit_usage
    std::string error;               // one line (without "error: ")
    std::vector<std::string> hints;  // more lines for stderr (text) / "hints" (JSON)
    std::string message;             // message name (encode)
    byte_vector bytes;               // encoded frame
    // encode: the library's error behind `error`, when there is one
    std::string code;        // its name ("value_out_of_range"), "" when none
    std::size_t offset = 0;  // its byte
    std::string field;       // its field ("colors.g" in a record), "" when none
};

// ---- output.cpp: the output formats of decode, scan and monitor (--format, --json).
// What they print is a series of records (messages, errors, reassembly
// notes, counters), written straight into one buffer: text rows, one JSON
// object a line (docs/cli.md), or CSV tables (messages only; one per message).
enum class format_kind { text, json, csv };
enum class link_direction { unknown, host_to_device, device_to_host };
// Where a record came from: a log line (line 0: no line, e.g. an argument).
struct record_meta {
    std::size_t line = 0;
    link_direction dir = link_direction::unknown;
    std::string_view uuid, handle;  // Android: the characteristic; desktop: the attribute handle
    std::string_view time;          // ISO 8601 with milliseconds, or empty
};
struct output_format {
    std::string_view name;
    std::string_view help;  // for --format's help
    format_kind kind;
};
std::span<const output_format> output_formats();  // the first is the default
// The format named (nullptr: none).
const output_format* find_output_format(std::string_view name);

class output {
public:
    // line_buffered: each record written to stdout as it ends (otherwise in blocks of 64 KB).
    output(format_kind k, bool line_buffered);
    ~output();
    output(const output&) = delete;
    output& operator=(const output&) = delete;

    format_kind kind;
    buffer buf;  // the records not yet written; formats append to it
    // CSV: the table a message goes to (stdout: only --message's; with an
    // out_dir, a file <protocol>_<message>.csv each). Its header is written by
    // header(buffer&) on first use. nullptr: the message is not written.
    std::string csv_message, out_dir;
    template <class Header>
    buffer* csv_table(std::string_view protocol, std::string_view message, Header&& header) {
        if (out_dir.empty()) {
            if (message != csv_message) return nullptr;
            if (!stdout_header_) {
                header(buf);
                stdout_header_ = true;
            }
            return &buf;
        }
        bool found = false;
        if (auto* t = find_table(protocol, message, found); found) return t;
        buffer h;
        header(h);
        return open_table(protocol, message, h.view());
    }
    // Ends a record: writes the buffer out when line buffered or full.
    void end_record() {
        if (line_buffered_ || buf.size() >= (1u << 16)) flush();
    }
    void flush();
    // Where flush() writes the records instead of stdout (the Python package's reader).
    std::function<void(std::string_view)> sink;
    // CSV files written (out_dir), and the first write error ("" when none).
    std::vector<std::string> files;
    std::string write_error;

    // Records every format has: an error, counters.
    // Text (scan): `text` as given; JSON: {"type":"error", ..., "error": ..., extra members}; CSV: not written.
    // Returns whether it was written to stdout (otherwise the caller shows it on stderr).
    bool error(const record_meta& meta, std::string_view error, std::string_view text,
               const std::vector<std::pair<std::string_view, std::string_view>>& extra = {},
               const std::vector<std::string>& hints = {});
    bool counters(const std::vector<std::pair<std::string, std::uint64_t>>& counters, std::string_view input,
                  std::string_view text);

private:
    struct table;
    buffer* find_table(std::string_view protocol, std::string_view message, bool& found);
    buffer* open_table(std::string_view protocol, std::string_view message, std::string_view header);
    bool line_buffered_;
    bool stdout_header_ = false;
    std::vector<table*> tables_;
};

// Appenders shared by the formats.
// (Out: buffer or std::string.)
// A JSON string, escaped (invalid UTF-8 replaced by U+FFFD).
template <class Out>
void put_json_string(Out& o, std::string_view s);
// A CSV cell, quoted when it holds a comma, quote or line end.
template <class Out>
void put_csv_cell(Out& o, std::string_view s);
// {"type":"<type>","line":N,"time":...,"direction":...,"uuid":...,"handle":...  (no closing brace)
template <class Out>
void put_json_head(Out& o, std::string_view type, const record_meta& meta);
// "<time> line N (device to host): " (nothing without a line)
template <class Out>
void put_text_prefix(Out& o, const record_meta& meta);
const char* direction_key(link_direction d);   // "host_to_device", "device_to_host", ""
const char* direction_text(link_direction d);  // "host to device", "device to host", ""
// At most `max` characters of s, with " ... (N characters)" when cut: values echoed in messages.
std::string shorten(std::string_view s, std::size_t max = 80);

// ---- one protocol (buwizz3.cpp, navbot.cpp, osp.cpp)
enum class direction { any, command, notification };
struct protocol {
    std::string_view name;
    std::string_view summary;          // one line for `list`
    bool has_directions;               // BuWizz3: command / notification
    std::string (*list)(bool fields);  // `list` output
    // Decodes `in`: writes the message as a record of out's format (after
    // `meta`) and returns exit_ok, or returns the error's outcome (nothing written).
    outcome (*decode)(std::span<const std::uint8_t> in, direction d, output& out, const record_meta& meta);
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
// `list --json`: every protocol's tables (or the one named) as one JSON document (tools/lib/schema.hpp).
std::string list_json(std::string_view protocol);

// ---- input.cpp: a file, stdin or a device read in blocks as the data arrives
class input_stream {
public:
    static constexpr std::size_t max_line = 1 << 16;  // longer lines are cut (and reported)
    input_stream() = default;
    ~input_stream();
    input_stream(const input_stream&) = delete;
    input_stream& operator=(const input_stream&) = delete;
    // path "-": stdin. false and `error` when it cannot be read (missing,
    // unreadable, a directory, stdin closed).
    bool open(const std::string& path, std::string& error);
    // Reads `text` instead (an argument): its last line counts as ended (`ended` true).
    void open_text(std::string_view text, std::string name);
    // Reads from `source` instead (the Python package's file objects): it fills
    // at most n bytes at p and returns how many, 0 at the end of the input
    // (a read error: 0 and `error` set).
    void open_source(std::function<std::size_t(char* p, std::size_t n)> source, std::string name);
    std::string name;  // "stdin", the path, or what open_text was given
    // The first bytes (up to 4 KB; fewer at the end of the input or once a line has ended), left to read.
    std::span<const std::uint8_t> peek();
    // The next block of bytes (empty: end of input).
    std::span<const std::uint8_t> read();
    // The next line without its end (CR, LF or CRLF); false at the end of the
    // input. A line longer than max_line comes back cut to its first 64
    // bytes with `length` its full length; `ended` is false for a last line
    // without a line end.
    bool next_line(std::string_view& line, std::size_t& length, bool& ended);
    // The read error that ended the input ("" when none).
    std::string error;
    // Called before a read that would wait for data (a pipe or terminal with nothing
    // left to read): the output written so far goes out before the tool waits.
    output* flush_before_wait = nullptr;

private:
    bool fill();  // reads more (false: end of input)
    std::function<std::size_t(char*, std::size_t)> source_;
    int fd_ = -1;
    bool own_ = false, eof_ = false, skip_lf_ = false;
    std::string buf_;
    std::size_t pos_ = 0;
    std::string cut_;  // a long line's first bytes
};
// Do the first bytes of an input read as binary rather than text lines
// (more lines with a control byte, tab aside, than lines without)?
bool looks_binary(std::span<const std::uint8_t> first);
// ... as hex text (more lines of hex digits and separators only than other lines)?
bool looks_like_hex_lines(std::span<const std::uint8_t> first);
// "control byte 0x01 at character 5" for the first byte of `line` that is not text, or "".
std::string control_byte(std::string_view line);

// ---- logs.cpp: text input line by line (hex lines, nRF Connect logs of Android and desktop)
// One line of an nRF Connect log that carries a value (decode takes it as an argument too)?
bool is_log_line(std::string_view text);
// A time of day, or a date and time ("10:12", "10:12:06.5", "2026-03-14T10:12:06"): --since, --until.
struct time_point {
    long day = -1;  // days since 1970-01-01, -1: a time of day only
    long ms = 0;    // milliseconds since midnight
};
std::optional<time_point> parse_time_point(std::string_view s);
struct log_options {
    direction forced = direction::any;
    bool scan = false;                       // scan: errors on stdout too, NAVBOT reassembly, counters last
    std::optional<time_point> since, until;  // only frames logged in [since, until]
    bool quiet = false;  // nothing on stderr: errors as records only, the summary as a counters record
};
// The lines of one input, fed one by one (decode_lines; the Python package's read_log).
class line_decoder {
public:
    line_decoder(const protocol* p, std::string_view name, output& out, const log_options& opt);
    ~line_decoder();
    line_decoder(const line_decoder&) = delete;
    line_decoder& operator=(const line_decoder&) = delete;
    // Line `num` (from 1) as input_stream::next_line gives it; false: stop (a usage error was reported).
    bool feed(std::size_t num, std::string_view line, std::size_t length, bool ended);
    // The end of the input: the lines held back, the summary. Returns the exit status.
    int finish();

private:
    struct impl;
    std::unique_ptr<impl> impl_;
};
// Decodes every line of `in` that holds a frame as it is read, with `p`
// (nullptr: the characteristic UUID of each line picks the protocol). decode:
// results on stdout, errors and a summary on stderr. scan: errors on stdout
// too, NAVBOT messages reassembled, counters last.
int decode_lines(const protocol* p, input_stream& in, output& out, const log_options& opt);

}  // namespace robowire::tools
