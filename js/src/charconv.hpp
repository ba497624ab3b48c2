// std::to_chars and std::from_chars for double, which emscripten 3.1.6's
// libc++ lacks (it has the integer forms only); the command-line tool's JSON
// writer (tools/lib/emit.hpp) uses them. Forced into each translation unit of the
// WebAssembly build (js/build, -include), from printf and strtod (musl:
// correctly rounded), with the standard's results:
//   to_chars(f, l, v)                 shortest round-trip digits, fixed or scientific, whichever is shorter (fixed on a
//   tie) to_chars(f, l, v, scientific)     shortest round-trip digits, d.ddde+XX to_chars(f, l, v, general, p) printf's
//   %.<p>g from_chars(f, l, v)               strtod
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace std {

namespace robowire_js {
// The shortest %.<p>e of v that reads back as v: its digits d[0..n) and exponent.
inline int shortest(double v, char* digits, int& exp) {
    char b[40];
    for (int p = 0; p < 17; ++p) {
        std::snprintf(b, sizeof b, "%.*e", p, v);
        if (std::strtod(b, nullptr) == v || p == 16) {
            int n = 0;
            const char* s = b + (b[0] == '-');
            for (; *s && *s != 'e'; ++s)
                if (*s != '.') digits[n++] = *s;
            exp = std::atoi(s + 1);
            while (n > 1 && digits[n - 1] == '0') --n;
            return n;
        }
    }
    return 0;
}
inline to_chars_result put(char* first, char* last, const std::string& s) {
    if (static_cast<std::size_t>(last - first) < s.size()) return {last, errc::value_too_large};
    std::memcpy(first, s.data(), s.size());
    return {first + s.size(), errc{}};
}
inline std::string special(double v) {
    if (v != v) return "nan";
    return v < 0 ? "-inf" : "inf";
}
inline std::string scientific(bool neg, const char* d, int n, int exp) {
    std::string s = neg ? "-" : "";
    s += d[0];
    if (n > 1) s += '.', s.append(d + 1, static_cast<std::size_t>(n - 1));
    char e[8];
    std::snprintf(e, sizeof e, "e%c%02d", exp < 0 ? '-' : '+', exp < 0 ? -exp : exp);
    return s + e;
}
inline std::string fixed(bool neg, const char* d, int n, int exp) {
    std::string s = neg ? "-" : "";
    if (exp >= n - 1) {
        s.append(d, static_cast<std::size_t>(n));
        s.append(static_cast<std::size_t>(exp - (n - 1)), '0');
    } else if (exp >= 0) {
        s.append(d, static_cast<std::size_t>(exp + 1));
        s += '.';
        s.append(d + exp + 1, static_cast<std::size_t>(n - exp - 1));
    } else {
        s += "0.";
        s.append(static_cast<std::size_t>(-exp - 1), '0');
        s.append(d, static_cast<std::size_t>(n));
    }
    return s;
}
}  // namespace robowire_js

inline to_chars_result to_chars(char* first, char* last, double v) {
    if (v != v || v - v != 0) return robowire_js::put(first, last, robowire_js::special(v));
    char d[24];
    int exp = 0;
    const int n = robowire_js::shortest(v, d, exp);
    const bool neg = std::signbit(v);
    const std::string f = robowire_js::fixed(neg, d, n, exp), e = robowire_js::scientific(neg, d, n, exp);
    return robowire_js::put(first, last, f.size() <= e.size() ? f : e);
}
inline to_chars_result to_chars(char* first, char* last, double v, chars_format fmt) {
    if (fmt != chars_format::scientific) return to_chars(first, last, v);
    if (v != v || v - v != 0) return robowire_js::put(first, last, robowire_js::special(v));
    char d[24];
    int exp = 0;
    const int n = robowire_js::shortest(v, d, exp);
    return robowire_js::put(first, last, robowire_js::scientific(std::signbit(v), d, n, exp));
}
inline to_chars_result to_chars(char* first, char* last, double v, chars_format fmt, int precision) {
    char b[64];
    const char* spec = fmt == chars_format::scientific ? "%.*e" : fmt == chars_format::fixed ? "%.*f" : "%.*g";
    std::snprintf(b, sizeof b, spec, precision, v);
    return robowire_js::put(first, last, b);
}
inline from_chars_result from_chars(const char* first, const char* last, double& v,
                                    chars_format = chars_format::general) {
    const std::string s(first, last);
    char* end = nullptr;
    const double r = std::strtod(s.c_str(), &end);
    if (end == s.c_str()) return {first, errc::invalid_argument};
    v = r;
    return {first + (end - s.c_str()), errc{}};
}

}  // namespace std
