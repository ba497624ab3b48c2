// robowire: decode, encode and describe BuWizz3, NAVBOT-ES02 and OSP frames from
// the library's field tables; scan an OSP byte stream; watch a serial port.
#include <robowire/robowire.hpp>

#include "dissector.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace bw = robowire::buwizz3;
namespace nb = robowire::navbot;
namespace osp = robowire::osp;
using robowire::errc;

namespace {

// ------------------------------------------------------------------ type lists
template <class... M> struct types {};
template <class V> struct of_variant;
template <class... M> struct of_variant<std::variant<M...>> { using type = types<M...>; };
template <class... A, class... B> types<A..., B...> join(types<A...>, types<B...>) { return {}; }

using buwizz3_types = decltype(join(typename of_variant<bw::command>::type{}, typename of_variant<bw::notification>::type{}));
using navbot_types = types<nb::maneuver, nb::frame>;
using osp_types = typename of_variant<osp::message>::type;

template <class... M, class F>
void for_each_type(types<M...>, F&& f) {
    (f(std::type_identity<M>{}), ...);
}

// ------------------------------------------------------------------ output tree
struct node {
    std::string key;
    std::string json;   // for leaves: JSON value
    std::string text;   // for leaves: text value (raw, and physical when it has a unit)
    std::vector<node> children;
    enum kind_t { leaf, object, array } kind = leaf;
};

std::string json_string(std::string_view s) {
    std::string o = "\"";
    for (char c : s) {
        switch (c) {
        case '"': o += "\\\""; break;
        case '\\': o += "\\\\"; break;
        case '\n': o += "\\n"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char b[8];
                std::snprintf(b, sizeof b, "\\u%04x", c);
                o += b;
            } else {
                o += c;
            }
        }
    }
    return o + "\"";
}
std::string hex_of(std::span<const std::uint8_t> b) {
    std::string s(robowire::hex_size(b.size()), ' ');
    const auto n = robowire::to_hex(b, std::span(s.data(), s.size()));
    s.resize(n.value_or(0));
    return s;
}
std::string number(double v) {
    char b[48];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

template <class F, class E>
node leaf_of(const F& f, const E& v) {
    node n;
    if constexpr (std::is_same_v<E, bool>) {
        n.json = n.text = v ? "true" : "false";
    } else if constexpr (std::is_enum_v<E>) {
        const auto name = robowire::enum_name(v);
        char b[16];
        std::snprintf(b, sizeof b, "0x%02X", static_cast<unsigned>(v));
        n.json = json_string(name);
        n.text = std::string(name) + " (" + b + ")";
    } else if constexpr (std::is_same_v<E, float>) {
        n.json = std::isfinite(v) ? number(v) : "null";
        n.text = number(v);
    } else if constexpr (std::is_integral_v<E>) {
        const auto raw = static_cast<long long>(v);
        n.json = std::to_string(raw);
        n.text = std::to_string(raw);
        if (!f.unit.name.empty()) {
            const double phys = static_cast<double>(raw) * f.unit.scale + f.unit.offset;
            if (f.unit.scale != 1.0 || f.unit.offset != 0.0) n.text += " (" + number(phys) + " " + std::string(f.unit.name) + ")";
            else n.text += " " + std::string(f.unit.name);
        }
    } else if constexpr (requires { v.view(); }) {
        n.json = json_string(v.view());
        n.text = json_string(v.view());
    } else {
        n.json = json_string(hex_of(v.span()));
        n.text = v.empty() ? "(none)" : hex_of(v.span());
    }
    return n;
}

template <class M>
node tree_of(const M& m);

template <class F, class E>
node element_of(const F& f, const E& v) {
    if constexpr (F::kind == robowire::wire_kind::record) {
        node n = tree_of(v);
        return n;
    } else {
        return leaf_of(f, v);
    }
}

template <class M>
node tree_of(const M& m) {
    node obj;
    obj.kind = node::object;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        const auto& member = m.*(f.member);
        auto value_node = [&](const auto& value) {
            if constexpr (F::is_array) {
                node arr;
                arr.kind = node::array;
                for (const auto& e : value) arr.children.push_back(element_of(f, e));
                return arr;
            } else {
                return element_of(f, value);
            }
        };
        node n;
        if constexpr (F::is_optional) {
            if (member) n = value_node(*member);
            else n.json = n.text = "null";
        } else {
            n = value_node(member);
        }
        n.key = std::string(f.name);
        obj.children.push_back(std::move(n));
    });
    return obj;
}

