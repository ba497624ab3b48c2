// A decoded message written straight into an output buffer, in each format
// (text rows, one JSON object, one CSV row and its header), from the
// library's field tables: no intermediate tree, no JSON document.
// Included by the protocol modules only (buwizz3.cpp, navbot.cpp, osp.cpp).
#pragma once

#include <robowire/core/fields.hpp>
#include <robowire/core/flag_bits.hpp>
#include <robowire/robowire.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <type_traits>
#include <variant>

#include "text.hpp"
#include "tools.hpp"

namespace robowire::tools::emit {

template <class F>
using element_t = typename F::element_type;

// ---------------------------------------------------------------- numbers
inline void put_int(buffer& o, std::int64_t v) {
    if (v >= 0 && v < 100) {  // most values: one or two digits without std::to_chars
        if (v < 10) return void(o += static_cast<char>('0' + v));
        const char b[2] = {static_cast<char>('0' + v / 10), static_cast<char>('0' + v % 10)};
        o.append(b, 2);
        return;
    }
    char b[24];
    o.append(b, std::to_chars(b, b + sizeof b, v).ptr);
}
// ---- printf's %.<p>g, fast: from the shortest round-trip digits of the
// double (std::to_chars, Ryu), rounded in decimal. When the first digit
// dropped is 4 or 5 the shortest digits are too close to halfway to decide
// and std::to_chars with the precision (exact, about ten times slower) does it.
struct decimal {
    char d[24];
    int n = 0;  // digits d[0..n): d[0].d[1]d[2]... x 10^exp
    int exp = 0;
    bool neg = false;
};
inline decimal shortest_decimal(double v) {
    char b[48];
    const char* e = std::to_chars(b, b + sizeof b, v, std::chars_format::scientific).ptr;
    decimal x;
    const char* p = b;
    if (*p == '-') x.neg = true, ++p;
    for (; p < e && *p != 'e'; ++p)
        if (*p != '.') x.d[x.n++] = *p;
    ++p;  // 'e'
    const bool neg_exp = *p == '-';
    ++p;
    for (; p < e; ++p) x.exp = x.exp * 10 + (*p - '0');
    if (neg_exp) x.exp = -x.exp;
    return x;
}
// u's decimal digits into b, lowest first (at most 20); returns how many.
inline int reversed_digits(std::uint64_t u, char* b) {
    int n = 0;
    do {
        b[n++] = static_cast<char>('0' + u % 10);
        u /= 10;
    } while (u);
    return n;
}
// The digits of v when a decimal of at most 15 significant digits with up to
// 7 decimals reads back as v (most physical values: raw x 0.015): then it is
// what %.15g writes, found with a few multiplications instead of Ryu.
inline bool short_decimal(double v, decimal& x) {
    static constexpr double pow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7};
    for (int k = 0; k < 8; ++k) {
        const double scaled = v * pow10[k];
        if (!(std::fabs(scaled) < 1e15)) return false;
        const double r = std::nearbyint(scaled);
        if (r / pow10[k] != v) continue;
        auto m = static_cast<std::int64_t>(r);
        x.neg = m < 0 || (m == 0 && std::signbit(v));
        const std::uint64_t u = m < 0 ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
        char b[24];
        const int n = reversed_digits(u, b);
        x.n = n;
        for (int i = 0; i < n; ++i) x.d[i] = b[n - 1 - i];
        x.exp = n - 1 - k;
        if (m == 0) x.exp = 0;
        while (x.n > 1 && x.d[x.n - 1] == '0') --x.n;
        return true;
    }
    return false;
}

