// Templates over the library's tables: a message's `list` entry, the field at
// a byte offset, and encoding from name=value pairs (emit.hpp writes messages).
// Included by the protocol modules only (buwizz3.cpp, navbot.cpp, osp.cpp).
#pragma once

#include <robowire/core/fields.hpp>
#include <robowire/core/flag_bits.hpp>
#include <robowire/reflect.hpp>
#include <robowire/robowire.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <variant>

#include "text.hpp"
#include "tools.hpp"

namespace robowire::tools {

// ---------------------------------------------------------------- small helpers
inline std::string number(double v) {
    char b[48];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}
// Rounded to 15 significant digits (13.000000000000002 -> 13).
inline double tidy(double v) {
    char b[48];
    std::snprintf(b, sizeof b, "%.15g", v);
    return std::strtod(b, nullptr);
}
inline std::string plural(std::size_t n, std::string_view one, std::string_view many) {
    return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}
inline std::string unit_text(const robowire::unit& u) {
    if (u.name.empty()) return {};
    std::string s;
    if (u.scale != 1.0 || u.offset != 0.0) {
        s = "raw x " + number(u.scale);
        if (u.offset != 0.0) s += " + " + number(u.offset);
        s += " ";
    }
    return s + std::string(u.name);
}

template <class F>
using element_of_t = typename F::element_type;

// Values a field's element takes: "20..255 ms", "one of a, b", "a number", ...
template <class F>
std::string valid_of(const F& f) {
    using E = element_of_t<F>;
    if constexpr (std::is_enum_v<E>) {
        std::string s = "one of ";
        bool first = true;
        for (const auto& e : robowire::enum_table_v<E>) {
            if (!first) s += ", ";
            s.append(e.name);
            first = false;
        }
        return s;
    } else if constexpr (std::is_same_v<E, bool>) {
        return "true or false";
    } else if constexpr (F::kind == wire_kind::f32le) {
        return "a number";
    } else if constexpr (F::kind == wire_kind::text) {
        return "text of up to " + plural(E::capacity(), "byte", "bytes");
    } else if constexpr (F::kind == wire_kind::tail) {
        return "hex bytes, up to " + std::to_string(E::capacity());
    } else if constexpr (F::kind == wire_kind::record) {
        return "a record";
    } else {
        std::string s = std::to_string(f.valid.min) + ".." + std::to_string(f.valid.max);
        if (!f.unit.name.empty()) s += " (" + unit_text(f.unit) + ")";
        return s;
    }
}

// Values one field takes in encode's flattened list (records: all their fields, arrays: every element).
template <class M>
constexpr std::size_t flat_count();
template <class F>
constexpr std::size_t flat_count_of() {
    if constexpr (F::kind == wire_kind::record) return F::count * flat_count<element_of_t<F>>();
    else if constexpr (F::kind == wire_kind::text || F::kind == wire_kind::tail) return 1;
    else return F::count;
}
template <class M>
constexpr std::size_t flat_count() {
    std::size_t n = 0;
    robowire::for_each_field<M>([&](const auto& f) { n += flat_count_of<std::remove_cvref_t<decltype(f)>>(); });
    return n;
}
// "type, velocity, absolute_position, position"
template <class M>
std::string flat_names(const std::string& prefix = {}) {
    std::string s;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (!s.empty()) s += ", ";
        const std::string name =
            prefix + std::string(f.name) + (F::is_array ? "[" + std::to_string(F::count) + "]" : "");
        if constexpr (F::kind == wire_kind::record) s += name + " (" + flat_names<element_of_t<F>>() + ")";
        else s += name;
    });
    return s;
}