std::string render_json(const node& n) {
    if (n.kind == node::leaf) return n.json;
    std::string s = n.kind == node::object ? "{" : "[";
    for (std::size_t i = 0; i < n.children.size(); ++i) {
        if (i) s += ", ";
        if (n.kind == node::object) s += json_string(n.children[i].key) + ": ";
        s += render_json(n.children[i]);
    }
    return s + (n.kind == node::object ? "}" : "]");
}
void flatten(const node& n, const std::string& path, std::vector<std::pair<std::string, std::string>>& out) {
    if (n.kind == node::leaf) {
        out.emplace_back(path, n.text);
        return;
    }
    for (std::size_t i = 0; i < n.children.size(); ++i) {
        const std::string p = n.kind == node::object ? (path.empty() ? n.children[i].key : path + "." + n.children[i].key)
                                                      : path + "[" + std::to_string(i) + "]";
        flatten(n.children[i], p, out);
    }
}

template <class M>
void print_message(std::string_view protocol, const M& m, bool json) {
    const node t = tree_of(m);
    const std::string_view name = robowire::table_v<M>.name;
    if (json) {
        std::printf("{\"protocol\": %s, \"message\": %s, \"fields\": %s}\n", json_string(protocol).c_str(),
                    json_string(name).c_str(), render_json(t).c_str());
        return;
    }
    std::printf("%.*s %.*s\n", static_cast<int>(protocol.size()), protocol.data(), static_cast<int>(name.size()), name.data());
    std::vector<std::pair<std::string, std::string>> rows;
    flatten(t, "", rows);
    std::size_t w = 0;
    for (const auto& r : rows) w = std::max(w, r.first.size());
    for (const auto& r : rows) std::printf("  %-*s  %s\n", static_cast<int>(w), r.first.c_str(), r.second.c_str());
}

// ------------------------------------------------------------------ errors
int fail_with(const robowire::error& e, std::string_view extra = {}) {
    std::fprintf(stderr, "error: %.*s at byte %zu", static_cast<int>(robowire::to_string(e.code).size()),
                 robowire::to_string(e.code).data(), e.offset);
    if (!extra.empty()) std::fprintf(stderr, " (%.*s)", static_cast<int>(extra.size()), extra.data());
    std::fputc('\n', stderr);
    return 1;
}
int usage_error(const std::string& what) {
    std::fprintf(stderr, "error: %s (see robowire --help)\n", what.c_str());
    return 2;
}

// ------------------------------------------------------------------ hex input
std::optional<std::vector<std::uint8_t>> parse_hex_args(const std::vector<std::string>& args, robowire::error& err) {
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    const auto r = robowire::parse_hex<4096>(joined);
    if (!r) {
        err = r.error();
        return std::nullopt;
    }
    return std::vector<std::uint8_t>(r->begin(), r->end());
}

