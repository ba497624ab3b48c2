// Text input line by line: hex lines, and the logs of nRF Connect (Android
// and desktop). Each line that holds a frame is decoded with its line number;
// the line says the direction and, in Android logs, the characteristic UUID,
// which picks the protocol. `scan navbot` reassembles multi-frame messages.
#include <robowire/navbot/frame.hpp>
#include <robowire/navbot/multiframe.hpp>
#include <robowire/protocols.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <deque>
#include <map>

#include "tools.hpp"

namespace robowire::tools {
namespace {
void err_line(const std::string& s) { std::fprintf(stderr, "%s\n", s.c_str()); }

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
void lower_into(std::string& o, std::string_view s) {
    o.assign(s);
    for (char& c : o)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
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

// "13:40:29.880" at the start of s: milliseconds since midnight, or -1.
long time_of_day(std::string_view s) {
    if (s.size() < 12 || s[2] != ':' || s[5] != ':' || s[8] != '.') return -1;
    for (const std::size_t i : {0u, 1u, 3u, 4u, 6u, 7u, 9u, 10u, 11u})
        if (!is_digit(s[i])) return -1;
    auto d = [&](std::size_t i) { return static_cast<long>(s[i] - '0'); };
    const long h = d(0) * 10 + d(1), m = d(3) * 10 + d(4), sec = d(6) * 10 + d(7);
    if (h > 23 || m > 59 || sec > 60) return -1;
    return ((h * 60 + m) * 60 + sec) * 1000 + d(9) * 100 + d(10) * 10 + d(11);
}
// "2026-03-14" at the start of s: days since 1970-01-01, or -1.
long date_of(std::string_view s) {
    if (s.size() < 10 || s[4] != '-' || s[7] != '-') return -1;
    for (const std::size_t i : {0u, 1u, 2u, 3u, 5u, 6u, 8u, 9u})
        if (!is_digit(s[i])) return -1;
    auto n = [&](std::size_t i, std::size_t k) {
        int v = 0;
        for (std::size_t j = i; j < i + k; ++j) v = v * 10 + (s[j] - '0');
        return v;
    };
    const std::chrono::year_month_day ymd{std::chrono::year(n(0, 4)),
                                          std::chrono::month(static_cast<unsigned>(n(5, 2))),
                                          std::chrono::day(static_cast<unsigned>(n(8, 2)))};
    if (!ymd.ok()) return -1;
    return static_cast<long>(std::chrono::sys_days(ymd).time_since_epoch().count());
}
// "2026-03-14T10:12:06.655" (day -1: "10:12:06.655")
void put_iso(std::string& o, long day, long ms) {
    if (day >= 0) {
        static long cached_day = -1;
        static char date[16];
        if (day != cached_day) {
            const std::chrono::year_month_day ymd{std::chrono::sys_days(std::chrono::days(day))};
            std::snprintf(date, sizeof date, "%04d-%02u-%02uT", static_cast<int>(ymd.year()),
                          static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()));
            cached_day = day;
        }
        o += date;
    }
    char b[12] = {'0', '0', ':', '0', '0', ':', '0', '0', '.', '0', '0', '0'};
    auto two = [&](int at, long v) {
        b[at] = static_cast<char>('0' + v / 10);
        b[at + 1] = static_cast<char>('0' + v % 10);
    };
    two(0, ms / 3600000 % 100);
    two(3, ms / 60000 % 60);
    two(6, ms / 1000 % 60);
    b[9] = static_cast<char>('0' + ms % 1000 / 100);
    b[10] = static_cast<char>('0' + ms % 100 / 10);
    b[11] = static_cast<char>('0' + ms % 10);
    o.append(b, sizeof b);
}

struct parsed_line {
    enum kind_t { none, frame, bad } kind = none;
    bool log = false;         // an nRF Connect line (with or without a frame)
    const char* source = "";  // "nRF Connect (Android)", "nRF Connect (desktop)", "hex"
    byte_vector bytes;
    link_direction dir = link_direction::unknown;
    std::string uuid;    // Android: the characteristic
    std::string handle;  // desktop: the attribute handle
    bool desktop_changed = false, desktop_written = false;
    std::string error;
    long tod = -1;         // time of day (ms), -1: none
    long day = -1;         // the line's own date (desktop log file), -1: none
    long header_day = -1;  // "nRF Connect, 2026-03-14": the date of the lines that follow
    void reset() {
        kind = none;
        log = false;
        source = "";
        bytes.clear();
        dir = link_direction::unknown;
        uuid.clear();
        handle.clear();
        desktop_changed = desktop_written = false;
        error.clear();
        tod = day = header_day = -1;
    }
};

// The bytes of a logged value: "(0x) 01-6D-50" up to the comma before the
// value as text that nRF Connect may add (`, "Hello"`).
bool value_bytes(std::string_view v, byte_vector& out, std::string& error) {
    v = trim(v);
    if (starts_with(v, "(0x)")) v.remove_prefix(4);
    v = trim(v);
    std::size_t used = 0;  // the common form, one pass
    if (parse_dashed_hex(v, out, used)) return true;
    // the value runs up to the comma before the text: a character in it that is no hex digit
    // is reported as in a hex line, with its place in the value
    v = trim(v.substr(0, v.find(',')));
    out.clear();
    if (v.empty()) return true;
    return parse_hex_into(v, out, error);
}

// One line of nRF Connect for Android.
void android_line(std::string_view msg, parsed_line& p) {
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
        if (starts_with(rest, "descr.")) return;  // a descriptor (notifications on/off), no frame
        const auto comma = rest.find(", value: ");
        if (comma == std::string_view::npos) return;
        lower_into(p.uuid, trim(rest.substr(0, comma)));
        if (!value_bytes(rest.substr(comma + 9), p.bytes, p.error)) {
            p.kind = parsed_line::bad;
        } else if (!p.bytes.empty()) {
            p.kind = parsed_line::frame;
            p.dir = dir;
        }
        return;
    }
}

// One line of nRF Connect for Desktop (Bluetooth Low Energy app): the log
// file's "2024-09-14T21:29:24.282Z INFO Attribute value changed, handle: 0x12, value (0x): 01-02"
// or the log panel's "11:44:40.906<TAB>Attribute value written, handle: 0x26, value (0x): 01-00".
bool desktop_line(std::string_view s, parsed_line& p) {
    const bool iso = s.size() > 25 && is_digit(s[0]) && s[4] == '-' && s[10] == 'T' && s[23] == 'Z' && s[24] == ' ';
    const bool panel = s.size() > 13 && is_digit(s[0]) && s[2] == ':' && s[5] == ':' && s[8] == '.' && s[12] == '\t';
    static constexpr std::array<std::pair<std::string_view, link_direction>, 3> kinds{{
        {"Attribute value changed, handle: ", link_direction::device_to_host},
        {"Attribute value read, handle: ", link_direction::device_to_host},
        {"Attribute value written, handle: ", link_direction::host_to_device},
    }};
    auto set_time = [&] {
        if (iso) {
            p.day = date_of(s);
            p.tod = time_of_day(s.substr(11));
            if (p.tod < 0) p.day = -1;
        } else if (panel) {
            p.tod = time_of_day(s);
        }
    };
    for (const auto& [text, dir] : kinds) {
        const auto at = s.find(text);
        if (at == std::string_view::npos) continue;
        p.log = true;
        p.source = "nRF Connect (desktop)";
        set_time();
        std::string_view rest = s.substr(at + text.size());
        const auto comma = rest.find(", value (0x): ");
        if (comma == std::string_view::npos) return true;
        lower_into(p.handle, trim(rest.substr(0, comma)));
        p.desktop_changed = text.find("changed") != std::string_view::npos;
        p.desktop_written = text.find("written") != std::string_view::npos;
        const bool ok = value_bytes(rest.substr(comma + 14), p.bytes, p.error);
        // 00 00, 01 00, 02 00 written: a Client Characteristic Configuration descriptor
        // (notifications or indications off or on), no frame of any protocol here
        const bool cccd = ok && p.bytes.size() == 2 && p.bytes[0] <= 2 && p.bytes[1] == 0;
        if (!ok) {
            p.kind = parsed_line::bad;
        } else if (!p.bytes.empty() && !cccd) {
            p.kind = parsed_line::frame;
            p.dir = dir;
        }
        return true;
    }
    // other lines of the desktop log: "2024-09-14T21:29:24.282Z INFO ...", "11:44:29.244<TAB>Connected to device ..."
    if (iso || panel) {
        p.log = true;
        p.source = "nRF Connect (desktop)";
        set_time();
        return true;
    }
    return false;
}

void parse_line(std::string_view raw, parsed_line& p) {
    p.reset();
    const std::string_view s = trim(raw);
    if (android_prefix(s)) {
        p.tod = time_of_day(s.substr(2));
        android_line(s.substr(15), p);
        return;
    }
    if (desktop_line(s, p)) return;
    // the header of an nRF Connect for Android log: "nRF Connect, 2024-05-11", "Device Name (A4:...)"
    if (starts_with(s, "nRF Connect, ")) {
        p.log = true;
        p.source = "nRF Connect (Android)";
        p.header_day = date_of(s.substr(13));
        return;
    }
    if (s.empty() || s[0] == '#') return;
    p.source = "hex";
    p.kind = parse_hex_into(s, p.bytes, p.error) ? parsed_line::frame : parsed_line::bad;
}

// The protocol and role of a characteristic UUID robowire knows.
struct known_uuid {
    const protocol* p;
    const char* role;
};
std::optional<known_uuid> protocol_of_uuid_uncached(const std::string& uuid) {
    const auto u = uuid128::parse(uuid);
    if (!u) return std::nullopt;
    for (const auto* d : robowire::all_protocols)
        if (const auto* c = d->find(*u))
            if (const protocol* p = find_protocol(d->name)) return known_uuid{p, c->label.data()};
    return std::nullopt;
}

// Whether `scan` reassembles the protocol's frames into messages (its descriptor's stream kind).
bool reassembles(const protocol* p) {
    const auto* d = robowire::find_descriptor(p->name);
    return d != nullptr && d->stream == robowire::stream_kind::reassembler;
}

// The same, remembering the last UUID asked for (a log asks for the same few again and again).
std::optional<known_uuid> protocol_of_uuid(const std::string& uuid) {
    static std::string last;
    static std::optional<known_uuid> known;
    if (uuid != last) {
        last = uuid;
        known = protocol_of_uuid_uncached(uuid);
    }
    return known;
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

// The lines of a message's frames: a range where they follow each other ("4-5",
// "2, 4", "2-4, 6"); of more than 8 runs the first 3, "..." and the last.
std::string line_list(const std::vector<std::size_t>& lines) {
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (const std::size_t n : lines) {
        if (!runs.empty() && n == runs.back().second + 1) runs.back().second = n;
        else runs.emplace_back(n, n);
    }
    std::string s = lines.size() == 1 ? "line " : "lines ";
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (i) s += ", ";
        if (runs.size() > 8 && i == 3) {
            s += "..., ";
            i = runs.size() - 1;
        }
        s += std::to_string(runs[i].first);
        if (runs[i].second != runs[i].first) s += "-" + std::to_string(runs[i].second);
    }
    return s;
}

struct counters {
    std::size_t lines = 0, frames = 0, decoded = 0, errors = 0, no_frame = 0, other = 0, outside = 0;
    std::size_t messages = 0, duplicates = 0, restarts = 0, discarded = 0, reassembly_errors = 0;
};

// Lines are decoded as they are read. Two decisions need lines further on,
// which are held back (at most `hold_lines` lines, `hold_bytes` bytes) until
// a line decides them or the limit or the end of the input is reached:
// whether the input is an nRF Connect log (then lines that are neither log
// entries nor hex carry no frame; otherwise they are errors), and, with a
// protocol given, whether values of characteristics robowire does not know
// are decoded with it (when no line carries one of its own UUIDs).
// nRF Connect for Desktop's "changed" line waits for the next line (the
// "written" line of the same value makes it no notification).
class runner {
public:
    static constexpr std::size_t hold_lines = 1024, hold_bytes = 1 << 20;