// Keeps x's first p digits (p < x.n), one up in the last when `up`, and drops trailing zeros.
inline void cut_digits(decimal& x, int p, bool up) {
    x.n = p;
    if (up) {
        int i = p - 1;
        while (i >= 0 && x.d[i] == '9') x.d[i--] = '0';
        if (i < 0) {
            x.d[0] = '1';
            ++x.exp;
        } else {
            ++x.d[i];
        }
    }
    while (x.n > 1 && x.d[x.n - 1] == '0') --x.n;
}
// Rounds x to p significant digits and drops trailing zeros; false when the decimal digits cannot decide.
inline bool round_digits(decimal& x, int p) {
    if (x.n > p) {
        const char first = x.d[p];
        if (first == '4' || first == '5') return false;
        cut_digits(x, p, first > '5');
        return true;
    }
    while (x.n > 1 && x.d[x.n - 1] == '0') --x.n;
    return true;
}
// x (rounded to at most p digits) as printf's %.<p>g writes it.
inline void put_g(buffer& o, const decimal& x, int p) {
    if (x.neg) o += '-';
    if (x.exp < -4 || x.exp >= p) {
        o += x.d[0];
        if (x.n > 1) o.append(".").append(x.d + 1, static_cast<std::size_t>(x.n - 1));
        char b[8];
        int e = x.exp < 0 ? -x.exp : x.exp;
        int k = 0;
        do {
            b[k++] = static_cast<char>('0' + e % 10);
            e /= 10;
        } while (e);
        if (k < 2) b[k++] = '0';
        o += 'e';
        o += x.exp < 0 ? '-' : '+';
        while (k) o += b[--k];
    } else if (x.exp >= 0) {
        const auto whole = static_cast<std::size_t>(x.exp + 1);
        const auto n = static_cast<std::size_t>(x.n);
        o.append(x.d, std::min(n, whole));
        if (n < whole) o.append(whole - n, '0');
        else if (n > whole) o.append(".").append(x.d + whole, n - whole);
    } else {
        o.append("0.").append(static_cast<std::size_t>(-x.exp - 1), '0').append(x.d, static_cast<std::size_t>(x.n));
    }
}
inline void put_g_exact(buffer& o, double v, int p) {
    char b[48];
    o.append(b, std::to_chars(b, b + sizeof b, v, std::chars_format::general, p).ptr);
}
// printf's %.<p>g of v.
inline void put_g(buffer& o, double v, int p) {
    // whole numbers (most physical values of scale 1) as integers
    if (std::fabs(v) < 1e15 && v == std::trunc(v) && !(v == 0.0 && std::signbit(v)) && (p >= 15 || std::fabs(v) < 1e6))
        return put_int(o, static_cast<std::int64_t>(v));
    if (!std::isnormal(v) && v != 0.0) return put_g_exact(o, v, p);  // subnormals have fewer digits
    decimal x;
    if (!short_decimal(v, x)) x = shortest_decimal(v);
    if (round_digits(x, p)) put_g(o, x, p);
    else put_g_exact(o, v, p);
}
// %.<p2>g of v rounded to 15 significant digits first (tidy(v): 13.000000000000002 -> 13).
inline void put_g_tidy(buffer& o, double v, int p2) {
    if (std::fabs(v) < 1e6 && v == std::trunc(v) && !(v == 0.0 && std::signbit(v)))
        return put_int(o, static_cast<std::int64_t>(v));
    if (std::isnormal(v) || v == 0.0) {
        decimal x;
        if (!short_decimal(v, x)) x = shortest_decimal(v);
        if (round_digits(x, 15) && round_digits(x, p2)) return put_g(o, x, p2);
    }
    char b[48];
    char* e = std::to_chars(b, b + sizeof b, v, std::chars_format::general, 15).ptr;
    double t = v;
    std::from_chars(b, e, t);
    put_g_exact(o, t, p2);
}
// printf's %.6g (text output)
inline void put_g6(buffer& o, double v) { put_g(o, v, 6); }
// ---- physical values (raw x scale + offset) from integers: when the scale
// is a short decimal m / 10^k (|m| < 2^31, k <= 9, the double nearest to it)
// and the offset 0, the decimal raw x m / 10^k of at most 15 digits is what
// rounding the double product to 15 significant digits gives (the product is
// within 2.3e-16 of it, relative; half a unit of its 15th digit is at least
// 5e-16): %.15g writes it, and tidy() reads it back.
inline bool scale_decimal(double scale, std::int64_t& m, int& k) {
    static constexpr double pow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
    for (k = 0; k < 10; ++k) {
        const double t = scale * pow10[k];
        if (!(std::fabs(t) < 2147483648.0)) return false;
        m = static_cast<std::int64_t>(t < 0 ? t - 0.5 : t + 0.5);
        if (static_cast<double>(m) / pow10[k] == scale) return m != 0;
    }
    return false;
}
// raw x scale + offset as that exact decimal; false when it is not one (or zero: its sign is the double's).
inline bool physical_decimal(std::int64_t raw, double scale, double offset, decimal& x) {
    std::int64_t m;
    int k;
    if (offset != 0.0 || raw == 0 || raw <= -(std::int64_t{1} << 32) || raw >= (std::int64_t{1} << 32) ||
        !scale_decimal(scale, m, k))
        return false;
    const std::int64_t p = raw * m;
    const std::uint64_t u = p < 0 ? 0 - static_cast<std::uint64_t>(p) : static_cast<std::uint64_t>(p);
    if (u >= 1'000'000'000'000'000u) return false;
    char b[24];
    const int n = reversed_digits(u, b);
    x.neg = p < 0;
    x.exp = n - 1 - k;
    int lo = 0;
    while (b[lo] == '0') ++lo;  // trailing zeros
    x.n = n - lo;
    for (int i = 0; i < x.n; ++i) x.d[i] = b[n - 1 - i];
    return true;
}
// Rounds the exact decimal x to p significant digits (half away from zero, as
// printf rounds any double near x); false on an exact tie, which the double's
// side of x decides.
inline bool round_exact(decimal& x, int p) {
    if (x.n <= p) return true;
    if (x.d[p] == '5' && x.n == p + 1) return false;
    cut_digits(x, p, x.d[p] >= '5');
    return true;
}
// The text's physical value: %.<p>g of tidy(raw x scale + offset), as put_g_tidy writes it.
inline void put_physical_g(buffer& o, std::int64_t raw, double scale, double offset, int p) {
    decimal x;
    if (physical_decimal(raw, scale, offset, x) && round_exact(x, p)) return put_g(o, x, p);
    put_g_tidy(o, static_cast<double>(raw) * scale + offset, p);
}
// x as std::to_chars(double) writes its shortest digits: fixed, or scientific when that is shorter.
inline void put_to_chars_form(buffer& o, const decimal& x) {
    if (x.neg) o += '-';
    const int n = x.n, e = x.exp;
    const int fixed = e >= 0 ? std::max(n, e + 1) + (n > e + 1 ? 1 : 0) : 1 - e + n;
    const int ae = e < 0 ? -e : e;
    const int scientific = n + (n > 1 ? 1 : 0) + 2 + (ae >= 100 ? 3 : 2);
    if (scientific < fixed) {
        o += x.d[0];
        if (n > 1) o.append(".").append(x.d + 1, static_cast<std::size_t>(n - 1));
        o += 'e';
        o += e < 0 ? '-' : '+';
        char b[4];
        int k = 0, a = ae;
        do {
            b[k++] = static_cast<char>('0' + a % 10);
            a /= 10;
        } while (a);
        if (k < 2) b[k++] = '0';
        while (k) o += b[--k];
    } else if (e >= 0) {
        const auto whole = static_cast<std::size_t>(e + 1);
        const auto un = static_cast<std::size_t>(n);
        o.append(x.d, std::min(un, whole));
        if (un < whole) o.append(whole - un, '0');
        else if (un > whole) o.append(".").append(x.d + whole, un - whole);
    } else {
        o.append("0.").append(static_cast<std::size_t>(-e - 1), '0').append(x.d, static_cast<std::size_t>(n));
    }
}
// The shortest text that reads back as v, as std::to_chars(double) writes it
// (a decimal of few digits without Ryu: short_decimal).
inline void put_shortest17(buffer& o, double v) {
    decimal x;
    if (std::isnormal(v) && short_decimal(v, x)) return put_to_chars_form(o, x);
    char b[48];
    o.append(b, std::to_chars(b, b + sizeof b, v).ptr);
}
// The shortest text that reads back as v (CSV); precision 15: rounded to 15 significant digits first.
inline void put_shortest(buffer& o, double v, int precision = 17) {
    if (precision == 15) return put_g(o, v, 15);
    put_shortest17(o, v);
}
// A JSON number as nlohmann/json writes a double, ".0" after an integer. precision 15:
// the shortest text of v rounded to 15 significant digits (what tidy(v) writes).
inline void put_json_double(buffer& o, double v, int precision = 17) {
    if (!std::isfinite(v)) {
        o += "null";
        return;
    }
    if (precision == 15 && std::fabs(v) < 1e15 && v == std::trunc(v) && !(v == 0.0 && std::signbit(v))) {
        put_int(o, static_cast<std::int64_t>(v));  // a whole number (most physical values of scale 1)
        o += ".0";
        return;
    }
    const std::size_t start = o.size();
    if (precision == 15) put_g(o, v, 15);
    else put_shortest17(o, v);
    const std::string_view w = o.view().substr(start);
    for (const char c : w)
        if (c == '.' || c == 'e') return;
    o += ".0";
}
// JSON's physical value: put_json_double(raw x scale + offset, 15).
inline void put_physical_json(buffer& o, std::int64_t raw, double scale, double offset) {
    if (scale == 1.0 && offset == 0.0 && raw > -1'000'000'000'000'000 && raw < 1'000'000'000'000'000) {
        put_int(o, raw);  // raw x 1 + 0: a whole number, written exactly (not -0: 0 x 1 + 0 is +0)
        o += ".0";
        return;
    }
    decimal x;
    if (!physical_decimal(raw, scale, offset, x))
        return put_json_double(o, static_cast<double>(raw) * scale + offset, 15);
    put_g(o, x, 15);
    if (x.exp >= -4 && x.exp < 15 && x.n <= x.exp + 1) o += ".0";  // a whole number
}
// Rounded to 15 significant digits (13.000000000000002 -> 13): physical values.
inline double tidy(double v) {
    char b[48];
    char* e = std::to_chars(b, b + sizeof b, v, std::chars_format::general, 15).ptr;
    double r = v;
    std::from_chars(b, e, r);
    return r;
}

// Rounded as the tool prints it (robowire::physical_of, reflect.hpp: raw * scale + offset).
template <class F>
double physical(const F& f, std::int64_t raw) {
    return tidy(physical_of(f, raw));
}

// Leaves with a physical value when their field has a unit: integers.
template <class F>
constexpr bool has_physical() {
    return robowire::value_kind_v<F> == robowire::value_kind::integer;
}
// Long byte arrays without meaning per byte (a payload): one hex value.
template <class F>
bool is_hex_array(const F& f) {
    if constexpr (F::is_array && F::kind == wire_kind::u8 && std::is_same_v<element_t<F>, std::uint8_t> &&
                  F::count >= 8)
        return f.unit.name.empty();
    else return false;
}
// Its bytes (empty for any other field).
template <class F, class V>
std::span<const std::uint8_t> hex_bytes(const V& v) {
    if constexpr (F::is_array && std::is_same_v<element_t<F>, std::uint8_t>) return {v.data(), v.size()};
    else return {};
}

// "battery_voltage_raw" -> "battery_voltage", "centivolts" -> "centivolts_physical"
template <class Out>
void put_physical_key(Out& o, std::string_view key) {
    constexpr std::string_view raw = "_raw";
    if (key.size() > raw.size() && key.substr(key.size() - raw.size()) == raw) o.append(key.substr(0, key.size() - 4));
    else o.append(key).append("_physical");
}

// No unit name of M's fields needs JSON escaping (decided at compile time).
template <class M>
inline constexpr bool plain_units_v = [] {
    bool plain = true;
    robowire::for_each_field<M>([&](const auto& f) {
        for (const char c : f.unit.name) {
            const auto u = static_cast<unsigned char>(c);
            if (u < 0x20 || u >= 0x7F || c == '"' || c == '\\') plain = false;
        }
    });
    return plain;
}();

// The NAVBOT JSON payload as text (up to its first zero byte), for frames of the JSON command.
template <class M>
bool payload_text(const M& m, std::string_view field, std::string& text) {
    if constexpr (std::is_same_v<M, robowire::navbot::frame>) {
        if (field != "payload" || m.command != robowire::navbot::command::json) return false;
        text.clear();
        for (const std::uint8_t b : m.payload) {
            if (b == 0) break;
            text += static_cast<char>(b);
        }
        return true;
    } else {
        (void)m, (void)field, (void)text;
        return false;
    }
}

// ---------------------------------------------------------------- text rows
// A leaf's text: "80 (13 V)", "charging (0x03)", "109 = error | charging", "\"name\"".
template <class M, class F, class E>
void text_value(buffer& o, const F& f, const E& v) {
    if constexpr (std::is_same_v<E, bool>) {
        o += v ? "true" : "false";
    } else if constexpr (std::is_enum_v<E>) {
        o.append(robowire::enum_name(v)).append(" (").append(hex2(static_cast<unsigned>(v))).append(")");
    } else if constexpr (std::is_same_v<E, float>) {
        put_g6(o, static_cast<double>(v));
    } else if constexpr (std::is_integral_v<E>) {
        const auto i = static_cast<std::int64_t>(v);
        put_int(o, i);
        if (!f.unit.name.empty()) {
            if (f.unit.scale != 1.0 || f.unit.offset != 0.0) {
                o += " (";
                put_physical_g(o, i, f.unit.scale, f.unit.offset, 6);
                o.append(" ").append(f.unit.name).append(")");
            } else {
                o.append(" ").append(f.unit.name);
            }
        }
        if constexpr (robowire::has_flag_bits<M>) {
            const auto raw = static_cast<unsigned>(i);
            unsigned known = 0;
            bool any_bits = false, any_shown = false;
            std::size_t mark = o.size();
            robowire::for_each_flag_bit<M>(f.name, [&](const robowire::flag_bit& b) {
                if (!any_bits) {
                    o += " = ";
                    mark = o.size();
                    any_bits = true;
                }
                known |= robowire::flag_mask(b);
                const unsigned value = robowire::flag_value(b, raw);
                if (b.width == 1 && !value) return;
                if (any_shown) o += " | ";
                any_shown = true;
                o.append(b.name);
                if (b.width > 1) {
                    o += ' ';
                    if (const auto name = robowire::flag_value_name(b, value); !name.empty()) o.append(name);
                    else put_int(o, value);
                }
            });
            if (any_bits) {
                for (unsigned bit = 0; bit < 8; ++bit) {
                    if (!((raw & ~known) & (1u << bit))) continue;
                    o += any_shown ? " | bit" : "bit";
                    any_shown = true;
                    put_int(o, bit);
                }
                if (!any_shown) o.insert(mark, "(none)");
            }
        }
    } else if constexpr (requires { v.view(); }) {
        o.append("\"").append(v.view()).append("\"");
    } else {
        if (v.empty()) o += "(none)";
        else o += hex_of(v.span());
    }
}

// A field path as text rows show it: "pu_motors[1].position" (at most 200 characters).
struct path_buf {
    char s[200];
    std::size_t n = 0;
    bool varies = false;  // a row that depends on the message's values (payload text) was seen
    void push(std::string_view x) {
        const std::size_t k = std::min(x.size(), sizeof s - n);
        std::copy_n(x.data(), k, s + n);
        n += k;
    }
    void push_index(std::size_t i) {
        if (i < 10 && n + 3 <= sizeof s) {
            s[n] = '[';
            s[n + 1] = static_cast<char>('0' + i);
            s[n + 2] = ']';
            n += 3;
            return;
        }
        char b[24];
        b[0] = '[';
        char* e = std::to_chars(b + 1, b + sizeof b - 1, i).ptr;
        *e++ = ']';
        push(std::string_view(b, static_cast<std::size_t>(e - b)));
    }
    std::string_view view() const { return {s, n}; }
};

// Calls row(path, write_value) for each text row of m, in order; write_value(o) appends the row's value.
// Paths false: the path stays empty (rows whose heads are known).
template <bool Paths = true, class M, class Row>
void for_each_row(const M& m, path_buf& p, Row& row) {
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        const std::size_t mark = p.n;
        if constexpr (Paths) {
            if (mark) p.push(".");
            p.push(f.name);
        }
        auto element = [&](const auto& e) {
            if constexpr (F::kind == wire_kind::record) for_each_row<Paths>(e, p, row);
            else row(p.view(), [&](buffer& o) { text_value<M>(o, f, e); });
        };
        auto value = [&](const auto& v) {
            if constexpr (F::is_array) {
                if (is_hex_array(f)) {
                    row(p.view(), [&](buffer& o) { o += hex_of(hex_bytes<F>(v)); });
                } else {
                    for (std::size_t i = 0; i < v.size(); ++i) {
                        const std::size_t at = p.n;
                        if constexpr (Paths) p.push_index(i);
                        element(v[i]);
                        p.n = at;
                    }
                }
            } else {
                element(v);
            }
        };
        const auto& member = m.*(f.member);
        if constexpr (F::is_optional) {
            if (member) value(*member);
            else row(p.view(), [](buffer& o) { o += "(absent)"; });
        } else {
            value(member);
        }
        thread_local std::string text;
        if constexpr (std::is_same_v<M, robowire::navbot::frame>) p.varies = true;
        if (payload_text(m, f.name, text)) {
            const std::size_t at = p.n;
            if constexpr (Paths) p.push(" (text)");
            row(p.view(), [&](buffer& o) { o += text; });
            p.n = at;
        }
        p.n = mark;
    });
}