// ---------------------------------------------------------------- the field at a byte
struct location {
    std::string path;       // "pu_motors[1].position"
    std::string valid;      // "-180..179 (deg)"
    std::size_t start = 0;  // the element's first byte (relative to the message)
    wire_kind kind = wire_kind::u8;
    bool is_enum = false;
    unsigned lo = 0, width = 8;  // bits fields
};
template <class M>
std::optional<location> locate(std::size_t offset) {
    std::optional<location> found;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (found || offset < f.offset) return;
        if (F::kind != wire_kind::tail && offset >= f.end()) return;
        std::string path(f.name);
        std::size_t inner = offset - f.offset;
        if constexpr (F::is_array) {
            path += "[" + std::to_string(inner / F::element_size) + "]";
            inner %= F::element_size;
        }
        const std::size_t start = offset - inner;
        if constexpr (F::kind == wire_kind::record) {
            if (auto sub = locate<element_of_t<F>>(inner)) {
                found = *sub;
                found->path = path + "." + sub->path;
                found->start += start;
            } else {
                found = location{path, {}, start, F::kind};
            }
        } else {
            found = location{path, valid_of(f), start, F::kind, F::is_enum};
            if constexpr (F::kind == wire_kind::bits) {
                found->lo = F::wire_type::lo;
                found->width = F::wire_type::width;
            }
        }
    });
    return found;
}
// The raw value of the field at `loc` in `in`, as an error shows it: integers in
// decimal, signed ones signed, with their bytes ("-128 (0x80)", "300 (0x2C 0x01)");
// a bits field's value with its byte; enum codes and other bytes in hex.
inline std::string raw_value_text(const location& loc, std::span<const std::uint8_t> in, std::size_t offset) {
    if (offset >= in.size()) return {};
    std::size_t size = 0;
    bool is_signed = false;
    switch (loc.kind) {
    case wire_kind::i8: is_signed = true; [[fallthrough]];
    case wire_kind::u8:
    case wire_kind::bits: size = 1; break;
    case wire_kind::i16le: is_signed = true; [[fallthrough]];
    case wire_kind::u16le: size = 2; break;
    case wire_kind::i32le: is_signed = true; [[fallthrough]];
    case wire_kind::u32le: size = 4; break;
    default: break;
    }
    if (loc.is_enum || size == 0 || loc.start != offset || offset + size > in.size()) return hex2(in[offset]);
    std::uint64_t u = 0;
    for (std::size_t k = 0; k < size; ++k) u |= std::uint64_t{in[offset + k]} << (8 * k);
    const auto bytes = in.subspan(offset, size);
    if (loc.kind == wire_kind::bits)
        return std::to_string((u >> loc.lo) & ((1u << loc.width) - 1u)) + " (byte " + hex2(in[offset]) + ")";
    std::string v;
    if (is_signed) {
        const std::uint64_t sign = std::uint64_t{1} << (8 * size - 1);
        v = std::to_string(static_cast<std::int64_t>(u ^ sign) - static_cast<std::int64_t>(sign));
    } else {
        v = std::to_string(u);
    }
    std::string h;
    for (const std::uint8_t b : bytes) h += (h.empty() ? "" : " ") + hex2(b);
    return v + " (" + h + ")";
}

// robowire::describe_error's line for error e of message M ("maneuver.pitch:
// value out of range (valid -100..100 %) at byte 7"): the text C++ and
// Python give for the same error.
template <class M>
std::string core_line(const robowire::error& e) {
    char buf[160];
    return std::string(robowire::describe_error<M>(e, buf));
}
// A decode error of variant V: `line` (the protocol's describe_error line for
// it), and a hint with what the line leaves out: the value at the offset
// ("period_ms at byte 1 is 10 (0x0A)", an enum's codes too) or the length
// given ("2 bytes given").
template <class V>
outcome decode_failure(std::string_view line, std::span<const std::uint8_t> in, const robowire::error& e) {
    outcome o;
    o.status = exit_bad_input;
    o.error = line;
    const bool length = e.code == errc::too_short || e.code == errc::too_long || e.code == errc::bad_length;
    if (length) {
        o.hints.push_back(plural(in.size(), "byte", "bytes") + " given");
        return o;
    }
    if (e.offset >= in.size() || e.code == errc::unknown_message) return o;
    bool done = false;
    for_each_alternative<V>([&](auto t) {
        using M = typename decltype(t)::type;
        if (done || !robowire::matches_fixed_bytes<M>(in)) return;
        if (const auto loc = locate<M>(e.offset)) {
            done = true;
            o.hints.push_back(loc->path + " at byte " + std::to_string(e.offset) + " is " +
                              raw_value_text(*loc, in, e.offset) +
                              (loc->is_enum && !loc->valid.empty() ? ", valid " + loc->valid : std::string()));
        }
    });
    return o;
}