    runner(const protocol* p, std::string_view name, const log_options& opt, output& out)
        : p_(p), name_(name), opt_(opt), out_(out) {}

    // The next line; false: stop (a usage error was reported).
    bool feed(std::size_t num, std::string_view text, std::size_t length, bool ended) {
        c_.lines = num;
        last_ended_ = ended;
        parsed_line& pl = scratch_;
        if (length > text.size() || length > input_stream::max_line) {
            pl.reset();
            pl.kind = parsed_line::bad;
            pl.error = "line too long: " + std::to_string(length) + " bytes (at most " +
                       std::to_string(input_stream::max_line) + "), skipped; it starts " +
                       std::string(text.substr(0, 32)) + "...";
            pl.source = "";
        } else if (const std::string c = control_byte(text); !c.empty()) {
            pl.reset();
            pl.kind = parsed_line::bad;
            pl.error = "not text: " + c + " (binary data in a text input), line skipped";
        } else {
            parse_line(text, pl);
            if (!ended && pl.kind == parsed_line::bad) pl.error += " (the last line has no line end: cut short?)";
        }
        pl.error = shorten(pl.error, 300);
        // time: the header's date, then each line's time of day (a day more when it goes back past midnight)
        if (pl.header_day >= 0) day_ = pl.header_day, last_tod_ = -1;
        if (pl.day >= 0) day_ = pl.day, last_tod_ = pl.tod;
        if (pl.tod >= 0 && pl.day < 0) {
            if (last_tod_ >= 0 && pl.tod + 12L * 3600 * 1000 < last_tod_ && day_ >= 0) ++day_;
            last_tod_ = pl.tod;
        }
        if (pl.log) {
            log_ = true;
            if (*pl.source) source_ = std::string(pl.source) + " log";
        }
        if (pl.tod >= 0) pl.day = day_;
        return stage_desktop(num, pl);
    }

