// robowire/core/bytes.hpp - bytes<N>: fixed-capacity byte buffer (no heap),
// and hex formatting / parsing into caller-owned buffers.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <span>
#include <string_view>
#include <type_traits>

#include "result.hpp"

namespace robowire {

namespace codec {
// Copies n <= 16 bytes. At run time: two fixed-size (overlapping) copies,
// never a call to memcpy.
constexpr void copy_small(std::uint8_t* to, const std::uint8_t* from, std::size_t n) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) {
        for (std::size_t k = 0; k < n; ++k) to[k] = from[k];
        return;
    }
    const auto pair = [&](auto width) {
        constexpr std::size_t w = decltype(width)::value;
        std::memcpy(to, from, w);
        std::memcpy(to + n - w, from + n - w, w);
    };
    if (n >= 8) pair(std::integral_constant<std::size_t, 8>{});
    else if (n >= 4) pair(std::integral_constant<std::size_t, 4>{});
    else if (n >= 2) pair(std::integral_constant<std::size_t, 2>{});
    else if (n == 1) to[0] = from[0];
}
}  // namespace codec
namespace detail {
// n bytes at a and at b are equal (memcmp at run time, as std::equal does).
constexpr bool same_bytes(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) {
        for (std::size_t k = 0; k < n; ++k)
            if (a[k] != b[k]) return false;
        return true;
    }
    return n == 0 || std::memcmp(a, b, n) == 0;
}
}  // namespace detail

template <std::size_t N>
class bytes;
namespace codec {
// Sets the size of a bytes<N> whose first n bytes (n <= N) the caller has
// written through data(): no clamp, no zero fill (the codecs' encoders).
template <std::size_t N>
constexpr void set_written_size(bytes<N>& b, std::size_t n) noexcept;
}  // namespace codec

// Up to N bytes, stored inline. Unused capacity is always zero, so the default
// comparison compares exactly the used bytes.
template <std::size_t N>
class bytes {
public:
    using value_type = std::uint8_t;
    using iterator = std::uint8_t*;
    using const_iterator = const std::uint8_t*;

    constexpr bytes() noexcept : size_(0), data_{} {}
    // Bytes and size unset: for an encoder that then writes all N bytes and
    // calls codec::set_written_size (nothing is cleared first).
    constexpr explicit bytes(codec::unset_t) noexcept {}
    // Precondition: init.size() <= N (excess is dropped).
    constexpr bytes(std::initializer_list<std::uint8_t> init) noexcept : bytes() {
        append(std::span(init.begin(), init.size()));
    }

    // A buffer of `n` zero bytes (n clamped to N).
    static constexpr bytes zeros(std::size_t n) noexcept {
        bytes b;
        b.size_ = static_cast<size_type>(n < N ? n : N);
        return b;
    }
    // Copy of `src`; capacity_exceeded if it does not fit.
    static constexpr result<bytes> from(std::span<const std::uint8_t> src) noexcept {
        bytes b;
        if (!b.append(src)) return fail(errc::capacity_exceeded, N);
        return b;
    }

    static constexpr std::size_t capacity() noexcept { return N; }
    constexpr std::size_t size() const noexcept {
#if defined(__GNUC__)
        if (size_ > N) __builtin_unreachable();  // lets the compiler drop paths for longer input
#endif
        return size_;
    }
    constexpr bool empty() const noexcept { return size_ == 0; }
    // The bytes; aligned to 1 only (the size is stored before them).
    constexpr std::uint8_t* data() noexcept { return data_.data(); }
    constexpr const std::uint8_t* data() const noexcept { return data_.data(); }
    constexpr iterator begin() noexcept { return data_.data(); }
    constexpr iterator end() noexcept { return data_.data() + size_; }
    constexpr const_iterator begin() const noexcept { return data_.data(); }
    constexpr const_iterator end() const noexcept { return data_.data() + size_; }
    // Precondition: i < size().
    constexpr std::uint8_t& operator[](std::size_t i) noexcept { return data_[i]; }
    constexpr const std::uint8_t& operator[](std::size_t i) const noexcept { return data_[i]; }

    constexpr std::span<std::uint8_t> span() noexcept { return {data_.data(), size_}; }
    constexpr std::span<const std::uint8_t> span() const noexcept { return {data_.data(), size_}; }

    // Appends one byte; false (and no change) when full.
    constexpr bool push_back(std::uint8_t b) noexcept {
        if (size_ == N) return false;
        data_[size_] = b;
        ++size_;
        return true;
    }
    // Appends all of src; false (and no change) when it does not fit.
    constexpr bool append(std::span<const std::uint8_t> src) noexcept {
        if (src.size() > N - size_) return false;
        for (auto b : src) {
            data_[size_] = b;
            ++size_;
        }
        return true;
    }
    // Sets the size; new bytes are zero. Precondition: n <= N.
    constexpr void resize(std::size_t n) noexcept {
        if (n > N) n = N;
        for (std::size_t i = n; i < size_; ++i) data_[i] = 0;
        size_ = static_cast<size_type>(n);
    }
    constexpr void clear() noexcept { resize(0); }