// ---------------------------------------------------------------- list
template <class M>
std::string key_bytes() {
    std::string s;
    for (const auto& b : robowire::table_v<M>.fixed) {
        if (b.code != errc::bad_command && b.code != errc::bad_device) continue;
        if (!s.empty()) s += ' ';
        s += hex_of(std::span<const std::uint8_t>(&b.value, 1));
    }
    return s;
}
template <class M>
void list_fields(std::string& out, std::size_t base, std::size_t stride_note_base, const std::string& prefix,
                 std::string_view indent) {
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        std::string type(robowire::to_string(F::kind));
        if constexpr (F::kind == wire_kind::bits) {
            type += "[" + std::to_string(F::wire_type::lo) + ".." +
                    std::to_string(F::wire_type::lo + F::wire_type::width - 1) + "]";
        }
        if (F::is_enum) type += " enum";
        if (F::is_array) type += " x" + std::to_string(F::count);
        if (F::is_optional) type += " optional";
        std::string at = "@" + std::to_string(base + f.offset);
        if (stride_note_base) at += "+" + std::to_string(stride_note_base) + "i";
        std::string name = prefix + std::string(f.name) + (F::is_array ? "[i]" : "");
        char line[256];
        if constexpr (F::kind == wire_kind::record) {
            using R = element_of_t<F>;
            const std::string what = F::is_array ? std::to_string(F::count) + " x " + std::to_string(flat_count<R>()) +
                                                       " = " + plural(flat_count_of<F>(), "value", "values")
                                                 : plural(flat_count_of<F>(), "value", "values");
            std::snprintf(line, sizeof line, "%.*s%-28s %-9s %-22s encode: %s=%s in this order: %s\n",
                          static_cast<int>(indent.size()), indent.data(), name.c_str(), at.c_str(), type.c_str(),
                          std::string(f.name).c_str(), what.c_str(), flat_names<R>().c_str());
            out += line;
            list_fields<R>(out, base + f.offset, F::is_array ? F::element_size : 0, name + ".",
                           std::string(indent) + "  ");
        } else {
            std::string valid = valid_of(f);
            std::string bits;
            robowire::for_each_flag_bit<M>(f.name, [&](const robowire::flag_bit& b) {
                if (!bits.empty()) bits += ", ";
                bits += "bit " + std::to_string(b.lo);
                if (b.width > 1) bits += "-" + std::to_string(b.lo + b.width - 1);
                bits += " " + std::string(b.name);
                if (b.width > 1) {
                    std::string vals;
                    for (std::size_t v = 0; v < robowire::flag_value_count(b); ++v)
                        vals += (vals.empty() ? "" : "/") + std::string(b.values[v]);
                    bits += " (" + vals + ")";
                }
            });
            if (!bits.empty()) valid += "; bits: " + bits;
            std::snprintf(line, sizeof line, "%.*s%-28s %-9s %-22s %s\n", static_cast<int>(indent.size()),
                          indent.data(), name.c_str(), at.c_str(), type.c_str(), valid.c_str());
            out += line;
        }
    });
}
template <class M>
void list_message(std::string& out, bool fields) {
    constexpr auto& t = robowire::table_v<M>;
    char line[160];
    std::snprintf(line, sizeof line, "  %-26.*s %-8s %s\n", static_cast<int>(t.name.size()), t.name.data(),
                  key_bytes<M>().c_str(), valid_lengths<M>().c_str());
    out += line;
    if (fields) list_fields<M>(out, 0, 0, "", "      ");
}
template <class V>
void list_variant(std::string& out, bool fields) {
    for_each_alternative<V>([&](auto t) { list_message<typename decltype(t)::type>(out, fields); });
}

// ---------------------------------------------------------------- encode
inline std::vector<std::string> split_commas(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t c = s.find(',', start);
        out.push_back(s.substr(start, c == std::string::npos ? std::string::npos : c - start));
        if (c == std::string::npos) return out;
        start = c + 1;
    }
}

// A field's path without element indexes: "colors[1].g" -> "colors.g".
inline std::string without_indexes(std::string_view path) {
    std::string out;
    bool in_index = false;
    for (const char c : path) {
        if (c == '[') in_index = true;
        else if (c == ']') in_index = false;
        else if (!in_index) out += c;
    }
    return out;
}