    // The end of the input.
    int finish() {
        if (held_) {
            held_ = false;
            if (!stage_hold(held_num_, held_line_)) return exit_usage;
        }
        force_decisions();
        if (!drain()) return exit_usage;
        if (stopped_) return exit_usage;
        if (c_.frames == 0 && c_.errors == 0) {
            std::string others;
            for (const auto& u : other_uuids_) others += (others.empty() ? ": " : ", ") + u;
            const std::size_t n = c_.lines;
            const std::string why =
                "no frame in " + name_ + ": " +
                (n == 0 ? std::string("it is empty") : std::to_string(n) + (n == 1 ? " line" : " lines")) +
                (n == 0 ? ""
                        : " (read as " + source() +
                              (c_.other ? "; " + std::to_string(c_.other) +
                                              (c_.other == 1 ? " value of another characteristic"
                                                             : " values of other characteristics") +
                                              others
                                        : "") +
                              (c_.outside ? "; " + std::to_string(c_.outside) + " outside the time range" : "") + ")");
            out_.error({}, why, "");
            say("error: " + why);
            return exit_bad_input;
        }
        summary();
        return (c_.errors && !opt_.scan) ? worst_ : exit_ok;
    }

private:
    void say(const std::string& s) const {
        if (!opt_.quiet) err_line(s);
    }
    std::string source() const { return source_.empty() ? (log_ ? "nRF Connect log" : "hex lines") : source_; }