// One bit per optional block of m, in the order of the rows, set when present (bit: the next bit).
template <class M>
void presence(const M& m, std::uint64_t& present, int& bit) {
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        auto inner = [&](const auto& v) {
            if constexpr (F::kind == wire_kind::record) {
                if constexpr (F::is_array) {
                    for (std::size_t i = 0; i < v.size(); ++i) presence(v[i], present, bit);
                } else {
                    presence(v, present, bit);
                }
            } else {
                (void)v;
            }
        };
        const auto& member = m.*(f.member);
        if constexpr (F::is_optional) {
            if (member) {
                if (bit < 64) present |= std::uint64_t{1} << bit;
                inner(*member);
            }
            ++bit;
        } else {
            inner(member);
        }
    });
}

// "protocol message" then one row per field, then the notes.
template <class M>
void write_text(buffer& o, std::string_view protocol, const M& m, const std::vector<std::string>& notes) {
    o.append(protocol).append(" ").append(robowire::table_v<M>.name).append("\n");
    // The rows' heads ("  path" and the padding to the widest path) depend only
    // on which optional blocks are present: rendered once for each combination
    // (up to 64 optional blocks; a NAVBOT frame's payload text: each message).
    struct heads {
        std::uint64_t present = 0;
        std::string text;             // the heads one after the other
        std::vector<std::size_t> at;  // where each ends in text
    };
    thread_local std::vector<heads> known;
    std::uint64_t present = 0;
    int blocks = 0;
    presence(m, present, blocks);
    const heads* h = nullptr;
    for (const auto& k : known)
        if (blocks <= 64 && k.present == present) h = &k;
    if (h) {
        std::size_t i = 0, from = 0;
        auto write = [&](std::string_view, const auto& value) {
            o.append(h->text.data() + from, h->at[i] - from);
            from = h->at[i++];
            value(o);
            o += '\n';
        };
        path_buf p;
        for_each_row<false>(m, p, write);
    } else {
        std::size_t w = 0;
        path_buf p;
        auto width = [&](std::string_view path, const auto&) { w = std::max(w, path.size()); };
        for_each_row(m, p, width);
        if (!p.varies && blocks <= 64 && known.size() < 64) {
            heads k;
            k.present = present;
            path_buf q;
            auto head = [&](std::string_view path, const auto&) {
                k.text.append("  ").append(path).append(w - path.size() + 2, ' ');
                k.at.push_back(k.text.size());
            };
            for_each_row(m, q, head);
            known.push_back(std::move(k));
        }
        path_buf r;
        auto write = [&](std::string_view path, const auto& value) {
            o.append("  ").append(path).append(w - path.size() + 2, ' ');
            value(o);
            o += '\n';
        };
        for_each_row(m, r, write);
    }
    for (const auto& n : notes) o.append("  note: ").append(n).append("\n");
}