struct value_reader {
    std::vector<std::string> tokens;
    std::size_t pos = 0;
    std::string error;
    errc code = errc::ok;  // a library error (value_out_of_range, ...) at `byte`: encode_as gives its line
    std::size_t byte = 0;
    std::string path;  // the value's field ("colors[1].g")
};

inline std::optional<std::int64_t> parse_integer(const std::string& t) {
    std::size_t i = 0;
    bool neg = false;
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) neg = t[i++] == '-';
    int base = 10;
    if (t.size() - i > 2 && t[i] == '0' && (t[i + 1] == 'x' || t[i + 1] == 'X')) {
        base = 16;
        i += 2;
    }
    if (i >= t.size()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const unsigned long long u = std::strtoull(t.c_str() + i, &end, base);
    if (*end || errno || t[i] == '-' || t[i] == '+' ||
        u > static_cast<unsigned long long>(std::numeric_limits<std::int64_t>::max()))
        return std::nullopt;
    const auto v = static_cast<std::int64_t>(u);
    return neg ? -v : v;
}

template <class M>
bool fill(M& m, value_reader& r, std::size_t base, const std::string& prefix);

template <class F, class E>
bool parse_element(const F& f, E& v, value_reader& r, std::size_t byte, const std::string& path) {
    if constexpr (F::kind == wire_kind::record) {
        return fill(v, r, byte, path + ".");
    } else {
        const std::string& t = r.tokens[r.pos++];
        // the value given, and what the field takes; `code`: the library's error for it
        auto bad = [&](std::string_view why, errc code = errc::ok) {
            const std::string given = path + "=" + shorten(t);
            if (code != errc::ok) r.error = given + " given, valid " + valid_of(f);  // a hint under the library's line
            else
                r.error =
                    std::string(why) + " at byte " + std::to_string(byte) + ": " + given + ", valid " + valid_of(f);
            r.code = code;
            r.byte = byte;
            r.path = path;
            return false;
        };
        if constexpr (std::is_same_v<E, bool>) {
            if (t == "true" || t == "1") v = true;
            else if (t == "false" || t == "0") v = false;
            else return bad("not true or false");
        } else if constexpr (std::is_enum_v<E>) {
            if (const auto e = robowire::enum_from_name<E>(t)) {
                v = *e;
            } else {
                const auto n = parse_integer(t);
                if (!n || *n < 0 || *n > 255 || !robowire::is_valid_enum(static_cast<E>(*n)))
                    return bad("unknown name", errc::invalid_enum);
                v = static_cast<E>(*n);
            }
        } else if constexpr (std::is_same_v<E, float>) {
            char* end = nullptr;
            const float x = std::strtof(t.c_str(), &end);
            if (t.empty() || *end || !std::isfinite(x)) return bad("not a number");
            v = x;
        } else if constexpr (std::is_integral_v<E>) {
            const auto n = parse_integer(t);
            if (!n) return bad("not an integer");
            if (*n < f.valid.min || *n > f.valid.max) return bad("", errc::value_out_of_range);
            v = static_cast<E>(*n);
        } else if constexpr (requires { v.view(); }) {
            const auto s = E::make(t);
            if (!s) return bad("", errc::value_out_of_range);
            v = *s;
        } else {
            std::string err;
            const auto b = parse_hex_text(t, err);
            if (!b) return bad(err);
            const auto x = E::from(*b);
            if (!x) return bad("", errc::capacity_exceeded);
            v = *x;
        }
        return true;
    }
}

template <class F, class T>
bool fill_field(const F& f, T& value, value_reader& r, std::size_t base, const std::string& path) {
    if constexpr (F::is_array) {
        for (std::size_t k = 0; k < F::count; ++k)
            if (!parse_element(f, value[k], r, base + f.offset + k * F::element_size,
                               path + "[" + std::to_string(k) + "]"))
                return false;
        return true;
    } else {
        return parse_element(f, value, r, base + f.offset, path);
    }
}

template <class M>
bool fill(M& m, value_reader& r, std::size_t base, const std::string& prefix) {
    bool ok = true;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (!ok) return;
        auto& member = m.*(f.member);
        if constexpr (F::is_optional) ok = fill_field(f, member.emplace(), r, base, prefix + std::string(f.name));
        else ok = fill_field(f, member, r, base, prefix + std::string(f.name));
    });
    return ok;
}

