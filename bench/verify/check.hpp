// Shared by bench/verify/*.cpp: compares an error of robowire with one of a
// baseline (bench::hw::error), counts the inputs compared, reports mismatches.
#pragma once
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
