// Text input line by line: hex lines, and the logs of nRF Connect (Android
// and desktop). Each line that holds a frame is decoded with its line number;
// the line says the direction and, in Android logs, the characteristic UUID,
// which picks the protocol. `scan navbot` reassembles multi-frame messages.
#include <nlohmann/json.hpp>
#include <robowire/buwizz3/uuids.hpp>
#include <robowire/navbot/frame.hpp>
#include <robowire/navbot/multiframe.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>

#include "cli.hpp"

namespace robowire::cli {
namespace {
using json = nlohmann::ordered_json;

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }
void err_line(const std::string& s) { std::fprintf(stderr, "%s\n", s.c_str()); }

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_hex_digit(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
std::string lower(std::string_view s) {
    std::string o(s);
    for (char& c : o)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return o;
}
std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// nRF Connect for Android: "I 13:40:29.880 message" (level letter, time with milliseconds).
bool android_prefix(std::string_view s) {
    if (s.size() < 15 || (s[1] != ' ' && s[1] != '\t') || (s[14] != ' ' && s[14] != '\t')) return false;
    if (std::string_view("VDIWEA").find(s[0]) == std::string_view::npos) return false;
    for (const std::size_t i : {2u, 3u, 5u, 6u, 8u, 9u, 11u, 12u, 13u})
        if (!is_digit(s[i])) return false;
    return s[4] == ':' && s[7] == ':' && s[10] == '.';
}

// The bytes of a logged value: "(0x) 01-6D-50" up to the first character that
// is not part of it (nRF Connect may add the value as text: `, "Hello"`).
std::optional<byte_vector> value_bytes(std::string_view v, std::string& error) {
    v = trim(v);
    if (starts_with(v, "(0x)")) v.remove_prefix(4);
    v = trim(v);
    std::size_t n = 0;
    while (n < v.size() && (is_hex_digit(v[n]) || v[n] == '-' || v[n] == ':' || v[n] == ' ')) ++n;
    v = trim(v.substr(0, n));
    if (v.empty()) return byte_vector{};
    return parse_hex_text(v, error);
}

struct parsed_line {
    enum kind_t { none, frame, bad } kind = none;
    bool log = false;  // an nRF Connect line (with or without a frame)
    std::string source;
    byte_vector bytes;
    link_direction dir = link_direction::unknown;
    std::string uuid;    // Android: the characteristic
    std::string handle;  // desktop: the attribute handle
    bool desktop_changed = false, desktop_written = false;
    std::string error;
};

// One line of nRF Connect for Android.
parsed_line android_line(std::string_view msg) {
    parsed_line p;
    p.log = true;
    p.source = "nRF Connect (Android)";
    static constexpr std::array<std::pair<std::string_view, link_direction>, 4> kinds{{
        {"Notification received from ", link_direction::device_to_host},
        {"Indication received from ", link_direction::device_to_host},
        {"Read Response received from ", link_direction::device_to_host},
        {"Data written to ", link_direction::host_to_device},
    }};
    for (const auto& [prefix, dir] : kinds) {
        if (!starts_with(msg, prefix)) continue;
        std::string_view rest = msg.substr(prefix.size());
        if (starts_with(rest, "descr.")) return p;  // a descriptor (notifications on/off), no frame
        const auto comma = rest.find(", value: ");
        if (comma == std::string_view::npos) return p;
        p.uuid = lower(trim(rest.substr(0, comma)));
        const auto b = value_bytes(rest.substr(comma + 9), p.error);
        if (!b) {
            p.kind = parsed_line::bad;
        } else if (!b->empty()) {
            p.kind = parsed_line::frame;
            p.bytes = *b;
            p.dir = dir;
        }
        return p;
    }
    return p;
}

// One line of nRF Connect for Desktop (Bluetooth Low Energy app): the log
// file's "2024-09-14T21:29:24.282Z INFO Attribute value changed, handle: 0x12, value (0x): 01-02"
// or the log panel's "11:44:40.906<TAB>Attribute value written, handle: 0x26, value (0x): 01-00".
std::optional<parsed_line> desktop_line(std::string_view s) {
    static constexpr std::array<std::pair<std::string_view, link_direction>, 3> kinds{{
        {"Attribute value changed, handle: ", link_direction::device_to_host},
        {"Attribute value read, handle: ", link_direction::device_to_host},
        {"Attribute value written, handle: ", link_direction::host_to_device},
    }};
    for (const auto& [text, dir] : kinds) {
        const auto at = s.find(text);
        if (at == std::string_view::npos) continue;
        parsed_line p;
        p.log = true;
        p.source = "nRF Connect (desktop)";
        std::string_view rest = s.substr(at + text.size());
        const auto comma = rest.find(", value (0x): ");
        if (comma == std::string_view::npos) return p;
        p.handle = lower(trim(rest.substr(0, comma)));
        p.desktop_changed = text.find("changed") != std::string_view::npos;
        p.desktop_written = text.find("written") != std::string_view::npos;
        const auto b = value_bytes(rest.substr(comma + 14), p.error);
        // 00 00, 01 00, 02 00 written: a Client Characteristic Configuration descriptor
        // (notifications or indications off or on), no frame of any protocol here
        const bool cccd = b && b->size() == 2 && (*b)[0] <= 2 && (*b)[1] == 0;
        if (!b) {
            p.kind = parsed_line::bad;
        } else if (!b->empty() && !cccd) {
            p.kind = parsed_line::frame;
            p.bytes = *b;
            p.dir = dir;
        }
        return p;
    }
    // other lines of the desktop log: "2024-09-14T21:29:24.282Z INFO ...", "11:44:29.244<TAB>Connected to device ..."
    const bool iso = s.size() > 25 && is_digit(s[0]) && s[4] == '-' && s[10] == 'T' && s[23] == 'Z' && s[24] == ' ';
    const bool panel = s.size() > 13 && is_digit(s[0]) && s[2] == ':' && s[5] == ':' && s[8] == '.' && s[12] == '\t';
    if (iso || panel) {
        parsed_line p;
        p.log = true;
        p.source = "nRF Connect (desktop)";
        return p;
    }
    return std::nullopt;
}

parsed_line parse_line(std::string_view raw) {
    const std::string_view s = trim(raw);
    if (android_prefix(s)) return android_line(s.substr(15));
    if (auto d = desktop_line(s)) return *d;
    parsed_line p;
    // the header of an nRF Connect for Android log: "nRF Connect, 2024-05-11", "Device Name (A4:...)"
    if (starts_with(s, "nRF Connect, ")) {
        p.log = true;
        p.source = "nRF Connect (Android)";
        return p;
    }
    if (s.empty() || s[0] == '#') return p;
    p.source = "hex";
    const auto b = parse_hex_text(s, p.error);
    if (b) {
        p.kind = parsed_line::frame;
        p.bytes = *b;
    } else {
        p.kind = parsed_line::bad;
    }
    return p;
}

const char* direction_text(link_direction d) {
    switch (d) {
    case link_direction::host_to_device: return "host to device";
    case link_direction::device_to_host: return "device to host";
    default: return "";
    }
}
const char* direction_key(link_direction d) {
    switch (d) {
    case link_direction::host_to_device: return "host_to_device";
    case link_direction::device_to_host: return "device_to_host";
    default: return "";
    }
}

// The protocol and role of a characteristic UUID robowire knows.
struct known_uuid {
    const protocol* p;
    const char* role;
};
std::optional<known_uuid> protocol_of_uuid(const std::string& uuid) {
    const auto u = uuid128::parse(uuid);
    if (!u) return std::nullopt;
    if (*u == robowire::buwizz3::application_uuid)
        return known_uuid{&buwizz3_protocol(), "BuWizz3 application characteristic"};
    if (*u == robowire::navbot::write_uuid) return known_uuid{&navbot_protocol(), "NAVBOT write characteristic"};
    if (*u == robowire::navbot::notify_uuid) return known_uuid{&navbot_protocol(), "NAVBOT notify characteristic"};
    return std::nullopt;
}

// The reassembly of NAVBOT messages, one per direction (the robot echoes what it receives).
struct navbot_stream {
    robowire::navbot::reassembler<256 * robowire::navbot::payload_size> r;
    std::vector<std::size_t> lines;  // lines of the message in progress
    int last_remaining = -1;         // `remaining` of the last frame pushed
};
const char* reassembly_name(robowire::navbot::reassembly r) {
    using robowire::navbot::reassembly;
    switch (r) {
    case reassembly::need_more: return "need_more";
    case reassembly::complete: return "complete";
    case reassembly::single: return "single";
    case reassembly::duplicate: return "duplicate";
    case reassembly::restarted: return "restarted";
    case reassembly::discarded: return "discarded";
    }
    return "?";
}
const char* reassembly_text(robowire::navbot::reassembly r) {
    using robowire::navbot::reassembly;
    switch (r) {
    case reassembly::need_more: return "part of a message, more frames to come";
    case reassembly::complete: return "message complete";
    case reassembly::single: return "a one-frame message inside another message (kept apart)";
    case reassembly::duplicate: return "duplicate of the message's last frame, ignored";
    case reassembly::restarted: return "the sender started the message over; the partial message was dropped";
    case reassembly::discarded: return "discarded: part of a message already broken";
    }
    return "?";
}

struct counters {
    std::size_t lines = 0, frames = 0, decoded = 0, errors = 0, no_frame = 0, other = 0;
    std::size_t messages = 0, duplicates = 0, restarts = 0, discarded = 0, reassembly_errors = 0;
};

class runner {
public:
    runner(const protocol* p, std::string_view name, direction forced, const output_format& out, bool scan)
        : p_(p), name_(name), forced_(forced), out_(out), scan_(scan) {}

    int run(std::string_view text) {
        std::vector<std::pair<std::size_t, parsed_line>> lines;
        bool log = false;
        std::size_t n = 0;
        for (std::size_t start = 0; start < text.size();) {
            auto end = text.find('\n', start);
            if (end == std::string_view::npos) end = text.size();
            auto pl = parse_line(text.substr(start, end - start));
            ++n;
            log = log || pl.log;
            lines.emplace_back(n, std::move(pl));
            start = end + 1;
        }
        c_.lines = n;
        // In an nRF Connect log, lines that are not log entries with a frame
        // (service lists, text) carry no frame; in a hex file every line is a frame.
        if (log) {
            // other lines carry no frame, but for bare hex (a frame pasted in among the log)
            for (auto& [num, pl] : lines)
                if (!pl.log && pl.kind == parsed_line::bad) pl.kind = parsed_line::none;
            source_ = "nRF Connect log";
            for (const auto& [num, pl] : lines)
                if (pl.log && !pl.source.empty()) source_ = pl.source + " log";
        } else {
            source_ = "hex lines";
        }
        // nRF Connect for Desktop logs a value the app writes twice: "changed" (its own
        // copy), then "written"; the first is no notification.
        for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
            auto& a = lines[i].second;
            if (a.kind != parsed_line::frame || !a.desktop_changed) continue;
            for (std::size_t k = i + 1; k < lines.size(); ++k) {
                const auto& b = lines[k].second;
                if (b.kind == parsed_line::none) continue;
                if (b.desktop_written && b.handle == a.handle && b.bytes == a.bytes) a.kind = parsed_line::none;
                break;
            }
        }
        // Without a protocol, every frame needs a characteristic UUID to pick one.
        if (!p_) {
            for (const auto& [num, pl] : lines) {
                if (pl.kind == parsed_line::none || !pl.uuid.empty()) continue;
                const std::string why =
                    "line " + std::to_string(num) + ": which protocol? " +
                    (pl.handle.empty() ? std::string("the line names no characteristic")
                                       : "the " + source_ + " names attribute handles, not characteristic UUIDs") +
                    ": give " + protocol_names() + " (robowire decode buwizz3 --file " + name_ + ")";
                out_.print(dump({{"type", "error"}, {"line", num}, {"error", why}}), "");
                err_line("error: " + why);
                return exit_usage;
            }
        }
        // With a protocol given: values of characteristics robowire does not know are
        // decoded with it when no line carries one of that protocol's own UUIDs (a
        // device with other UUIDs); otherwise they are other characteristics, skipped.
        if (p_) {
            decode_unknown_ = true;
            for (const auto& [num, pl] : lines) {
                if (pl.uuid.empty()) continue;
                const auto k = protocol_of_uuid(pl.uuid);
                if (k && k->p == p_) decode_unknown_ = false;
            }
        }
        for (auto& [num, pl] : lines) line(num, pl);
        if (c_.frames == 0 && c_.errors == 0) {
            std::string others;
            for (const auto& u : other_uuids_) others += (others.empty() ? ": " : ", ") + u;
            const std::string why = "no frame in " + name_ + ": " + std::to_string(n) + (n == 1 ? " line" : " lines") +
                                    " (read as " + source_ +
                                    (c_.other ? "; " + std::to_string(c_.other) +
                                                    (c_.other == 1 ? " value of another characteristic"
                                                                   : " values of other characteristics") +
                                                    others
                                              : "") +
                                    ")";
            out_.print(dump({{"type", "error"}, {"error", why}}), "");
            err_line("error: " + why);
            return exit_bad_input;
        }
        summary();
        return (c_.errors && !scan_) ? worst_ : exit_ok;
    }

    const std::string& source() const { return source_; }

private:
    void line(std::size_t num, const parsed_line& pl) {
        if (pl.kind == parsed_line::none) {
            ++c_.no_frame;
            return;
        }
        if (pl.kind == parsed_line::bad) {
            ++c_.frames;
            fail(num, pl, nullptr, pl.error, {}, exit_bad_input);
            return;
        }
        ++c_.frames;
        const protocol* p = p_;
        if (!pl.uuid.empty()) {
            const auto k = protocol_of_uuid(pl.uuid);
            // another characteristic (device name, battery, a port's UART...)
            if ((!k && !decode_unknown_) || (k && p_ && k->p != p_)) {
                ++c_.other;
                --c_.frames;
                if (other_uuids_.size() < 3 &&
                    std::find(other_uuids_.begin(), other_uuids_.end(), pl.uuid) == other_uuids_.end())
                    other_uuids_.push_back(pl.uuid);
                return;
            }
            if (k) p = k->p;
        }
        if (!p) {
            fail(num, pl, nullptr,
                 "which protocol? the line names no characteristic: give " + protocol_names() +
                     " (robowire decode buwizz3 --file ...)",
                 {}, exit_usage);
            return;
        }
        direction d = forced_;
        if (d == direction::any && p->has_directions) {
            if (pl.dir == link_direction::device_to_host) d = direction::notification;
            if (pl.dir == link_direction::host_to_device) d = direction::command;
        }
        const outcome o = p->decode(pl.bytes, d);
        if (o.status != exit_ok) {
            fail(num, pl, p, o.error, o.hints, o.status);
        } else {
            ++c_.decoded;
            std::string head = "line " + std::to_string(num);
            if (pl.dir != link_direction::unknown) head += " (" + std::string(direction_text(pl.dir)) + ")";
            out_.print(dump(with_line(json::parse(render_json(p->name, o)), num, pl)),
                       head + ": " + render_text(p->name, o));
        }
        if (scan_ && p == &navbot_protocol() && pl.bytes.size() == robowire::navbot::frame_size) reassemble(num, pl);
    }

    json with_line(const json& j, std::size_t num, const parsed_line& pl) const {
        json o = json::object();
        o["type"] = j.value("type", "message");
        o["line"] = num;
        if (pl.dir != link_direction::unknown) o["direction"] = direction_key(pl.dir);
        if (!pl.uuid.empty()) o["uuid"] = pl.uuid;
        if (!pl.handle.empty()) o["handle"] = pl.handle;
        for (auto it = j.begin(); it != j.end(); ++it)
            if (it.key() != "type") o[it.key()] = it.value();
        return o;
    }

    void fail(std::size_t num, const parsed_line& pl, const protocol* p, const std::string& error,
              const std::vector<std::string>& hints, int status) {
        ++c_.errors;
        if (status > worst_) worst_ = status;
        json j = {{"type", "error"}, {"error", error}};
        if (p) j["protocol"] = std::string(p->name);
        if (!pl.bytes.empty()) j["bytes"] = hex_of(pl.bytes);
        if (!hints.empty()) j["hints"] = hints;
        std::string text;  // scan: errors among the messages on stdout; decode: on stderr only
        if (scan_) {
            text = "line " + std::to_string(num) + ": error: " + error + "\n";
            for (const auto& h : hints) text += "line " + std::to_string(num) + ": hint: " + h + "\n";
        }
        if (out_.print(dump(with_line(j, num, pl)), text)) return;
        err_line("error: line " + std::to_string(num) + ": " + error);
        for (const auto& h : hints) err_line("hint: line " + std::to_string(num) + ": " + h);
    }

    void reassemble(std::size_t num, const parsed_line& pl) {
        namespace nb = robowire::navbot;
        auto& s = streams_[pl.dir];
        const auto r = s.r.push(std::span<const std::uint8_t>(pl.bytes));
        const auto f = robowire::decode<nb::frame>(std::span<const std::uint8_t>(pl.bytes));
        if (!f) return;  // not a frame: the decode above reported it
        std::string note;
        json j = {{"type", "reassembly"}};
        const int before = s.last_remaining;
        s.last_remaining = f->remaining;
        if (!r) {
            ++c_.reassembly_errors;
            std::string dropped;
            if (!s.lines.empty())
                dropped = "; the partial message (line" + std::string(s.lines.size() > 1 ? "s " : " ") +
                          std::to_string(s.lines.front()) +
                          (s.lines.size() > 1 ? "-" + std::to_string(s.lines.back()) : "") + ") is dropped";
            s.lines.clear();
            if (f->remaining != 0 && r.code() == errc::command_changed) s.lines.push_back(num);
            note = std::string(robowire::to_string(r.code())) + " at byte " + std::to_string(r.error().offset);
            if (r.code() == errc::bad_sequence)
                note += ": remaining " + std::to_string(f->remaining) + " after " + std::to_string(before) +
                        ", frames were lost";
            if (r.code() == errc::command_changed) note += ": a frame of another multi-frame message";
            note += dropped;
            j["outcome"] = "error";
            j["error"] = note;
        } else {
            j["outcome"] = reassembly_name(*r);
            switch (*r) {
            case nb::reassembly::need_more:
                s.lines.push_back(num);
                note = std::string(reassembly_text(*r)) + " (" + std::to_string(f->remaining) + " more)";
                break;
            case nb::reassembly::restarted:
                ++c_.restarts;
                s.lines.assign(1, num);
                note = reassembly_text(*r);
                break;
            case nb::reassembly::duplicate:
                ++c_.duplicates;
                note = reassembly_text(*r);
                break;
            case nb::reassembly::discarded:
                ++c_.discarded;
                note = reassembly_text(*r);
                break;
            case nb::reassembly::single: note = reassembly_text(*r); break;
            case nb::reassembly::complete: {
                s.lines.push_back(num);
                if (s.lines.size() < 2) {  // a one-frame message: the decode shows it
                    s.lines.clear();
                    return;
                }
                ++c_.messages;
                const auto text = s.r.text();
                const bool is_json = s.r.json().has_value();
                note = std::string(reassembly_text(*r)) + ", " + std::to_string(s.lines.size()) + " frames (lines " +
                       std::to_string(s.lines.front()) + "-" + std::to_string(num) + "), command 0x" +
                       hex_of(std::span(&f->command, 1)) + ", " + std::to_string(text.size()) + " bytes" +
                       (is_json ? " of JSON" : "") + ": " + std::string(text);
                j["command"] = f->command;
                j["lines"] = s.lines;
                j["text"] = std::string(text);
                j["json_object"] = is_json;
                s.lines.clear();
                break;
            }
            }
        }
        out_.print(dump(with_line(j, num, pl)), "line " + std::to_string(num) + ": navbot reassembly: " + note + "\n");
    }

    void summary() {
        std::vector<std::pair<std::string, std::uint64_t>> cs = {{"lines", c_.lines},
                                                                 {"frames", c_.frames},
                                                                 {"decoded", c_.decoded},
                                                                 {"errors", c_.errors},
                                                                 {"lines_without_frame", c_.no_frame},
                                                                 {"other_characteristics", c_.other}};
        if (scan_ && p_ == &navbot_protocol()) {
            cs.insert(cs.end(), {{"messages_reassembled", c_.messages},
                                 {"duplicates", c_.duplicates},
                                 {"restarted", c_.restarts},
                                 {"discarded", c_.discarded},
                                 {"reassembly_errors", c_.reassembly_errors}});
        }
        std::string text;
        for (const auto& [k, v] : cs) {
            std::string name = k;
            for (char& ch : name)
                if (ch == '_') ch = ' ';
            text += (text.empty() ? "" : ", ") + name + " " + std::to_string(v);
        }
        if (scan_) {
            out_.print(render_json_counters(cs, source_), text + "; " + name_ + " read as " + source_ + "\n");
        } else {
            err_line(name_ + ": read as " + source_ + ": " + text);
        }
    }

    const protocol* p_;
    std::string name_;
    direction forced_;
    const output_format& out_;
    bool scan_;
    counters c_;
    int worst_ = exit_ok;
    std::string source_;
    std::map<link_direction, navbot_stream> streams_;
    bool decode_unknown_ = false;
    std::vector<std::string> other_uuids_;
};

}  // namespace

bool is_log_line(std::string_view text) {
    if (text.find('\n') != std::string_view::npos) return false;
    const auto p = parse_line(text);
    return p.log && p.kind != parsed_line::none;
}

bool looks_like_text(std::span<const std::uint8_t> data) {
    for (const std::uint8_t b : data)
        if (b < 0x20 && b != '\t' && b != '\n' && b != '\r') return false;
    return !data.empty();
}

int decode_lines(const protocol* p, std::string_view name, std::string_view text, const output_format& out,
                 direction forced, bool scan) {
    runner r(p, name, forced, out, scan);
    return r.run(text);
}

}  // namespace robowire::cli