// Builds M from name=value pairs (names already checked against M's fields, no repeats).
template <class M>
outcome encode_as(const std::vector<std::pair<std::string, std::string>>& values) {
    outcome o;
    M m{};
    const std::string mname(robowire::table_v<M>.name);
    // names first: unknown and repeated names are usage errors
    for (std::size_t i = 0; i < values.size(); ++i) {
        bool known = false;
        robowire::for_each_field<M>([&](const auto& f) { known = known || f.name == values[i].first; });
        if (!known) {
            std::string names;
            robowire::for_each_field<M>(
                [&](const auto& f) { names += (names.empty() ? "" : ", ") + std::string(f.name); });
            o.status = exit_usage;
            o.error = "unknown field " + shorten(values[i].first) + " of " + mname +
                      " (fields: " + (names.empty() ? "none" : names) + ")";
            return o;
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (values[j].first == values[i].first) {
                o.status = exit_usage;
                o.error = "field " + values[i].first + " given twice (" + values[j].first + "=" +
                          shorten(values[j].second) + ", " + values[i].first + "=" + shorten(values[i].second) + ")";
                return o;
            }
        }
    }
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (o.status) return;
        const std::pair<std::string, std::string>* given = nullptr;
        for (const auto& v : values)
            if (v.first == f.name) given = &v;
        if (!given) return;
        value_reader r;
        if constexpr (F::kind == wire_kind::text || F::kind == wire_kind::tail) r.tokens = {given->second};
        else r.tokens = split_commas(given->second);
        constexpr std::size_t want = flat_count_of<F>();
        if (r.tokens.size() != want) {
            o.status = exit_bad_input;
            o.error = std::string(f.name) + ": " + plural(r.tokens.size(), "value", "values") + " given, " +
                      std::to_string(want) + " expected";
            if constexpr (F::kind == wire_kind::record)
                o.error += " (" + (F::is_array ? std::to_string(F::count) + " x " : std::string()) + "[" +
                           flat_names<element_of_t<F>>() + "])";
            else if (F::is_array) o.error += " (" + std::string(f.name) + "=v1,...,v" + std::to_string(want) + ")";
            return;
        }
        auto& member = m.*(f.member);
        bool ok;
        if constexpr (F::is_optional) ok = fill_field(f, member.emplace(), r, 0, std::string(f.name));
        else ok = fill_field(f, member, r, 0, std::string(f.name));
        if (!ok && r.code != errc::ok) {  // the library's line, the value given as a hint
            o.status = exit_bad_input;
            o.error = core_line<M>(robowire::error{r.code, static_cast<std::uint16_t>(r.byte)});
            o.hints.push_back(r.error);
            o.code = std::string(robowire::name_of(r.code));
            o.offset = r.byte;
            o.field = without_indexes(r.path);

        } else if (!ok) {
            o.status = exit_bad_input;
            o.error = r.error;
        }
    });
    if (o.status) return o;
    const auto w = robowire::encode(m);
    if (!w) {
        o.status = exit_bad_input;
        o.error = core_line<M>(w.error());
        o.code = std::string(robowire::name_of(w.error().code));
        o.offset = w.error().offset;
        if (const auto f = robowire::field_at<M>(w.error())) o.field = std::string(f.name);
        if (const auto f = robowire::field_at<M>(w.error()); f && w.error().code == errc::missing_field)
            o.hints.push_back("give " + std::string(f.name) + " too");
        return o;
    }
    o.message = mname;
    o.bytes.assign(w->begin(), w->end());
    return o;
}

// Encodes message `name` if it is one of V's alternatives.
template <class V>
std::optional<outcome> encode_in(std::string_view name,
                                 const std::vector<std::pair<std::string, std::string>>& values) {
    std::optional<outcome> o;
    for_each_alternative<V>([&](auto t) {
        using M = typename decltype(t)::type;
        if (!o && robowire::table_v<M>.name == name) o = encode_as<M>(values);
    });
    return o;
}

inline outcome failure(int status, std::string error) {
    outcome o;
    o.status = status;
    o.error = std::move(error);
    return o;
}

}  // namespace robowire::tools