// ------------------------------------------------------------------ list
template <class M>
std::string key_bytes() {
    std::string s;
    for (const auto& b : robowire::table_v<M>.fixed) {
        if (b.code != errc::bad_command && b.code != errc::bad_device) continue;
        char h[8];
        std::snprintf(h, sizeof h, "%s%02X", s.empty() ? "" : " ", b.value);
        s += h;
    }
    return s;
}
template <class M>
void list_message(bool fields) {
    constexpr auto& t = robowire::table_v<M>;
    const std::size_t lo = t.min_size(), hi = t.max_input();
    std::printf("  %-26.*s %-8s %s bytes\n", static_cast<int>(t.name.size()), t.name.data(), key_bytes<M>().c_str(),
                lo == hi ? std::to_string(lo).c_str() : (std::to_string(lo) + "-" + std::to_string(hi)).c_str());
    if (!fields) return;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        std::string type(robowire::to_string(F::kind));
        if constexpr (F::kind == robowire::wire_kind::bits) {
            type.append("[").append(std::to_string(F::wire_type::lo)).append("..");
            type.append(std::to_string(F::wire_type::lo + F::wire_type::width - 1)).append("]");
        }
        if (F::is_enum) type.append(" enum");
        if (F::is_array) type.append(" x").append(std::to_string(F::count));
        if (F::is_optional) type.append(" optional");
        std::string range;
        if constexpr (F::is_enum) {
            for (const auto& e : robowire::enum_table_v<typename F::element_type>) {
                if (!range.empty()) range += '|';
                range.append(e.name);
            }
        } else if (F::kind != robowire::wire_kind::f32le && F::kind != robowire::wire_kind::record &&
                   F::kind != robowire::wire_kind::text && F::kind != robowire::wire_kind::tail) {
            range.append(std::to_string(f.valid.min)).append("..").append(std::to_string(f.valid.max));
        }
        std::string unit(f.unit.name);
        if (!unit.empty() && (f.unit.scale != 1.0 || f.unit.offset != 0.0)) {
            std::string scaled = "x";
            scaled.append(number(f.unit.scale));
            if (f.unit.offset != 0.0) scaled.append("+").append(number(f.unit.offset));
            unit = scaled.append(" ").append(unit);
        }
        std::printf("      %-24.*s @%-3zu %-20s %-12s %s\n", static_cast<int>(f.name.size()), f.name.data(), f.offset,
                    type.c_str(), unit.c_str(), range.c_str());
    });
}
int cmd_list(const std::vector<std::string>& args) {
    bool fields = false;
    std::string which;
    for (const auto& a : args) {
        if (a == "--fields") fields = true;
        else which = a;
    }
    if (!which.empty() && which != "buwizz3" && which != "navbot" && which != "osp") return usage_error("unknown protocol " + which);
    if (which.empty() || which == "buwizz3") {
        std::puts("buwizz3 (BLE; byte 0 = command)");
        for_each_type(buwizz3_types{}, [&](auto t) { list_message<typename decltype(t)::type>(fields); });
    }
    if (which.empty() || which == "navbot") {
        std::puts("navbot (BLE; 20-byte frames 55 AA command remaining 00 + 15 payload bytes)");
        for_each_type(navbot_types{}, [&](auto t) { list_message<typename decltype(t)::type>(fields); });
    }
    if (which.empty() || which == "osp") {
        std::puts("osp (serial; FF AA DEV CMD P1..P4 55 77)");
        for_each_type(osp_types{}, [&](auto t) { list_message<typename decltype(t)::type>(fields); });
    }
    return 0;
}

// ------------------------------------------------------------------ decode
int cmd_decode(const std::vector<std::string>& args) {
    bool json = false;
    std::string protocol, direction = "command";
    std::vector<std::string> hex;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json") json = true;
        else if (args[i] == "--direction" && i + 1 < args.size()) direction = args[++i];
        else if (protocol.empty()) protocol = args[i];
        else hex.push_back(args[i]);
    }
    if (protocol.empty() || hex.empty()) return usage_error("decode needs a protocol and hex bytes");
    robowire::error err{};
    const auto bytes = parse_hex_args(hex, err);
    if (!bytes) return fail_with(err, "in the hex text, character offset");
    const std::span<const std::uint8_t> in(*bytes);
    auto show = [&](const auto& v) {
        std::visit([&](const auto& m) { print_message(protocol, m, json); }, v);
        return 0;
    };
    if (protocol == "buwizz3") {
        if (direction == "command") {
            const auto r = bw::decode_command(in);
            return r ? show(*r) : fail_with(r.error());
        }
        if (direction == "notification") {
            const auto r = bw::decode_notification(in);
            return r ? show(*r) : fail_with(r.error());
        }
        return usage_error("--direction is command or notification");
    }
    if (protocol == "navbot") {
        const auto r = nb::decode_frame(in);
        if (!r && (r.code() == errc::too_long || r.code() == errc::too_short)) return fail_with(r.error(), nb::length_error_text(in.size()));
        return r ? show(*r) : fail_with(r.error());
    }
    if (protocol == "osp") {
        const auto r = osp::decode(in);
        if (!r && r.frame()) {
            char b[96];
            std::snprintf(b, sizeof b, "DEV %02X CMD %02X params %s", r.frame()->device, r.frame()->command,
                          hex_of(r.frame()->params).c_str());
            return fail_with(r.error(), b);
        }
        return r ? show(*r) : fail_with(r.error());
    }
    return usage_error("unknown protocol " + protocol);
}

