// Hex text as users paste it, and hex/binary detection.
#include <array>
#include <cstdio>

#include "tools.hpp"

namespace robowire::tools {
namespace {
// Per byte: 0-15 a hex digit's value, 16 a separator, 17 anything else.
constexpr std::array<std::uint8_t, 256> classes = [] {
    std::array<std::uint8_t, 256> t{};
    for (auto& c : t) c = 17;
    for (int i = 0; i < 10; ++i) t[static_cast<std::size_t>('0' + i)] = static_cast<std::uint8_t>(i);
    for (int i = 0; i < 6; ++i) {
        t[static_cast<std::size_t>('a' + i)] = static_cast<std::uint8_t>(10 + i);
        t[static_cast<std::size_t>('A' + i)] = static_cast<std::uint8_t>(10 + i);
    }
    for (const char c : {' ', '\t', '\n', '\r', '\f', '\v', '-', ':', ',', ';', '{', '}', '[', ']'})
        t[static_cast<unsigned char>(c)] = 16;
    return t;
}();
bool is_separator(char c) { return classes[static_cast<unsigned char>(c)] == 16; }
int digit(char c) {
    const int v = classes[static_cast<unsigned char>(c)];
    return v < 16 ? v : -1;
}
bool starts_with_0x_marker(std::string_view s) {  // nRF Connect's "(0x)"
    return s.size() >= 4 && s[0] == '(' && s[1] == '0' && (s[2] == 'x' || s[2] == 'X') && s[3] == ')';
}
std::string shown(char c) {
    char b[16];
    if (static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F)
        std::snprintf(b, sizeof b, "'%c'", c);
    else std::snprintf(b, sizeof b, "byte 0x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
    return b;
}
}  // namespace

std::optional<byte_vector> parse_hex_text(std::string_view text, std::string& error) {
    byte_vector out;
    if (!parse_hex_into(text, out, error)) return std::nullopt;
    return out;
}

bool parse_hex_into(std::string_view text, byte_vector& out, std::string& error) {
    out.clear();
    // the common spellings first ("01-6D-50", "01 6D 50", "016D50"): two digits, then a separator or not
    {
        std::size_t k = 0;
        const std::size_t n = text.size();
        while (k + 1 < n) {
            const unsigned hi = classes[static_cast<unsigned char>(text[k])];
            const unsigned lo = classes[static_cast<unsigned char>(text[k + 1])];
            if ((hi | lo) >= 16) break;
            out.push_back(static_cast<std::uint8_t>(hi << 4 | lo));
            k += 2;
            if (k < n && classes[static_cast<unsigned char>(text[k])] == 16) ++k;
        }
        if (k == n && !out.empty() && n > 0 && !(n >= 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')))
            return true;
        out.clear();
    }
    std::size_t i = 0;
    while (i < text.size()) {
        if (is_separator(text[i])) {
            ++i;
            continue;
        }
        if (starts_with_0x_marker(text.substr(i))) {
            i += 4;
            continue;
        }
        const std::size_t start = i;
        std::size_t end = i;
        while (end < text.size() && !is_separator(text[end])) ++end;
        std::size_t d = start;
        if (end - start >= 2 && text[start] == '0' && (text[start + 1] == 'x' || text[start + 1] == 'X')) d += 2;
        for (std::size_t k = d; k < end; ++k) {
            if (digit(text[k]) < 0) {
                error = "bad hex: " + shown(text[k]) + " at character " + std::to_string(k) + " is not a hex digit";
                return false;
            }
        }
        const std::size_t digits = end - d;
        if (d != start && digits == 1) {  // "0x1": one byte, as C writes it
            out.push_back(static_cast<std::uint8_t>(digit(text[d])));
            i = end;
            continue;
        }
        if (digits == 0 || digits % 2 != 0) {
            error = "bad hex: odd number of hex digits in \"" + shorten(text.substr(start, end - start)) +
                    "\" at character " + std::to_string(start) + " (each byte is two hex digits, or one after 0x)";
            return false;
        }
        for (std::size_t k = d; k < end; k += 2)
            out.push_back(static_cast<std::uint8_t>(digit(text[k]) << 4 | digit(text[k + 1])));
        i = end;
    }
    if (out.empty()) {
        error = "bad hex: no hex bytes given";
        return false;
    }
    return true;
}

bool parse_dashed_hex(std::string_view text, byte_vector& out, std::size_t& used) {
    const std::size_t n = text.size();
    // at most n / 3 + 1 bytes, written through a pointer: into a local array
    // for a value of up to 512 bytes (no zero fill of `out` first), else into `out`
    std::uint8_t local[512];
    const bool small = n / 3 + 1 <= sizeof local;
    if (!small) out.resize(n / 3 + 1);
    std::uint8_t* const start = small ? local : out.data();
    std::uint8_t* d = start;
    std::size_t k = 0;
    for (;;) {
        if (k + 1 >= n) return false;
        const unsigned hi = classes[static_cast<unsigned char>(text[k])];
        const unsigned lo = classes[static_cast<unsigned char>(text[k + 1])];
        if ((hi | lo) >= 16) return false;
        *d++ = static_cast<std::uint8_t>(hi << 4 | lo);
        k += 2;
        if (k == n || text[k] != '-') break;
        ++k;
    }
    if (small) out.assign(start, d);
    else out.resize(static_cast<std::size_t>(d - start));
    // what follows the value: the end, or a character that cannot continue it
    if (k < n && (classes[static_cast<unsigned char>(text[k])] < 16 || text[k] == ':' || text[k] == ' ')) return false;
    used = k;
    return true;
}

bool looks_like_hex_text(std::span<const std::uint8_t> data) {
    bool any_digit = false;
    for (const std::uint8_t b : data) {
        const char c = static_cast<char>(b);
        if (digit(c) >= 0) any_digit = true;
        else if (!is_separator(c) && c != 'x' && c != 'X' && c != '(' && c != ')') return false;
    }
    return any_digit;
}

std::string hex_of(std::span<const std::uint8_t> bytes) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string s;
    s.reserve(bytes.size() * 3);
    for (const std::uint8_t b : bytes) {
        if (!s.empty()) s += ' ';
        s += digits[b >> 4];
        s += digits[b & 15];
    }
    return s;
}

}  // namespace robowire::tools