// ---------------------------------------------------------------- JSON
template <class M, class F, class E>
void json_value(buffer& o, const F& f, const E& v);

// A flag field's bits as JSON members: ,"flags_bits":{"error":true,...} (nothing for other fields).
template <class M, class F>
void put_json_bits(buffer& o, const F& f, unsigned raw) {
    if constexpr (robowire::has_flag_bits<M>) {
        bool any = false;
        robowire::for_each_flag_bit<M>(f.name, [&](const robowire::flag_bit& b) {
            o += any ? "," : ",\"";
            if (!any) o.append(f.name).append("_bits\":{");
            any = true;
            const unsigned value_bits = robowire::flag_value(b, raw);
            o.append("\"").append(b.name).append("\":");
            if (b.width == 1) {
                o += value_bits ? "true" : "false";
            } else {
                o += '"';
                if (const auto name = robowire::flag_value_name(b, value_bits); !name.empty()) o.append(name);
                else put_int(o, value_bits);
                o += '"';
            }
        });
        if (any) o += '}';
    } else {
        (void)o, (void)f, (void)raw;
    }
}

template <class M>
void write_json_object(buffer& o, const M& m) {
    o += '{';
    bool first = true;
    auto key = [&](auto&&... parts) {
        if (!first) o += ',';
        first = false;
        o += '"';
        (o.append(parts), ...);
        o += "\":";
    };
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        using E = element_t<F>;
        const auto& member = m.*(f.member);
        auto value = [&](const auto& v) {
            if constexpr (F::is_array) {
                o += '[';
                for (std::size_t i = 0; i < v.size(); ++i) {
                    if (i) o += ',';
                    json_value<M>(o, f, v[i]);
                }
                o += ']';
            } else {
                json_value<M>(o, f, v);
            }
        };
        key(f.name);
        const bool present = [&] {
            if constexpr (F::is_optional) return member.has_value();
            else return true;
        }();
        if (!present) {
            o += "null";
            return;
        }
        const auto& v = [&]() -> const auto& {
            if constexpr (F::is_optional) return *member;
            else return member;
        }
        ();
        value(v);
        if constexpr (has_physical<F>()) {
            if (!f.unit.name.empty()) {
                o += ',';
                o += '"';
                put_physical_key(o, f.name);
                o += "\":{\"value\":";
                if constexpr (F::is_array) {
                    o += '[';
                    for (std::size_t i = 0; i < v.size(); ++i) {
                        if (i) o += ',';
                        put_physical_json(o, static_cast<std::int64_t>(v[i]), f.unit.scale, f.unit.offset);
                    }
                    o += ']';
                } else {
                    put_physical_json(o, static_cast<std::int64_t>(v), f.unit.scale, f.unit.offset);
                }
                if constexpr (plain_units_v<M>) {
                    o.append(",\"unit\":\"").append(f.unit.name).append("\"}");
                } else {
                    o.append(",\"unit\":");
                    put_json_string(o, f.unit.name);
                    o += '}';
                }
            }
            if constexpr (!F::is_array) put_json_bits<M>(o, f, static_cast<unsigned>(v));
        }
        (void)sizeof(E);
        thread_local std::string text;
        if (payload_text(m, f.name, text)) {
            o.append(",\"").append(f.name).append("_text\":");
            put_json_string(o, text);
        }
    });
    o += '}';
}