// ------------------------------------------------------------------ encode
struct token_reader {
    std::vector<std::string> tokens;
    std::size_t pos = 0;
    std::string error;
    const std::string* next() {
        if (pos >= tokens.size()) {
            error = "not enough values";
            return nullptr;
        }
        return &tokens[pos++];
    }
};
std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t c = s.find(',', start);
        out.push_back(s.substr(start, c == std::string::npos ? std::string::npos : c - start));
        if (c == std::string::npos) return out;
        start = c + 1;
    }
}

template <class M>
bool fill_record(M& m, token_reader& r);

template <class F, class E>
bool parse_element(E& v, token_reader& r, const std::string& field) {
    if constexpr (F::kind == robowire::wire_kind::record) {
        return fill_record(v, r);
    } else {
        const std::string* t = r.next();
        if (!t) return false;
        auto bad = [&](const char* why) {
            r.error = field + "=" + *t + ": " + why;
            return false;
        };
        if constexpr (std::is_same_v<E, bool>) {
            if (*t == "true" || *t == "1") v = true;
            else if (*t == "false" || *t == "0") v = false;
            else return bad("expected true or false");
        } else if constexpr (std::is_enum_v<E>) {
            if (const auto e = robowire::enum_from_name<E>(*t)) {
                v = *e;
            } else {
                char* end = nullptr;
                const long n = std::strtol(t->c_str(), &end, 0);
                if (end == t->c_str() || *end || n < 0 || n > 255) return bad("unknown name");
                v = static_cast<E>(n);  // the codec reports an invalid code
            }
        } else if constexpr (std::is_same_v<E, float>) {
            char* end = nullptr;
            v = std::strtof(t->c_str(), &end);
            if (end == t->c_str() || *end) return bad("expected a number");
        } else if constexpr (std::is_integral_v<E>) {
            char* end = nullptr;
            errno = 0;
            const long long n = std::strtoll(t->c_str(), &end, 0);
            if (end == t->c_str() || *end || errno) return bad("expected an integer");
            if (n < static_cast<long long>(std::numeric_limits<E>::min()) || n > static_cast<long long>(std::numeric_limits<E>::max()))
                return bad("value out of range");
            v = static_cast<E>(n);
        } else if constexpr (requires { v.view(); }) {
            const auto s = E::make(*t);
            if (!s) return bad("text too long");
            v = *s;
        } else {
            const auto b = robowire::parse_hex<E::capacity()>(*t);
            if (!b) return bad("expected hex bytes");
            v = *b;
        }
        return true;
    }
}

template <class M>
bool fill_record(M& m, token_reader& r) {
    bool ok = true;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (!ok) return;
        auto& member = m.*(f.member);
        auto fill = [&](auto& value) {
            if constexpr (F::is_array) {
                for (auto& e : value) if (ok) ok = parse_element<F>(e, r, std::string(f.name));
            } else {
                ok = parse_element<F>(value, r, std::string(f.name));
            }
        };
        if constexpr (F::is_optional) fill(member.emplace());
        else fill(member);
    });
    return ok;
}

