// The core building blocks, each against a simple model: bytes<N>, text<N>,
// the AD structure reader, sign-magnitude bytes, error/fail, enum validity
// of a code run and fuzz::source ranges. The protocols' codecs use only part
// of this API (whole frames, cut-to-capacity copies); users call all of it.
// Input: a list of operations, one byte each (modulo their number), followed
// by their operands.
#include <robowire/core.hpp>
#include <robowire/ext/fuzz.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <string_view>

#include "common.hpp"

namespace {

namespace rw = robowire;
constexpr std::size_t cap = 12;
using buffer = rw::bytes<cap>;

// What bytes<cap> must hold.
struct model {
    std::array<std::uint8_t, cap> b{};
    std::size_t n = 0;
    std::span<const std::uint8_t> span() const { return {b.data(), n}; }
};

void check_same(const buffer& b, const model& m) {
    FUZZ_CHECK(b.size() == m.n && b.empty() == (m.n == 0) && b.end() - b.begin() == static_cast<std::ptrdiff_t>(m.n));
    FUZZ_CHECK(fuzz::same_bytes(b.span(), m.span()) && b == m.span());
    for (std::size_t i = m.n; i < cap; ++i) FUZZ_CHECK(b.data()[i] == 0);  // unused capacity is zero
}

// Up to `most` bytes drawn from the input.
struct drawn {
    std::array<std::uint8_t, 32> b{};
    std::size_t n = 0;
    std::span<const std::uint8_t> span() const { return {b.data(), n}; }
};
drawn draw(rw::fuzz::source& s, std::size_t most) {
    drawn d;
    d.n = s.integral_in_range<std::size_t>(0, std::min(most, d.b.size()));
    for (std::size_t i = 0; i < d.n; ++i) d.b[i] = s.byte();
    return d;
}

// An enumeration whose valid codes are one run that does not start at 0.
enum class gear : std::uint8_t { low = 3, mid = 4, high = 5 };
constexpr auto enum_table_of(std::type_identity<gear>) {
    return std::array{rw::enum_entry<gear>{gear::low, "low"}, rw::enum_entry<gear>{gear::mid, "mid"},
                      rw::enum_entry<gear>{gear::high, "high"}};
}

// The AD structures of `adv` by the Core Specification's rule, against reader.
void check_advertising(std::span<const std::uint8_t> adv) {
    rw::ad::reader r(adv);
    std::size_t pos = 0;
    for (;;) {
        const auto s = r.next();
        if (pos >= adv.size() || adv[pos] == 0) {  // the end, or padding
            FUZZ_CHECK(!s && !r.error());
            break;
        }
        const std::size_t len = adv[pos];
        if (pos + 1 + len > adv.size()) {  // runs past the end
            FUZZ_CHECK(!s && r.error() == rw::fail(rw::errc::bad_length, pos));
            break;
        }
        FUZZ_CHECK(s && s->offset == pos && s->type == adv[pos + 1]);
        FUZZ_CHECK(s->data.data() == adv.data() + pos + 2 && s->data.size() == len - 1);
        pos += 1 + len;
    }
    const auto error = r.error();
    FUZZ_CHECK(!r.next() && r.error() == error);  // stays at its end
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rw::fuzz::source s{data, size};
    buffer b;
    model m;
    for (int ops = 0; ops < 64 && s.remaining() > 0; ++ops) {
        switch (s.byte() % 12) {
        case 0: {  // push_back: false and no change when full
            const std::uint8_t v = s.byte();
            const bool fits = m.n < cap;
            FUZZ_CHECK(b.push_back(v) == fits);
            if (fits) m.b[m.n++] = v;
            break;
        }
        case 1: {  // append: all or nothing
            const drawn d = draw(s, cap + 2);
            const bool fits = d.n <= cap - m.n;
            FUZZ_CHECK(b.append(d.span()) == fits);
            if (fits) {
                std::copy_n(d.b.begin(), d.n, m.b.begin() + static_cast<std::ptrdiff_t>(m.n));
                m.n += d.n;
            }
            break;
        }
        case 2: {  // resize (clamped to capacity; new bytes zero) and clear
            const std::size_t n = s.integral_in_range<std::size_t>(0, cap + 3);
            const bool clear = s.boolean();
            if (clear) b.clear();
            else b.resize(n);
            const std::size_t want = clear ? 0 : std::min(n, cap);
            FUZZ_CHECK(b.size() == want);
            for (std::size_t i = std::min(want, m.n); i < cap; ++i) m.b[i] = 0;
            m.n = want;
            break;
        }
        case 3: {  // zeros(n): n clamped to capacity
            const std::size_t n = s.integral_in_range<std::size_t>(0, cap + 3);
            b = buffer::zeros(n);
            m = model{};
            m.n = std::min(n, cap);
            break;
        }
        case 4: {  // from(span): capacity_exceeded at offset cap when it does not fit
            const drawn d = draw(s, cap + 3);
            const auto r = buffer::from(d.span());
            fuzz::check_access(r);
            if (d.n > cap) {
                FUZZ_CHECK(!r && r.error() == rw::fail(rw::errc::capacity_exceeded, cap));
                break;
            }
            FUZZ_CHECK(r && *r == d.span());
            b = *r;
            m = model{};
            std::copy_n(d.b.begin(), d.n, m.b.begin());
            m.n = d.n;
            break;
        }
        case 5: {  // comparisons: equal exactly when the used bytes are
            const drawn d = draw(s, cap + 3);
            const bool same = d.n == m.n && std::equal(d.b.begin(), d.b.begin() + static_cast<std::ptrdiff_t>(d.n), m.b.begin());
            FUZZ_CHECK(rw::equal_bytes(b.span(), d.span()) == same && (b == d.span()) == same);
            rw::bytes<cap + 4> wide;
            FUZZ_CHECK(wide.append(d.span()) && (b == wide) == same && (wide == b) == same);
            break;
        }
        case 6: {  // text<8>: make and assign take at most 8 characters, else fail and keep the text
            using text8 = rw::text<8>;
            const drawn d = draw(s, 11);
            const std::string_view str(reinterpret_cast<const char*>(d.b.data()), d.n);
            const auto t = text8::make(str);
            fuzz::check_access(t);
            if (d.n > 8) FUZZ_CHECK(!t && t.error() == rw::fail(rw::errc::value_out_of_range, 8));
            else FUZZ_CHECK(t && t->view() == str && t->size() == d.n && *t == str);
            text8 u = text8("keep");
            FUZZ_CHECK(u.assign(str) == (d.n <= 8));
            FUZZ_CHECK(u.view() == (d.n <= 8 ? str : std::string_view("keep")));
            break;
        }
        case 7:  // the AD structure reader over the rest of the input
            check_advertising(s.rest());
            break;
        case 8: {  // sign-magnitude: every int8 but -128 round-trips
            const auto v = s.integral<std::int8_t>();
            const auto r = rw::to_sign_magnitude(v);
            fuzz::check_access(r);
            if (v == -128) {
                FUZZ_CHECK(!r && r.error() == rw::fail(rw::errc::value_out_of_range, 0) && r.value_or(0x55) == 0x55);
            } else {
                FUZZ_CHECK(r && rw::from_sign_magnitude(*r) == v && (*r & 0x80) == (v < 0 ? 0x80 : 0));
            }
            const std::uint8_t byte = s.byte();
            const int back = rw::from_sign_magnitude(byte);
            FUZZ_CHECK(back == ((byte & 0x80) ? -(byte & 0x7F) : (byte & 0x7F)));
            break;
        }
        case 9: {  // errors: fail clamps offsets to 65535; equality is member-wise; every code has a text
            const auto code = static_cast<rw::errc>(s.byte());
            const auto other = static_cast<rw::errc>(s.byte());
            const std::uint64_t offset = s.integral<std::uint32_t>() >> (s.byte() % 32);
            const rw::error e = rw::fail(code, offset);
            FUZZ_CHECK(e.code == code && e.offset == std::min<std::uint64_t>(offset, 0xFFFF));
            FUZZ_CHECK((e == rw::fail(other, offset)) == (code == other));
            FUZZ_CHECK((e == rw::fail(code, offset + 1)) == (offset >= 0xFFFF));
            FUZZ_CHECK(static_cast<bool>(e) == (code != rw::errc::ok));
            FUZZ_CHECK(!rw::to_string(code).empty());
            break;
        }
        case 10: {  // a code run that starts above 0
            const auto g = static_cast<gear>(s.byte());
            const auto code = static_cast<unsigned>(g);
            FUZZ_CHECK(rw::is_valid_enum(g) == (code >= 3 && code <= 5));
            break;
        }
        case 11: {  // fuzz::source ranges: lo..hi, lo for an empty range, every uint64 value for the full one
            const auto lo = s.integral<std::uint64_t>() >> (s.byte() % 64);
            const auto hi = s.integral<std::uint64_t>() >> (s.byte() % 64);
            const drawn d = draw(s, 8);
            rw::fuzz::source inner{d.b.data(), d.n};
            const auto v = inner.integral_in_range(lo, hi);
            FUZZ_CHECK(hi < lo ? v == lo : (v >= lo && v <= hi));
            rw::fuzz::source whole{d.b.data(), d.n};
            std::uint64_t le = 0;
            for (std::size_t i = 0; i < d.n; ++i) le |= std::uint64_t{d.b[i]} << (8 * i);
            FUZZ_CHECK(whole.integral_in_range<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()) == le);
            rw::fuzz::source small{d.b.data(), d.n};
            const auto i8 = small.integral_in_range<std::int8_t>(-100, 100);
            FUZZ_CHECK(i8 >= -100 && i8 <= 100);
            break;
        }
        }
        check_same(b, m);
    }
    return 0;
}