    friend constexpr bool operator==(const bytes& a, std::span<const std::uint8_t> b) noexcept {
        return a.size_ == b.size() && detail::same_bytes(a.data(), b.data(), b.size());
    }

    // A bytes<N> lies as its size (one byte), then its N bytes: an encoder may
    // write the size and the first bytes as one word.
    static constexpr bool size_byte_then_data() noexcept;

private:
    // The smallest type that holds N and one value more (a result's error mark).
    using size_type =
        std::conditional_t<(N < 0xFF), std::uint8_t, std::conditional_t<(N < 0xFFFF), std::uint16_t, std::size_t>>;
    static constexpr size_type no_value = static_cast<size_type>(-1);
    // The size first: an encoder's store of it joins that of the first byte (often a constant).
    size_type size_;
    std::array<std::uint8_t, N> data_;  // set by every constructor but bytes(codec::unset_t)
    template <std::size_t M>
    friend constexpr void codec::set_written_size(bytes<M>& b, std::size_t n) noexcept;
    friend struct detail::niche<bytes>;
};

template <std::size_t N>
constexpr bool bytes<N>::size_byte_then_data() noexcept {
    return sizeof(size_type) == 1 && sizeof(bytes) == N + 1 && offsetof(bytes, data_) == 1;
}
template <std::size_t N>
constexpr void codec::set_written_size(bytes<N>& b, std::size_t n) noexcept {
    b.size_ = static_cast<typename bytes<N>::size_type>(n);
}

// result<bytes<N>> keeps its error in the bytes: a size of no_value, the code
// and the offset in the first four bytes.
template <std::size_t N>
requires(N >= 4) struct detail::niche<bytes<N>> {
    static constexpr bool used = true;
    static constexpr bool engaged(const bytes<N>& b) noexcept { return b.size_ != bytes<N>::no_value; }
    static constexpr void set_error(bytes<N>& b, error e) noexcept {
        b.size_ = bytes<N>::no_value;
        const auto code = static_cast<std::uint16_t>(e.code);
        b.data_[0] = static_cast<std::uint8_t>(code);
        b.data_[1] = static_cast<std::uint8_t>(code >> 8);
        b.data_[2] = static_cast<std::uint8_t>(e.offset);
        b.data_[3] = static_cast<std::uint8_t>(e.offset >> 8);
    }
    static constexpr bytes<N> make_error(error e) noexcept {
        bytes<N> b = ROBOWIRE_CONSTANT_EVALUATED() ? bytes<N>() : bytes<N>(codec::unset_t{});
        set_error(b, e);
        return b;
    }
    static constexpr error get_error(const bytes<N>& b) noexcept {
        return error{static_cast<errc>(b.data_[0] | b.data_[1] << 8),
                     static_cast<std::uint16_t>(b.data_[2] | b.data_[3] << 8)};
    }
};

// Equal when sizes and used bytes are equal (capacities may differ).
template <std::size_t N, std::size_t M>
[[nodiscard]] constexpr bool operator==(const bytes<N>& a, const bytes<M>& b) noexcept {
    return a.size() == b.size() && detail::same_bytes(a.data(), b.data(), a.size());
}

// Equality of two byte spans.
[[nodiscard]] constexpr bool equal_bytes(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) noexcept {
    return a.size() == b.size() && detail::same_bytes(a.data(), b.data(), a.size());
}

namespace detail {
// The two upper-case hex digits of each byte value b, at 2 * b (to_hex at
// speed; a literal: nothing to evaluate in a file that includes this header).
inline constexpr char hex_pairs[] =
    "000102030405060708090A0B0C0D0E0F"
    "101112131415161718191A1B1C1D1E1F"
    "202122232425262728292A2B2C2D2E2F"
    "303132333435363738393A3B3C3D3E3F"
    "404142434445464748494A4B4C4D4E4F"
    "505152535455565758595A5B5C5D5E5F"
    "606162636465666768696A6B6C6D6E6F"
    "707172737475767778797A7B7C7D7E7F"
    "808182838485868788898A8B8C8D8E8F"
    "909192939495969798999A9B9C9D9E9F"
    "A0A1A2A3A4A5A6A7A8A9AAABACADAEAF"
    "B0B1B2B3B4B5B6B7B8B9BABBBCBDBEBF"
    "C0C1C2C3C4C5C6C7C8C9CACBCCCDCECF"
    "D0D1D2D3D4D5D6D7D8D9DADBDCDDDEDF"
    "E0E1E2E3E4E5E6E7E8E9EAEBECEDEEEF"
    "F0F1F2F3F4F5F6F7F8F9FAFBFCFDFEFF";
static_assert(sizeof hex_pairs == 513);
// The two digits of b and a space, as a word that holds them in memory order
// (to_hex with the space: one 4-byte store per byte, the next overwrites the
// fourth). A template: evaluated only where to_hex runs.
template <class = void>
inline constexpr auto hex_words_v = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::size_t b = 0; b < 256; ++b) {
        const std::uint32_t c0 = static_cast<std::uint8_t>(hex_pairs[2 * b]),
                            c1 = static_cast<std::uint8_t>(hex_pairs[2 * b + 1]), sp = ' ';
        t[b] = std::endian::native == std::endian::little ? c0 | c1 << 8 | sp << 16 : c0 << 24 | c1 << 16 | sp << 8;
    }
    return t;
}();
}  // namespace detail

