// robowire: decode, encode and describe BuWizz3, NAVBOT-ES02 and OSP frames
// from the library's field tables; decode logs line by line (logs.cpp); scan an
// OSP byte stream; watch a serial port.
// Commands and options: CLI11. Output: render.cpp (text or JSON lines).
#include <CLI/CLI.hpp>
#include <robowire/osp/scanner.hpp>
#include <robowire/protocols.hpp>

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>
#include <tuple>

#include "cli.hpp"

namespace robowire::cli {

namespace {

// Accepts a value that does not start with '-' (the option's type then checks it is a number).
const CLI::Validator not_negative(
    [](std::string& v) {
        return !v.empty() && v[0] == '-' ? std::string("must not be negative: ") + v : std::string();
    },
    "NOT NEGATIVE", "not_negative");

void out_line(const std::string& s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}
void err_line(const std::string& s) { std::fprintf(stderr, "%s\n", s.c_str()); }

// --format (and --json as its short form), --line-buffered, and for CSV --message and --out-dir.
struct format_option {
    std::string name;
    bool json = false;
    bool line_buffered = false;
    std::string message, out_dir;
    format_kind kind() const {
        return find_output_format(json ? "json" : name.empty() ? output_formats()[0].name : name)->kind;
    }
    // The output, or nullptr after a usage error (reported).
    std::unique_ptr<output> make() const {
        auto o = std::make_unique<output>(kind(), line_buffered || ::isatty(1));
        if (o->kind == format_kind::csv) {
            if (message.empty() && out_dir.empty()) {
                err_line(
                    "error: --format csv writes one table per message: give --message NAME (robowire list) or "
                    "--out-dir DIR");
                return nullptr;
            }
            o->csv_message = message;
            o->out_dir = out_dir;
        } else if (!message.empty() || !out_dir.empty()) {
            err_line("error: --message and --out-dir go with --format csv");
            return nullptr;
        }
        return o;
    }
};
// Adds --format, --json and --line-buffered (and CSV's options) to `sub`; `what`: --json's help.
void add_format_options(CLI::App& sub, format_option& f, const std::string& what, bool csv) {
    std::string help = "output format:";
    std::vector<std::string> names;
    for (const output_format& o : output_formats()) {
        if (!csv && o.kind == format_kind::csv) continue;
        names.emplace_back(o.name);
        help += std::string(names.size() == 1 ? " " : "; ") + std::string(o.name) +
                (names.size() == 1 ? " (default)" : "") + ", " + std::string(o.help);
    }
    auto* format = sub.add_option("--format", f.name, help)->check(CLI::IsMember(names));
    sub.add_flag("--json", f.json, what)->excludes(format);
    sub.add_flag("--line-buffered", f.line_buffered,
                 "write each record as it is decoded (the default when stdout is a terminal; otherwise in blocks)");
    if (csv) {
        sub.add_option("--message", f.message, "CSV: the message whose table is written (e.g. status)");
        sub.add_option(
            "--out-dir", f.out_dir,
            "CSV: one file per message in DIR (created if missing), <protocol>_<message>.csv (with --message: that "
            "one only)");
    }
}
// --out-dir: the directory made (with its parents) when missing, before anything is
// decoded; false after an error (reported: exit status 1).
bool make_out_dir(const std::string& dir) {
    if (dir.empty()) return true;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (!ec && !std::filesystem::is_directory(dir, ec) && !ec) ec = std::make_error_code(std::errc::not_a_directory);
    if (ec) {
        err_line("error: --out-dir " + dir + ": cannot create the directory: " + ec.message());
        return false;
    }
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
        err_line("error: --out-dir " + dir + ": cannot write into the directory: " + std::strerror(errno));
        return false;
    }
    return true;
}
// The CSV files written (stderr), and a write error (exit status 1).
int finish_output(output& out, int rc) {
    out.flush();
    for (const auto& f : out.files) err_line("wrote " + f);
    if (!out.write_error.empty()) {
        err_line("error: " + out.write_error);
        return rc ? rc : exit_bad_input;
    }
    return rc;
}

int report(const protocol& p, std::span<const std::uint8_t> bytes, direction d, output& out) {
    const outcome o = p.decode(bytes, d, out, {});
    if (o.status != exit_ok) {
        out.error({}, o.error, "", {{"protocol", p.name}}, o.hints);
        out.flush();
        err_line("error: " + o.error);
        for (const auto& h : o.hints) err_line("hint: " + h);
        return o.status;
    }
    return exit_ok;
}

// ---- input files: binary or hex text
enum class input_mode { detect, hex, binary };

// ---- decode
struct decode_options {
    std::string protocol;
    std::vector<std::string> hex;
    std::string file;
    std::string direction;
    format_option format;
    bool hex_file = false, binary_file = false;
    std::string since, until;
};
direction direction_of(const std::string& name) {
    return name == "command" ? direction::command : name == "notification" ? direction::notification : direction::any;
}
// --since / --until into `opt`; false after a usage error (reported).
bool time_range(const std::string& since, const std::string& until, log_options& opt) {
    for (const auto& [text, slot, name] :
         {std::tuple{&since, &opt.since, "--since"}, {&until, &opt.until, "--until"}}) {
        if (text->empty()) continue;
        *slot = parse_time_point(*text);
        if (!*slot) {
            err_line(std::string("error: ") + name + ": " + shorten(*text) +
                     " is no time: give HH:MM[:SS[.mmm]] or YYYY-MM-DD[THH:MM[:SS[.mmm]]]");
            return false;
        }
    }
    return true;
}

int run_decode(const decode_options& opt) {
    const protocol* pp = opt.protocol.empty() ? nullptr : find_protocol(opt.protocol);
    if (!opt.direction.empty() && pp && !pp->has_directions) {
        err_line("error: --direction applies to buwizz3 only");
        return exit_usage;
    }
    log_options lo;
    lo.forced = direction_of(opt.direction);
    if (!time_range(opt.since, opt.until, lo)) return exit_usage;
    const auto out = opt.format.make();
    if (!out) return exit_usage;
    if (!opt.file.empty()) {
        if (!opt.hex.empty()) {
            err_line("error: give hex bytes or --file, not both");
            return exit_usage;
        }
        input_stream in;
        std::string error;
        if (!in.open(opt.file, error)) {
            err_line("error: " + error);
            return exit_bad_input;
        }
        // text (hex lines, an nRF Connect log): every line that holds a frame, as it is read
        if (opt.hex_file || (!opt.binary_file && !looks_binary(in.peek()))) {
            if (!make_out_dir(out->out_dir)) return exit_bad_input;
            return finish_output(*out, decode_lines(pp, in, *out, lo));
        }
        if (!pp) {
            err_line("error: a binary file holds one frame: give its protocol (robowire decode buwizz3 --file " +
                     opt.file + ")");
            return exit_usage;
        }
        if (!make_out_dir(out->out_dir)) return exit_bad_input;
        // one frame: at most 64 KB are read (a frame is far shorter)
        byte_vector bytes;
        for (auto b = in.read(); !b.empty() && bytes.size() <= (1u << 16); b = in.read())
            bytes.insert(bytes.end(), b.begin(), b.end());
        if (!in.error.empty()) {
            err_line("error: " + in.error);
            return exit_bad_input;
        }
        if (bytes.size() > (1u << 16)) {
            err_line("error: " + in.name +
                     " read as binary holds one frame, and it is longer than 65536 bytes "
                     "(use --hex for a hex dump)");
            return exit_bad_input;
        }
        err_line("read " + in.name + " as binary (" + std::to_string(bytes.size()) +
                 (bytes.size() == 1 ? " byte)" : " bytes)"));
        return finish_output(*out, report(*pp, bytes, lo.forced, *out));
    }
    if (!pp && opt.hex.empty()) {
        err_line("error: decode needs a protocol and hex bytes, or --file (robowire decode --help)");
        return exit_usage;
    }
    if (opt.hex.empty()) {
        err_line("error: decode needs hex bytes or --file (robowire decode --help)");
        return exit_usage;
    }
    std::string joined;
    for (const auto& a : opt.hex) joined += (joined.empty() ? "" : " ") + a;
    // a line copied from an nRF Connect log: its value, direction and UUID
    if (is_log_line(joined)) {
        if (!make_out_dir(out->out_dir)) return exit_bad_input;
        input_stream in;
        in.open_text(joined, "the argument");
        return finish_output(*out, decode_lines(pp, in, *out, lo));
    }
    std::string error;
    if (!pp) {
        err_line("error: decode needs a protocol before the bytes: " + protocol_names() + " (robowire decode --help)");
        return exit_usage;
    }
    const auto b = parse_hex_text(joined, error);
    if (!b) {
        out->error({}, error, "");
        out->flush();
        err_line("error: " + error);
        return exit_bad_input;
    }
    if (!make_out_dir(out->out_dir)) return exit_bad_input;
    return finish_output(*out, report(*pp, *b, lo.forced, *out));
}

// ---- encode
int run_encode(const std::string& protocol_name, const std::string& message,
               const std::vector<std::string>& assignments) {
    const protocol& p = *find_protocol(protocol_name);
    std::vector<std::pair<std::string, std::string>> values;
    for (const auto& a : assignments) {
        const auto eq = a.find('=');
        if (eq == std::string::npos || eq == 0) {
            err_line("error: expected name=value, got " + a);
            return exit_usage;
        }
        values.emplace_back(a.substr(0, eq), a.substr(eq + 1));
    }
    const outcome o = p.encode(message, values);
    if (o.status != exit_ok) {
        err_line("error: " + o.error);
        for (const auto& h : o.hints) err_line("hint: " + h);
        return o.status;
    }
    out_line(hex_of(o.bytes));
    return exit_ok;
}

// ---- scan / monitor: OSP frames in a byte stream
struct osp_printer {
    explicit osp_printer(output& f) : out(f) {}
    output& out;
    robowire::osp::scanner scanner;
    std::size_t line = 0;  // hex text: the line the bytes come from
    void feed(std::span<const std::uint8_t> chunk) {
        scanner.feed(chunk, [&](robowire::osp::scanner::frame_bytes f) {
            record_meta meta;
            meta.line = line;
            const outcome o = osp_protocol().decode(f, direction::any, out, meta);
            if (o.status == exit_ok) return;
            std::string prefix;
            put_text_prefix(prefix, meta);
            const std::string bytes = hex_of(f);
            std::string text = prefix + "osp frame " + bytes + ": " + o.error + "\n";
            for (const auto& h : o.hints) text += prefix + "hint: " + h + "\n";
            if (out.error(meta, o.error, text, {{"protocol", "osp"}, {"bytes", bytes}}, o.hints)) return;
            err_line("error: osp frame " + bytes + ": " + o.error);
            for (const auto& h : o.hints) err_line("hint: " + h);
        });
    }
    // bad_lines: hex text lines skipped (hex input only)
    void counters(const char* input, const std::size_t* bad_lines = nullptr) {
        std::vector<std::pair<std::string, std::uint64_t>> cs = {{"frames", scanner.frames()},
                                                                 {"skipped_bytes", scanner.skipped()},
                                                                 {"false_starts", scanner.false_starts()}};
        std::string text = "frames " + std::to_string(scanner.frames()) + ", skipped bytes " +
                           std::to_string(scanner.skipped()) + ", false starts " +
                           std::to_string(scanner.false_starts());
        if (bad_lines) {
            cs.emplace_back("lines_skipped", *bad_lines);
            text += ", lines skipped " + std::to_string(*bad_lines);
        }
        if (input) text += std::string("; input read as ") + input;
        if (!out.counters(cs, input ? input : "", text + "\n")) err_line(text);
    }
};

// scan buwizz3 / navbot: a BLE log has one frame per line.
int run_scan_lines(const protocol& proto, const std::string& path, output& out, input_mode mode) {
    input_stream in;
    std::string error;
    if (!in.open(path, error)) {
        err_line("error: " + error);
        return exit_bad_input;
    }
    if (mode == input_mode::binary || (mode == input_mode::detect && looks_binary(in.peek()))) {
        err_line("error: scan " + std::string(proto.name) +
                 " reads text, one frame per line (hex, or an nRF Connect log); " + in.name + " is binary");
        return exit_bad_input;
    }
    log_options lo;
    lo.scan = true;
    return finish_output(out, decode_lines(&proto, in, out, lo));
}

int run_scan(const std::string& path, output& out, input_mode mode) {
    osp_printer p(out);
    input_stream in;
    std::string error;
    if (!in.open(path, error)) {
        err_line("error: " + error);
        return exit_bad_input;
    }
    const auto first = in.peek();
    const bool empty = first.empty() && in.error.empty();
    const bool hex = mode == input_mode::hex || (mode == input_mode::detect && looks_like_hex_lines(first));
    const char* kind = empty ? "empty" : hex ? "hex text" : "binary";
    err_line(std::string("scan: reading ") + in.name + " as " + kind +
             (hex || empty ? "" : " (use --hex for a hex dump)"));
    std::size_t bad = 0;
    in.flush_before_wait = &out;
    if (hex) {
        // line by line: a line that is not hex is reported with its number and skipped
        std::string_view line;
        std::size_t length = 0;
        bool ended = true;
        byte_vector bytes;
        while (in.next_line(line, length, ended)) {
            ++p.line;
            std::string why = length > line.size() ? "line too long: " + std::to_string(length) + " bytes, skipped"
                                                   : control_byte(line);
            const auto t = line.find_first_not_of(" \t");
            if (why.empty() && (t == std::string_view::npos || line[t] == '#')) continue;
            if (why.empty() && !parse_hex_into(line, bytes, why)) {
            } else if (why.empty()) {
                p.feed(bytes);
                continue;
            }
            ++bad;
            why = shorten(why, 200);
            record_meta meta;
            meta.line = p.line;
            std::string prefix;
            put_text_prefix(prefix, meta);
            if (!out.error(meta, why, prefix + "error: " + why + "\n"))
                err_line("error: line " + std::to_string(p.line) + ": " + why);
        }
    } else {
        for (auto b = in.read(); !b.empty(); b = in.read()) p.feed(b);
    }
    if (!in.error.empty()) {
        out.flush();
        err_line("error: " + in.error);
        return exit_bad_input;
    }
    p.counters(kind, hex ? &bad : nullptr);
    return finish_output(out, exit_ok);
}

speed_t baud_of(long baud) {
    switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    default: return B921600;
    }
}