template <class M, class F, class E>
void json_value(buffer& o, const F& f, const E& v) {
    (void)f;
    if constexpr (F::kind == wire_kind::record) {
        write_json_object(o, v);
    } else if constexpr (std::is_same_v<E, bool>) {
        o += v ? "true" : "false";
    } else if constexpr (std::is_enum_v<E>) {
        put_json_string(o, robowire::enum_name(v));
    } else if constexpr (std::is_same_v<E, float>) {
        put_json_double(o, static_cast<double>(v));
    } else if constexpr (std::is_integral_v<E>) {
        put_int(o, static_cast<std::int64_t>(v));
    } else if constexpr (requires { v.view(); }) {
        put_json_string(o, v.view());
    } else {
        o += '"';
        o += hex_of(v.span());
        o += '"';
    }
}

// ---------------------------------------------------------------- CSV
// CSV header names: "pu_motors_0.position[deg]", "battery_voltage[V]", "motor_current_5[A]"
template <class M>
void csv_header(buffer& o, const std::string& prefix) {
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        auto leaf = [&](const std::string& at) {
            if constexpr (F::kind == wire_kind::record) {
                csv_header<element_t<F>>(o, at + ".");
            } else {
                o += ',';
                std::string name;
                name = at;
                if constexpr (has_physical<F>()) {
                    if (!f.unit.name.empty()) {
                        // the physical value: "battery_voltage_raw" -> "battery_voltage[V]"
                        constexpr std::string_view raw = "_raw";
                        const std::string_view n = f.name;
                        if (n.size() > raw.size() && n.substr(n.size() - raw.size()) == raw)
                            name = prefix + std::string(n.substr(0, n.size() - raw.size())) +
                                   at.substr(prefix.size() + n.size());
                        name.append("[").append(f.unit.name).append("]");
                    }
                }
                put_csv_cell(o, name);
            }
        };
        const std::string at = prefix + std::string(f.name);
        if constexpr (F::is_array) {
            if (is_hex_array(f)) {
                o += ',';
                put_csv_cell(o, at);
            } else {
                for (std::size_t i = 0; i < F::count; ++i) leaf(at + "_" + std::to_string(i));
            }
        } else {
            leaf(at);
        }
    });
}