namespace detail {
// to_hex's bytes before the last with another separator, or none: returns
// where the last byte's digits go. Out of line: to_hex with the space stays small.
ROBOWIRE_NOINLINE inline char* hex_other(const std::uint8_t* in, std::size_t n, char* o, char separator) noexcept {
    for (std::size_t i = 0; i < n; ++i) {
        std::memcpy(o, hex_pairs + 2 * std::size_t{in[i]}, 2);
        o += 2;
        if (separator) *o++ = separator;
    }
    return o;
}
}  // namespace detail

// Characters to_hex writes for n bytes (with a separator: 3n - 1, else 2n).
[[nodiscard]] constexpr std::size_t hex_size(std::size_t n, char separator = ' ') noexcept {
    if (n == 0) return 0;
    return separator ? 3 * n - 1 : 2 * n;
}

// Writes `in` as upper-case hex ("01 5C FF") into out; returns the number of
// characters written (no terminator) or buffer_too_small.
template <class Deferred = void>  // a template: nothing evaluated in a file that does not call it
[[nodiscard]] ROBOWIRE_ALWAYS_INLINE constexpr result<std::size_t> to_hex(std::span<const std::uint8_t> in,
                                                                          std::span<char> out,
                                                                          char separator = ' ') noexcept {
    constexpr std::string_view digits = "0123456789ABCDEF";
    const std::size_t need = hex_size(in.size(), separator);
    if (need > out.size()) return fail(errc::buffer_too_small, need);
    char* o = out.data();
    if constexpr (!ROBOWIRE_OPTIMIZE_SIZE) {  // digits from tables, the separator test outside the loop
        if (!ROBOWIRE_CONSTANT_EVALUATED() && !in.empty()) {
            const std::size_t last = in.size() - 1;
            if (separator == ' ') {  // 8 bytes a step
                const auto put = [&o](std::uint8_t b, std::size_t k) {
                    std::memcpy(o + 3 * k, &detail::hex_words_v<Deferred>[b], 4);
                };
                const std::uint8_t* p = in.data();
                for (std::size_t k = last / 8; k != 0; --k, p += 8, o += 24) {
                    put(p[0], 0), put(p[1], 1), put(p[2], 2), put(p[3], 3);
                    put(p[4], 4), put(p[5], 5), put(p[6], 6), put(p[7], 7);
                }
                for (std::size_t k = last % 8; k != 0; --k, ++p, o += 3) put(*p, 0);
            } else {
                o = detail::hex_other(in.data(), last, o, separator);
            }
            std::memcpy(o, detail::hex_pairs + 2 * std::size_t{in[last]}, 2);
            return need;
        }
    }
    const auto put = [&](std::uint8_t b) {
        *o++ = digits[b >> 4];
        *o++ = digits[b & 0x0F];
    };
    if (!in.empty()) put(in[0]);
    for (std::size_t i = 1; i < in.size(); ++i) {  // the first byte apart: no test for it in the loop
        if (separator) *o++ = separator;
        put(in[i]);
    }
    return static_cast<std::size_t>(o - out.data());
}

// Parses hex in the usual spellings: "01 5C", "015C", "0x01,0x5C", "01-5C",
// "01:5C". Error offsets are character positions in `text`.
template <std::size_t N>
[[nodiscard]] constexpr result<bytes<N>> parse_hex(std::string_view text) noexcept {
    auto nibble = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    bytes<N> out;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == ' ' || c == ',' || c == '-' || c == ':' || c == '\t' || c == '\n' || c == '\r') {
            ++i;
            continue;
        }
        if (c == '0' && i + 1 < text.size() && (text[i + 1] == 'x' || text[i + 1] == 'X')) {
            i += 2;
            continue;
        }
        const int hi = nibble(c);
        if (hi < 0) return fail(errc::value_out_of_range, i);
        if (i + 1 >= text.size() || nibble(text[i + 1]) < 0) return fail(errc::bad_length, i);
        if (!out.push_back(static_cast<std::uint8_t>(hi * 16 + nibble(text[i + 1]))))
            return fail(errc::capacity_exceeded, i);
        i += 2;
    }
    return out;
}

}  // namespace robowire