template <class M>
int encode_as(const std::map<std::string, std::string>& values, std::string& unknown) {
    M m{};
    std::map<std::string, std::string> rest = values;
    bool ok = true;
    std::string error;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        const auto it = rest.find(std::string(f.name));
        if (it == rest.end() || !ok) return;
        token_reader r{(F::kind == robowire::wire_kind::text || F::kind == robowire::wire_kind::tail) ? std::vector<std::string>{it->second}
                                                                                                    : split(it->second), 0, {}};
        auto& member = m.*(f.member);
        auto fill = [&](auto& value) {
            if constexpr (F::is_array) {
                for (auto& e : value) if (ok) ok = parse_element<F>(e, r, it->first);
            } else {
                ok = parse_element<F>(value, r, it->first);
            }
        };
        if constexpr (F::is_optional) fill(member.emplace());
        else fill(member);
        if (ok && r.pos != r.tokens.size()) {
            ok = false;
            r.error = it->first + ": too many values";
        }
        if (!ok) error = r.error.empty() ? it->first + ": bad value" : r.error;
        rest.erase(it);
    });
    if (!ok) {
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return 1;
    }
    if (!rest.empty()) {
        unknown = rest.begin()->first;
        return 2;
    }
    const auto w = robowire::encode(m);
    if (!w) return fail_with(w.error());
    std::printf("%s\n", hex_of(*w).c_str());
    return 0;
}

int cmd_encode(const std::vector<std::string>& args) {
    if (args.size() < 2) return usage_error("encode needs a protocol and a message name");
    const std::string& protocol = args[0];
    const std::string& message = args[1];
    std::map<std::string, std::string> values;
    for (std::size_t i = 2; i < args.size(); ++i) {
        const auto eq = args[i].find('=');
        if (eq == std::string::npos) return usage_error("expected name=value, got " + args[i]);
        values[args[i].substr(0, eq)] = args[i].substr(eq + 1);
    }
    int rc = -1;
    std::string unknown;
    auto try_types = [&](auto list) {
        for_each_type(list, [&](auto t) {
            using M = typename decltype(t)::type;
            if (rc == -1 && robowire::table_v<M>.name == message) rc = encode_as<M>(values, unknown);
        });
    };
    if (protocol == "buwizz3") try_types(buwizz3_types{});
    else if (protocol == "navbot") try_types(navbot_types{});
    else if (protocol == "osp") try_types(osp_types{});
    else return usage_error("unknown protocol " + protocol);
    if (rc == -1) return usage_error("unknown message " + message + " (robowire list " + protocol + ")");
    if (rc == 2) return usage_error("unknown field " + unknown + " (robowire list " + protocol + " --fields)");
    return rc;
}

// ------------------------------------------------------------------ scan / monitor
struct osp_printer {
    bool json = false;
    osp::scanner scanner;
    void feed(std::span<const std::uint8_t> chunk) {
        scanner.feed(chunk, [&](osp::scanner::frame_bytes f) {
            const auto m = osp::decode(f);
            if (m) {
                std::visit([&](const auto& msg) { print_message("osp", msg, json); }, *m);
            } else {
                std::printf("osp frame %s: %s\n", hex_of(f).c_str(), std::string(robowire::to_string(m.code())).c_str());
            }
            std::fflush(stdout);
        });
    }
    void counters() const {
        std::printf("frames %llu, skipped bytes %llu, false starts %llu\n", static_cast<unsigned long long>(scanner.frames()),
                    static_cast<unsigned long long>(scanner.skipped()), static_cast<unsigned long long>(scanner.false_starts()));
    }
};

int cmd_scan(const std::vector<std::string>& args) {
    osp_printer p;
    std::string path = "-";
    std::string protocol;
    for (const auto& a : args) {
        if (a == "--json") p.json = true;
        else if (protocol.empty()) protocol = a;
        else path = a;
    }
    if (protocol != "osp") return usage_error("scan reads OSP streams: robowire scan osp [file|-]");
    FILE* f = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
    if (!f) return usage_error("cannot open " + path);
    std::uint8_t buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) p.feed(std::span(buf, n));
    if (f != stdin) std::fclose(f);
    p.counters();
    return 0;
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
    case 921600: return B921600;
    default: return 0;
    }
}