    bool stage_desktop(std::size_t num, parsed_line& pl) {
        if (held_) {
            if (pl.kind == parsed_line::none || (!pl.log && pl.kind == parsed_line::bad && log_))
                return stage_hold(num, pl);
            if (pl.desktop_written && pl.handle == held_line_.handle && pl.bytes == held_line_.bytes)
                held_line_.kind = parsed_line::none;
            held_ = false;
            if (!stage_hold(held_num_, held_line_)) return false;
        }
        if (pl.kind == parsed_line::frame && pl.desktop_changed) {
            std::swap(held_line_, pl);
            held_num_ = num;
            held_ = true;
            return true;
        }
        return stage_hold(num, pl);
    }

    // Does the line wait for a decision?
    bool undecided(const parsed_line& pl) const {
        if (pl.kind == parsed_line::bad && !pl.log && !log_ && !hex_decided_ && pl.source[0]) return true;
        if (p_ && !unknown_decided_ && pl.kind != parsed_line::none && !pl.uuid.empty()) {
            const auto k = protocol_of_uuid(pl.uuid);
            if (!k) return true;
        }
        return false;
    }
    void note_decisions(const parsed_line& pl) {
        if (p_ && !unknown_decided_ && !pl.uuid.empty()) {
            const auto k = protocol_of_uuid(pl.uuid);
            if (k && k->p == p_) {
                unknown_decided_ = true;
                decode_unknown_ = false;
            }
        }
    }
    void force_decisions() {
        hex_decided_ = true;
        if (!unknown_decided_) {
            unknown_decided_ = true;
            decode_unknown_ = true;
        }
    }