// One cell per leaf of m (m null: an absent optional block, empty cells).
template <class M>
void csv_cells(buffer& o, const M* m) {
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        using E = element_t<F>;
        auto cell = [&](const E* v) {
            if constexpr (F::kind == wire_kind::record) {
                csv_cells<E>(o, v);
            } else {
                o += ',';
                if (!v) return;
                if constexpr (std::is_same_v<E, bool>) {
                    o += *v ? "true" : "false";
                } else if constexpr (std::is_enum_v<E>) {
                    o.append(robowire::enum_name(*v));
                } else if constexpr (std::is_same_v<E, float>) {
                    if (std::isfinite(*v)) put_shortest(o, static_cast<double>(*v));
                } else if constexpr (std::is_integral_v<E>) {
                    if (!f.unit.name.empty()) put_shortest(o, physical_of(f, static_cast<std::int64_t>(*v)), 15);
                    else put_int(o, static_cast<std::int64_t>(*v));
                } else if constexpr (requires { v->view(); }) {
                    put_csv_cell(o, v->view());
                } else {
                    o += hex_of(v->span());
                }
            }
        };
        const auto* value = [&]() -> const auto* {
            using T = std::remove_cvref_t<decltype(m->*(f.member))>;
            if constexpr (F::is_optional) {
                using V = typename T::value_type;
                return m && (m->*(f.member)) ? &*(m->*(f.member)) : static_cast<const V*>(nullptr);
            } else {
                return m ? &(m->*(f.member)) : static_cast<const T*>(nullptr);
            }
        }
        ();
        if constexpr (F::is_array) {
            if (is_hex_array(f)) {
                o += ',';
                if (value) o += hex_of(hex_bytes<F>(*value));
            } else {
                for (std::size_t i = 0; i < F::count; ++i) cell(value ? &(*value)[i] : nullptr);
            }
        } else {
            cell(value);
        }
    });
}