int cmd_monitor(const std::vector<std::string>& args) {
    osp_printer p;
    std::string device;
    long baud = 115200, count = -1;
    double timeout = -1;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json") p.json = true;
        else if (args[i] == "--baud" && i + 1 < args.size()) baud = std::strtol(args[++i].c_str(), nullptr, 10);
        else if (args[i] == "--count" && i + 1 < args.size()) count = std::strtol(args[++i].c_str(), nullptr, 10);
        else if (args[i] == "--timeout" && i + 1 < args.size()) timeout = std::strtod(args[++i].c_str(), nullptr);
        else device = args[i];
    }
    if (device.empty()) return usage_error("monitor needs a serial device");
    const speed_t speed = baud_of(baud);
    if (!speed) return usage_error("unsupported baud rate " + std::to_string(baud));
    const int fd = ::open(device.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    if (fd < 0) return usage_error("cannot open " + device + ": " + std::strerror(errno));
    termios tio{};
    if (tcgetattr(fd, &tio) == 0) {
        cfmakeraw(&tio);
        cfsetispeed(&tio, speed);
        cfsetospeed(&tio, speed);
        tio.c_cflag |= CLOCAL | CREAD;
        tcsetattr(fd, TCSANOW, &tio);
    }
    const auto start = std::chrono::steady_clock::now();
    std::uint8_t buf[1024];
    for (;;) {
        if (count >= 0 && p.scanner.frames() >= static_cast<std::uint64_t>(count)) break;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (timeout >= 0 && elapsed >= timeout) break;
        pollfd pfd{fd, POLLIN, 0};
        if (::poll(&pfd, 1, 100) <= 0) continue;
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n > 0) p.feed(std::span(buf, static_cast<std::size_t>(n)));
        else if (n == 0 || (errno != EAGAIN && errno != EINTR)) break;
    }
    ::close(fd);
    p.counters();
    return 0;
}

const char* help_text = R"(robowire - decode, encode and describe BuWizz3, NAVBOT-ES02 and OSP frames

usage:
  robowire list [buwizz3|navbot|osp] [--fields]
      every message: name, command byte(s), length; --fields: each field's name,
      byte offset, wire type, unit and valid range
  robowire decode <buwizz3|navbot|osp> <hex...> [--json] [--direction command|notification]
      hex in any spelling: "01 5C", 015C, 0x01,0x5C, 01-5C-...; prints the message
      and every field (raw, and in physical units); --json: one object with
      "protocol", "message", "fields". BuWizz3 direction defaults to command.
  robowire encode <protocol> <message> [name=value ...]
      builds a frame; arrays as power=10,-20,0,0,0,0, enums by name, records
      flattened in table order (colors=255,0,0,0,255,0,...); prints hex
  robowire scan osp [file|-] [--json]
      finds and decodes OSP frames in a byte stream; prints the scanner counters
  robowire monitor <serial-device> [--baud 115200] [--count N] [--timeout S] [--json]
      reads an OSP stream from a serial port (raw mode) and decodes frames as they come

exit status: 0 ok, 1 bad input (the message names the problem and byte offset), 2 usage error
)";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(help_text, stdout);
        return args.empty() ? 2 : 0;
    }
    const std::string cmd = args[0];
    args.erase(args.begin());
    for (const auto& a : args)
        if (a == "--help" || a == "-h") {
            std::fputs(help_text, stdout);
            return 0;
        }
    // ---- dissector <buwizz3|navbot|osp|all> [--output DIR]: Wireshark Lua plugins (tools/dissector.hpp)
    if (cmd == "dissector") {
        std::string dir = ".";
        if (args.size() == 3 && args[1] == "--output") dir = args[2];
        else if (args.size() != 1) return usage_error("usage: robowire dissector <buwizz3|navbot|osp|all> [--output DIR]");
        return robowire::tool::write_dissectors(args[0], dir.c_str(), stderr);
    }
    // ---- end dissector
    if (cmd == "list") return cmd_list(args);
    if (cmd == "decode") return cmd_decode(args);
    if (cmd == "encode") return cmd_encode(args);
    if (cmd == "scan") return cmd_scan(args);
    if (cmd == "monitor") return cmd_monitor(args);
    return usage_error("unknown command " + cmd);
}