    bool stage_hold(std::size_t num, parsed_line& pl) {
        note_decisions(pl);
        if (queue_.empty() && !undecided(pl)) return line(num, pl);
        queue_bytes_ += pl.bytes.size() + pl.error.size() + 64;
        queue_.emplace_back(num, pl);
        if (queue_.size() > hold_lines || queue_bytes_ > hold_bytes) force_decisions();
        return drain();
    }
    bool drain() {
        while (!queue_.empty() && !undecided(queue_.front().second)) {
            auto& [num, pl] = queue_.front();
            queue_bytes_ -= std::min(queue_bytes_, pl.bytes.size() + pl.error.size() + 64);
            const bool go = line(num, pl);
            queue_.pop_front();
            if (!go) return false;
        }
        return true;
    }

    record_meta meta_of(std::size_t num, const parsed_line& pl) {
        record_meta m;
        m.line = num;
        m.dir = pl.dir;
        m.uuid = pl.uuid;
        m.handle = pl.handle;
        time_.clear();
        if (pl.tod >= 0) put_iso(time_, pl.day, pl.tod);
        m.time = time_;
        return m;
    }

    bool in_range(const parsed_line& pl) const {
        if (!opt_.since && !opt_.until) return true;
        if (pl.tod < 0) return false;
        auto before = [&](const time_point& t) {  // is the line before t?
            if (t.day >= 0) return pl.day < 0 || pl.day < t.day || (pl.day == t.day && pl.tod < t.ms);
            return pl.tod < t.ms;
        };
        auto after = [&](const time_point& t) {
            if (t.day >= 0) return pl.day < 0 || pl.day > t.day || (pl.day == t.day && pl.tod > t.ms);
            return pl.tod > t.ms;
        };
        return !(opt_.since && before(*opt_.since)) && !(opt_.until && after(*opt_.until));
    }

    bool line(std::size_t num, parsed_line& pl) {
        if (pl.kind == parsed_line::bad && !pl.log && log_ && pl.source[0]) pl.kind = parsed_line::none;
        // each line is counted once, under the first that applies: no frame, another
        // characteristic (never a candidate), outside the time range, a frame
        if (pl.kind == parsed_line::none) {
            ++c_.no_frame;
            return true;
        }
        const protocol* p = p_;
        if (!pl.uuid.empty()) {
            const auto k = protocol_of_uuid(pl.uuid);
            // another characteristic (device name, battery, a port's UART...)
            if ((!k && !decode_unknown_) || (k && p_ && k->p != p_)) {
                ++c_.other;
                if (other_uuids_.size() < 3 &&
                    std::find(other_uuids_.begin(), other_uuids_.end(), pl.uuid) == other_uuids_.end())
                    other_uuids_.push_back(shorten(pl.uuid, 40));
                return true;
            }
            if (k) p = k->p;
        }
        if (!in_range(pl)) {
            ++c_.outside;
            return true;
        }
        ++c_.frames;
        if (pl.kind == parsed_line::bad) {
            fail(num, pl, nullptr, pl.error, {}, exit_bad_input);
            return true;
        }
        if (!p) {
            // without a protocol, every frame needs a characteristic UUID to pick one
            const std::string why =
                "which protocol? " +
                (pl.handle.empty() ? std::string("the line names no characteristic")
                                   : "the " + source() + " names attribute handles, not characteristic UUIDs") +
                ": give " + protocol_names() + " (robowire decode buwizz3 --file " + name_ + ")";
            record_meta m;
            m.line = num;
            out_.error(m, "line " + std::to_string(num) + ": " + why, "");
            say("error: " + line_prefix(num, pl) + why);
            stopped_ = true;
            return false;
        }
        direction d = opt_.forced;
        if (d == direction::any && p->has_directions) {
            if (pl.dir == link_direction::device_to_host) d = direction::notification;
            if (pl.dir == link_direction::host_to_device) d = direction::command;
        }
        const record_meta meta = meta_of(num, pl);
        const outcome o = p->decode(pl.bytes, d, out_, meta);
        if (o.status != exit_ok) fail(num, pl, p, o.error, o.hints, o.status);
        else ++c_.decoded;
        if (opt_.scan && reassembles(p) && pl.bytes.size() == robowire::navbot::frame_size) reassemble(num, pl);
        return true;
    }

