#include <robowire/core/result.hpp>

#include <array>
#include <catch2/catch.hpp>

using namespace robowire;

namespace {
constexpr result<int> half(int x) {
    if (x % 2) return fail(errc::value_out_of_range, 3);
    return x / 2;
}
}  // namespace

TEST_CASE("result<T> holds a value or an error with an offset", "[core][result]") {
    STATIC_REQUIRE(half(8).value() == 4);
    STATIC_REQUIRE(*half(8) == 4);
    STATIC_REQUIRE(half(8).has_value());
    STATIC_REQUIRE(!half(7));
    STATIC_REQUIRE(half(7).error() == error{errc::value_out_of_range, 3});
    STATIC_REQUIRE(half(7).code() == errc::value_out_of_range);
    STATIC_REQUIRE(half(8).code() == errc::ok);
    STATIC_REQUIRE(half(7).value_or(-1) == -1);
    const auto r = half(7);
    CHECK_FALSE(r);
    CHECK(r.error().offset == 3);
    CHECK(to_string(errc::too_short) == "input too short");
    // a temporary's value is returned by value: safe to iterate
    int sum = 0;
    for (int x : result<std::array<int, 3>>(std::array<int, 3>{1, 2, 3}).value()) sum += x;
    CHECK(sum == 6);
    CHECK(to_string(errc::bad_trailer) == "bad trailer byte");
}