// ---------------------------------------------------------------- a record
// A decoded message as one record of `out`'s format, after `meta`; `notes` for text and JSON.
template <class M>
void message(output& out, const record_meta& meta, std::string_view protocol, const M& m,
             const std::vector<std::string>& notes) {
    buffer& o = out.buf;
    switch (out.kind) {
    case format_kind::text:
        put_text_prefix(o, meta);
        write_text(o, protocol, m, notes);
        break;
    case format_kind::json:
        put_json_head(o, "message", meta);
        o.append(",\"protocol\":\"").append(protocol).append("\",\"message\":\"");
        o.append(robowire::table_v<M>.name).append("\",\"fields\":");
        write_json_object(o, m);
        if (!notes.empty()) {
            o += ",\"notes\":[";
            for (std::size_t i = 0; i < notes.size(); ++i) {
                if (i) o += ',';
                put_json_string(o, notes[i]);
            }
            o += ']';
        }
        o += "}\n";
        break;
    case format_kind::csv: {
        buffer* t = out.csv_table(protocol, robowire::table_v<M>.name, [](buffer& h) {
            h += "time,line,direction";
            csv_header<M>(h, std::string());
            h += '\n';
        });
        if (!t) return;
        put_csv_cell(*t, meta.time);
        *t += ',';
        if (meta.line) put_int(*t, static_cast<std::int64_t>(meta.line));
        *t += ',';
        *t += direction_key(meta.dir);
        csv_cells(*t, &m);
        *t += '\n';
        break;
    }
    }
    out.end_record();
}

// A decoded variant as a record.
template <class V>
void variant_message(output& out, const record_meta& meta, std::string_view protocol, const V& v,
                     const std::vector<std::string>& notes) {
    std::visit([&](const auto& m) { message(out, meta, protocol, m, notes); }, v);
}

}  // namespace robowire::tools::emit
