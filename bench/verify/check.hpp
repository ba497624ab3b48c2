// Shared by bench/verify/*.cpp: compares an error of robowire with one of a
// baseline (bench::hw::error), counts the inputs compared, reports mismatches.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
static std::map<std::string, std::size_t> g_counts;
static std::size_t g_fail = 0;
template <class R>
robowire::error rw_err(const R& r) { return r.has_value() ? robowire::error{} : r.error(); }
inline bool same_err(const char* what, robowire::error re, bench::hw::error he, const std::string& ctx) {
    ++g_counts[what];
    const unsigned hc = he & 0xFF, ho = he >> 8;
    if (static_cast<unsigned>(re.code) != hc || (re.code != robowire::errc::ok && re.offset != ho)) {
        if (g_fail++ < 20)
            std::printf("MISMATCH %s %s: robowire %u@%u, baseline %u@%u\n", what, ctx.c_str(),
                        static_cast<unsigned>(re.code), re.offset, hc, ho);
        return false;
    }
    return true;
}
inline void mismatch(const char* what, const std::string& ctx) {
    if (g_fail++ < 20) std::printf("VALUE MISMATCH %s %s\n", what, ctx.c_str());
}
inline int report() {
    std::size_t total = 0;
    for (auto& [k, v] : g_counts) { std::printf("%-28s %zu inputs compared\n", k.c_str(), v); total += v; }
    std::printf("total %zu, mismatches %zu\n", total, g_fail);
    return g_fail ? 1 : 0;
}

// `in` followed by random bytes from `r` up to N bytes: an input to cut to
// every length, past the message's end too.
template <std::size_t N, class In, class Rng>
std::array<std::uint8_t, N> padded(const In& in, Rng& r) {
    std::array<std::uint8_t, N> buf{};
    std::copy(in.begin(), in.end(), buf.begin());
    for (std::size_t i = in.size(); i < N; ++i) buf[i] = r.byte();
    return buf;
}
// The input `buf` cut to every length n from 0 to N: check(data, n, ctx) on
// it as it is ("len"), and, where every_byte(n), with each byte before n set
// to each of its 256 values ("byte POS=VAL").
template <std::size_t N, class Every, class Check>
void sweep_lengths(const std::array<std::uint8_t, N>& buf, Every every_byte, Check check) {
    for (std::size_t n = 0; n <= N; ++n) {
        check(buf.data(), n, std::string("len"));
        if (!every_byte(n)) continue;
        for (std::size_t pos = 0; pos < n; ++pos)
            for (int val = 0; val < 256; ++val) {
                auto b = buf;
                b[pos] = static_cast<std::uint8_t>(val);
                check(b.data(), n, "byte " + std::to_string(pos) + "=" + std::to_string(val));
            }
    }
}
// Each of `count` fields of `base` set to each of 256 values (set(m, k, v)),
// then each pair of fields set to their bad values bad[k] (the first one is
// the error): check(m, ctx) on every message.
template <class M, class Set, class Check>
void sweep_fields(const M& base, std::size_t count, Set set, const int* bad, Check check) {
    for (std::size_t k = 0; k < count; ++k)
        for (int val = 0; val < 256; ++val) {
            M m = base;
            set(m, k, val);
            check(m, "field " + std::to_string(k) + "=" + std::to_string(val));
        }
    for (std::size_t k = 0; k < count; ++k)
        for (std::size_t g = k + 1; g < count; ++g) {
            M m = base;
            set(m, k, bad[k]);
            set(m, g, bad[g]);
            check(m, std::string("pair"));
        }
}
