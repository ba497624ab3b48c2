// robowire and the hand-written baselines of bench/core.cpp, run on the same inputs:
// the same outcome, error code and offset, and output (bench/verify/run).
#include "../core.cpp"
#include "check.hpp"
#include <string>
int main() {
    const auto buf = random_bytes(100);
    for (std::size_t n = 0; n <= 85; ++n) {  // offsets up to 254 (bench::hw packs them in 8 bits)
        const std::size_t need = n ? 3 * n - 1 : 0;
        for (std::size_t size = 0; size <= need + 2; ++size) {
            std::array<char, 300> a, b;
            a.fill('#');
            b.fill('#');
            auto r = robowire::to_hex(std::span(buf).first(n), std::span(a.data(), size));
            const auto e = hw_to_hex(buf.data(), n, b.data(), size);
            const std::string ctx = "n=" + std::to_string(n) + " size=" + std::to_string(size);
            if (same_err("to_hex", rw_err(r), e, ctx)) {
                if (a != b) mismatch("to_hex text", ctx);
                if (e == bench::hw::good && *r != need) mismatch("to_hex count", ctx);
            }
            std::array<char, 300> c;
            c.fill('#');
            if (same_err("to_hex careful", rw_err(r), careful_to_hex(buf.data(), n, c.data(), size), ctx) && a != c)
                mismatch("to_hex careful text", ctx);
            for (const char sep : {'\0', ':'}) {  // the other separators against the byte-by-byte path's text
                std::array<char, 300> d;
                d.fill('#');
                const auto rs = robowire::to_hex(std::span(buf).first(n), std::span(d.data(), size), sep);
                std::string want;
                for (std::size_t k = 0; k < n; ++k) {
                    if (k && sep) want += sep;
                    want += "0123456789ABCDEF"[buf[k] >> 4];
                    want += "0123456789ABCDEF"[buf[k] & 15];
                }
                ++g_counts["to_hex separators"];
                if (want.size() <= size && (!rs || *rs != want.size() || std::string(d.data(), *rs) != want ||
                                            d[want.size()] != '#'))
                    mismatch("to_hex separator", ctx);
                if (want.size() > size && rs) mismatch("to_hex separator size", ctx);
            }
        }
    }
    return report();
}