struct monitor_options {
    std::string device;
    long baud = 115200;
    long count = -1;
    double timeout = -1;
    format_option format;
};
int run_monitor(const monitor_options& opt) {
    const auto out = opt.format.make();
    if (!out) return exit_usage;
    osp_printer p(*out);
    const int fd = ::open(opt.device.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    if (fd < 0) {
        err_line("error: cannot open " + opt.device + ": " + std::strerror(errno));
        return exit_bad_input;
    }
    termios tio{};
    if (tcgetattr(fd, &tio) == 0) {
        cfmakeraw(&tio);
        cfsetispeed(&tio, baud_of(opt.baud));
        cfsetospeed(&tio, baud_of(opt.baud));
        tio.c_cflag |= CLOCAL | CREAD;
        tcsetattr(fd, TCSANOW, &tio);
    } else {
        err_line("monitor: " + opt.device + " is not a serial port (" + std::strerror(errno) +
                 "); reading it as it is");
    }
    const auto start = std::chrono::steady_clock::now();
    std::uint8_t buf[1024];
    for (;;) {
        if (opt.count >= 0 && p.scanner.frames() >= static_cast<std::uint64_t>(opt.count)) break;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (opt.timeout >= 0 && elapsed >= opt.timeout) break;
        pollfd pfd{fd, POLLIN, 0};
        if (::poll(&pfd, 1, 100) <= 0) continue;
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n > 0) {
            p.feed(std::span(buf, static_cast<std::size_t>(n)));
            out->flush();  // live: what a read brought is written at once
        } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) break;
    }
    ::close(fd);
    p.counters(nullptr);
    return finish_output(*out, exit_ok);
}