    void fail(std::size_t num, const parsed_line& pl, const protocol* p, const std::string& error,
              const std::vector<std::string>& hints, int status) {
        ++c_.errors;
        if (status > worst_) worst_ = status;
        const record_meta meta = meta_of(num, pl);
        std::string text;  // scan: errors among the messages on stdout; decode: on stderr only
        if (opt_.scan) {
            record_meta at = meta;  // "<time> line N: error: ..."
            at.dir = link_direction::unknown;
            std::string prefix;
            put_text_prefix(prefix, at);
            text = prefix + "error: " + error + "\n";
            for (const auto& h : hints) text += prefix + "hint: " + h + "\n";
        }
        std::vector<std::pair<std::string_view, std::string_view>> extra;
        if (p) extra.emplace_back("protocol", p->name);
        const std::string bytes = pl.bytes.empty() ? std::string() : shorten(hex_of(pl.bytes), 200);
        if (!bytes.empty()) extra.emplace_back("bytes", bytes);
        if (out_.error(meta, error, text, extra, hints)) return;
        // decode: "error: <time> line N: ..." on stderr, the same place as scan's records
        const std::string at = line_prefix(num, pl);
        say("error: " + at + error);
        for (const auto& h : hints) say("hint: " + at + h);
    }
    // "<time> line N: " (no time when the line has none): where an error line on stderr comes from
    std::string line_prefix(std::size_t num, const parsed_line& pl) {
        record_meta at = meta_of(num, pl);
        at.dir = link_direction::unknown;
        std::string prefix;
        put_text_prefix(prefix, at);
        return prefix;
    }

