// The tool's fast number formatting (tools/lib/emit.hpp: %g from the shortest
// round-trip digits, whole numbers as integers) against the exact form
// (std::to_chars with the precision, printf's %g): physical values of the
// tables' scales over wide raw ranges, random doubles, random bit patterns.
// Prints the first differences; exits 1 on any.
#include <cstdio>
#include <cstring>
#include <random>

#include "emit.hpp"

using namespace robowire::tools;

int main() {
    long bad = 0, n = 0;
    auto text = [](const buffer& b) { return std::string(b.view()); };
    auto check = [&](double v) {
        for (const int p : {6, 15}) {
            buffer a, b;
            emit::put_g(a, v, p);
            emit::put_g_exact(b, v, p);
            if (text(a) != text(b) && bad++ < 10)
                std::printf("%%.%dg of %.17g: %s, expected %s\n", p, v, text(a).c_str(), text(b).c_str());
        }
        {
            // the shortest round-trip text (CSV, JSON floats) against std::to_chars's
            buffer c;
            emit::put_shortest17(c, v);
            char r[48];
            const std::string want(r, std::to_chars(r, r + sizeof r, v).ptr);
            if (text(c) != want && bad++ < 10)
                std::printf("shortest of %.17g: %s, expected %s\n", v, text(c).c_str(), want.c_str());
            // a JSON physical value: %.15g, ".0" after a whole number
            buffer j, g;
            emit::put_json_double(j, v, 15);
            emit::put_g_exact(g, v, 15);
            std::string jwant = text(g);
            if (jwant.find_first_of(".e") == std::string::npos) jwant += ".0";
            if (text(j) != jwant && bad++ < 10)
                std::printf("JSON value of %.17g: %s, expected %s\n", v, text(j).c_str(), jwant.c_str());
        }
        buffer a, b;
        emit::put_g_tidy(a, v, 6);
        emit::put_g_exact(b, emit::tidy(v), 6);
        if (text(a) != text(b) && bad++ < 10)
            std::printf("%%.6g of tidy(%.17g): %s, expected %s\n", v, text(a).c_str(), text(b).c_str());
        ++n;
    };
    const double scales[] = {0.015, 0.488, 0.1, 0.01, 100.0 / 127, 0.5, 1.0 / 16, 0.001, 3.3, 0.0625};
    for (const double sc : scales)
        for (long r = -70000; r <= 70000; ++r) check(static_cast<double>(r) * sc + ((r & 1) ? 0.0 : 9.0));
    for (long i = -3000000; i <= 3000000; i += 7) {
        check(static_cast<double>(i));
        check(static_cast<double>(i) * 1e9);
        check(static_cast<double>(i) * 1e10 + 0.5);
    }
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1e6, 1e6);
    for (int i = 0; i < 500000; ++i) check(u(rng));
    for (int i = 0; i < 500000; ++i) {
        const std::uint64_t b = rng();
        double d;
        std::memcpy(&d, &b, sizeof d);
        if (std::isfinite(d)) check(d);
    }
    // floats (CSV and JSON write them as doubles): random ones, and short decimals
    std::uniform_real_distribution<float> uf(-1e4f, 1e4f);
    for (int i = 0; i < 300000; ++i) check(static_cast<double>(uf(rng)));
    for (int i = -200000; i <= 200000; ++i) check(static_cast<double>(static_cast<float>(i) / 64.0f));
    for (const double v : {1e6, 1e7, 1e14, 123e5, 0.001, 0.0015, 0.00015, 1e-7, 1.5e-7, 2e21, 1e100,
                           0.5, -2.5, 12.75})
        check(v);
    for (const double v : {0.0, -0.0, 1e15, 1e16, 999999.5, 9.9999995, 0.0001, 0.00001, 123456789012345678.0, 5e-324,
                           1.7976931348623157e308})
        check(v);
    std::printf("%ld values, %ld differ\n", n, bad);
    return bad != 0;
}