// Subcommands defined elsewhere register here.
void add_extra_commands(CLI::App& app) { add_dissector_command(app); }

}  // namespace
}  // namespace robowire::cli

int main(int argc, char** argv) {
    using namespace robowire::cli;
    CLI::App app{"robowire - decode, encode and describe BuWizz3, NAVBOT-ES02 and OSP frames", "robowire"};
    app.require_subcommand(1);
    app.footer(
        "Exit status: 0 ok; 1 bad input (the message names the problem, the byte and the field);\n"
        "2 usage error (unknown command, option, protocol, message or field; bad option value).\n"
        "Run robowire <command> --help for a command's options. Manual: docs/cli.md");
    std::vector<std::string> names;  // every protocol (tools/lib/protocols.cpp)
    for (const protocol* p : protocols()) names.emplace_back(p->name);
    const std::string one_of = protocol_names();  // "buwizz3, navbot or osp"

    // list
    std::string list_protocol;
    bool list_fields = false, list_as_json = false;
    auto* list =
        app.add_subcommand("list", "every message: name, command byte(s), valid lengths; --fields: every field");
    list->add_option("protocol", list_protocol, one_of + " (default: all)")->check(CLI::IsMember(names));
    list->add_flag("--fields", list_fields,
                   "each field: name, byte offset, wire type, valid values, unit, flag bits; records expanded");
    list->add_flag("--json", list_as_json,
                   "the tables as one JSON document, every field included (Python: robowire.schema())");

    // decode
    decode_options dec_opt;
    auto* dec =
        app.add_subcommand("decode", "decode a frame from hex bytes (any spelling), or every frame of a file or log");
    dec->add_option("protocol", dec_opt.protocol,
                    one_of + " (with --file, may be left out: each log line's characteristic UUID picks it)")
        ->check(CLI::IsMember(names));
    dec->add_option("hex", dec_opt.hex, "bytes: \"01 6D\", 016D, 0x01,0x6D, 01-6D, 01:6D, (0x) 01-6D");
    add_format_options(*dec, dec_opt.format, "one JSON object on stdout", true);
    dec->add_option("--since", dec_opt.since,
                    "logs: only frames logged at or after this time (HH:MM[:SS[.mmm]] or YYYY-MM-DDTHH:MM...)");
    dec->add_option("--until", dec_opt.until, "logs: only frames logged at or before this time");
    dec->add_option("--direction", dec_opt.direction,
                    "BuWizz3: command or notification (default: what the command byte and length allow)")
        ->check(CLI::IsMember({"command", "notification"}));
    dec->add_option(
        "--file", dec_opt.file,
        "read frames from a file (- for stdin): text line by line (hex, nRF Connect logs), or one binary frame");
    auto* dec_hex = dec->add_flag("--hex", dec_opt.hex_file, "the file is hex text");
    auto* dec_bin = dec->add_flag("--binary", dec_opt.binary_file, "the file is binary");
    dec_hex->excludes(dec_bin);

    // encode
    std::string enc_protocol, enc_message;
    std::vector<std::string> enc_values;
    auto* enc = app.add_subcommand("encode", "build a frame from field values; prints hex");
    enc->add_option("protocol", enc_protocol, one_of)->required()->check(CLI::IsMember(names));
    enc->add_option("message", enc_message, "message name (robowire list)")->required();
    enc->add_option(
        "values", enc_values,
        "name=value: arrays and records as comma lists in the order robowire list --fields shows, enums by name");

    // scan
    std::string scan_protocol, scan_path = "-";
    format_option scan_format;
    bool scan_hex = false, scan_bin = false;
    auto* scan = app.add_subcommand("scan",
                                    "osp: find and decode frames in a byte stream (binary or hex text); "
                                    "buwizz3, navbot: every frame of a log, one per line, NAVBOT messages reassembled");
    scan->add_option("protocol", scan_protocol, one_of)->required()->check(CLI::IsMember(names));
    scan->add_option("file", scan_path, "file to read, - for stdin (default)");
    add_format_options(*scan, scan_format, "JSON lines on stdout: messages, errors, counters (each with a \"type\")",
                       false);
    auto* scan_hexf = scan->add_flag("--hex", scan_hex, "the input is hex text");
    auto* scan_binf = scan->add_flag("--binary", scan_bin, "the input is binary");
    scan_hexf->excludes(scan_binf);

    // monitor
    monitor_options mon_opt;
    auto* mon = app.add_subcommand("monitor", "read OSP frames from a serial port (raw mode) as they come");
    mon->add_option("device", mon_opt.device, "serial device, e.g. /dev/ttyUSB0")->required();
    mon->add_option("--baud", mon_opt.baud, "9600, 19200, 38400, 57600, 115200 (default), 230400, 460800 or 921600")
        ->check(CLI::IsMember({9600L, 19200L, 38400L, 57600L, 115200L, 230400L, 460800L, 921600L}));
    mon->add_option("--count", mon_opt.count, "stop after N frames")->check(not_negative);
    mon->add_option("--timeout", mon_opt.timeout, "stop after S seconds")->check(not_negative);
    add_format_options(*mon, mon_opt.format, "JSON lines on stdout: messages, errors, counters (each with a \"type\")",
                       false);

    add_extra_commands(app);

    if (argc < 2) {
        std::fputs(app.help().c_str(), stderr);
        return exit_usage;
    }
    if (argv[1][0] != '-' && app.get_subcommands([&](CLI::App* sub) { return sub->get_name() == argv[1]; }).empty()) {
        std::fprintf(stderr, "error: unknown command %s (robowire --help)\n", argv[1]);
        return exit_usage;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {  // an extra subcommand failed; it printed why
        return e.get_exit_code();
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help
        std::fprintf(stderr, "error: %s (robowire --help)\n", e.what());
        return exit_usage;
    } catch (const CLI::Error& e) {  // thrown by an extra subcommand's callback
        std::fprintf(stderr, "error: %s\n", e.what());
        return e.get_exit_code();
    }

    if (list->parsed()) {
        if (list_as_json) {
            out_line(list_json(list_protocol));
            return exit_ok;
        }
        for (const protocol* p : protocols())
            if (list_protocol.empty() || list_protocol == p->name) std::fputs(p->list(list_fields).c_str(), stdout);
        return exit_ok;
    }
    if (dec->parsed()) return run_decode(dec_opt);
    if (enc->parsed()) return run_encode(enc_protocol, enc_message, enc_values);
    if (scan->parsed()) {
        const auto mode = scan_hex ? input_mode::hex : scan_bin ? input_mode::binary : input_mode::detect;
        const auto out = scan_format.make();
        if (!out) return exit_usage;
        const auto* d = robowire::find_descriptor(scan_protocol);  // none: one frame per line
        if (d == nullptr || d->stream != robowire::stream_kind::scanner)
            return run_scan_lines(*find_protocol(scan_protocol), scan_path, *out, mode);
        return run_scan(scan_path, *out, mode);
    }
    if (mon->parsed()) return run_monitor(mon_opt);
    return exit_ok;  // an extra subcommand ran in its callback
}