    void reassemble(std::size_t num, const parsed_line& pl) {
        namespace nb = robowire::navbot;
        auto& s = streams_[pl.dir];
        const auto r = s.r.push(std::span<const std::uint8_t>(pl.bytes));
        const auto f = robowire::decode<nb::frame>(std::span<const std::uint8_t>(pl.bytes));
        if (!f) return;  // not a frame: the decode above reported it
        std::string note;
        std::string& j = json_;  // the record's members after the head (JSON)
        j.clear();
        const int before = s.last_remaining;
        s.last_remaining = f->remaining;
        if (!r) {
            ++c_.reassembly_errors;
            std::string dropped;
            if (!s.lines.empty()) dropped = "; the partial message (" + line_list(s.lines) + ") is dropped";
            s.lines.clear();
            if (f->remaining != 0 && r.code() == errc::command_changed) s.lines.push_back(num);
            note = std::string(robowire::to_string(r.code())) + " at byte " + std::to_string(r.error().offset);
            if (r.code() == errc::bad_sequence)
                note += ": remaining " + std::to_string(f->remaining) + " after " + std::to_string(before) +
                        ", frames were lost";
            if (r.code() == errc::command_changed) note += ": a frame of another multi-frame message";
            note += dropped;
            j += ",\"outcome\":\"error\",\"error\":";
            put_json_string(j, note);
        } else {
            j.append(",\"outcome\":\"").append(reassembly_name(*r)).append("\"");
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
                note = std::string(reassembly_text(*r)) + ", " + std::to_string(s.lines.size()) + " frames (" +
                       line_list(s.lines) + "), command 0x" + hex_of(std::span(&f->command, 1)) + ", " +
                       std::to_string(text.size()) + " bytes" + (is_json ? " of JSON" : "") + ": " + std::string(text);
                j.append(",\"command\":").append(std::to_string(f->command)).append(",\"lines\":[");
                for (std::size_t i = 0; i < s.lines.size(); ++i)
                    j.append(i ? "," : "").append(std::to_string(s.lines[i]));
                j += "],\"text\":";
                put_json_string(j, std::string_view(text.data(), text.size()));
                j.append(",\"json_object\":").append(is_json ? "true" : "false");
                s.lines.clear();
                break;
            }
            }
        }
        const record_meta meta = meta_of(num, pl);
        switch (out_.kind) {
        case format_kind::text: {
            record_meta at = meta;  // "<time> line N: navbot reassembly: ..."
            at.dir = link_direction::unknown;
            put_text_prefix(out_.buf, at);
            out_.buf.append("navbot reassembly: ").append(note).append("\n");
            break;
        }
        case format_kind::json:
            put_json_head(out_.buf, "reassembly", meta);
            out_.buf.append(j).append("}\n");
            break;
        case format_kind::csv: return;
        }
        out_.end_record();
    }

    void summary() {
        std::vector<std::pair<std::string, std::uint64_t>> cs = {{"lines", c_.lines},
                                                                 {"frames", c_.frames},
                                                                 {"decoded", c_.decoded},
                                                                 {"errors", c_.errors},
                                                                 {"lines_without_frame", c_.no_frame},
                                                                 {"other_characteristics", c_.other}};
        if (opt_.since || opt_.until) cs.emplace_back("outside_time_range", c_.outside);
        if (opt_.scan && reassembles(p_)) {
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
        if ((opt_.scan || opt_.quiet) &&
            out_.counters(cs, source(), text + "; " + name_ + " read as " + source() + "\n"))
            return;
        if (opt_.quiet) return;
        out_.flush();
        err_line(name_ + ": read as " + source() + ": " + text);
    }

    const protocol* p_;
    std::string name_;
    const log_options& opt_;
    output& out_;
    counters c_;
    int worst_ = exit_ok;
    std::string source_;
    bool log_ = false, hex_decided_ = false, unknown_decided_ = false, decode_unknown_ = false, stopped_ = false;
    bool last_ended_ = true;
    std::map<link_direction, navbot_stream> streams_;
    std::vector<std::string> other_uuids_;
    std::deque<std::pair<std::size_t, parsed_line>> queue_;
    std::size_t queue_bytes_ = 0;
    parsed_line scratch_, held_line_;
    std::size_t held_num_ = 0;
    bool held_ = false;
    long day_ = -1, last_tod_ = -1;
    std::string time_, json_;
};

}  // namespace

bool is_log_line(std::string_view text) {
    if (text.find_first_of("\r\n") != std::string_view::npos) return false;
    parsed_line p;
    parse_line(text, p);
    return p.log && p.kind != parsed_line::none;
}

std::optional<time_point> parse_time_point(std::string_view s) {
    time_point t;
    if (s.size() >= 10 && s[4] == '-') {
        t.day = date_of(s);
        if (t.day < 0) return std::nullopt;
        s.remove_prefix(10);
        if (s.empty()) return t;
        if (s[0] != 'T' && s[0] != ' ') return std::nullopt;
        s.remove_prefix(1);
    }
    // HH:MM[:SS[.mmm]]
    std::string full(s);
    if (full.size() == 5) full += ":00";
    if (full.size() == 8) full += ".000";
    while (full.size() > 8 && full.size() < 12) full += '0';
    if (full.size() != 12) return std::nullopt;
    t.ms = time_of_day(full);
    if (t.ms < 0) return std::nullopt;
    return t;
}

struct line_decoder::impl {
    runner r;
};
line_decoder::line_decoder(const protocol* p, std::string_view name, output& out, const log_options& opt)
    : impl_(new impl{runner(p, name, opt, out)}) {}
line_decoder::~line_decoder() = default;
bool line_decoder::feed(std::size_t num, std::string_view line, std::size_t length, bool ended) {
    return impl_->r.feed(num, line, length, ended);
}
int line_decoder::finish() { return impl_->r.finish(); }

int decode_lines(const protocol* p, input_stream& in, output& out, const log_options& opt) {
    line_decoder r(p, in.name, out, opt);
    in.flush_before_wait = &out;
    std::string_view line;
    std::size_t length = 0, num = 0;
    bool ended = true;
    while (in.next_line(line, length, ended))
        if (!r.feed(++num, line, length, ended)) break;
    if (!in.error.empty()) {
        out.flush();
        err_line("error: " + in.error);
        return exit_bad_input;
    }
    return r.finish();
}

}  // namespace robowire::tools
