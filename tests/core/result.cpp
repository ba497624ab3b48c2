#include <robowire/core/result.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <csetjmp>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

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

namespace {
// Row i of errc_table is the code whose value is i (to_string and name_of index it).
constexpr bool errc_table_in_order() {
    for (std::size_t i = 0; i < errc_count; ++i)
        if (static_cast<std::size_t>(errc_table[i].code) != i) return false;
    return true;
}
}  // namespace

TEST_CASE("to_string and name_of read errc_table", "[core][result]") {
    STATIC_REQUIRE(errc_table_in_order());
    STATIC_REQUIRE(to_string(errc::not_handled) == "message not handled");
    STATIC_REQUIRE(name_of(errc::not_handled) == "not_handled");
    STATIC_REQUIRE(name_of(errc::bad_json) == "bad_json");
    STATIC_REQUIRE(to_string(static_cast<errc>(20)) == "unknown error");
    STATIC_REQUIRE(name_of(static_cast<errc>(20)) == "unknown_error");
    // every text distinct: a log line names one code
    for (std::size_t i = 0; i < errc_count; ++i)
        for (std::size_t j = i + 1; j < errc_count; ++j) {
            CHECK(errc_table[i].text != errc_table[j].text);
            CHECK(errc_table[i].name != errc_table[j].name);
        }
}

namespace {
struct meters {
    int value = -1;
    constexpr explicit meters(int v) noexcept : value(v) {}
};
struct may_throw {
    explicit may_throw(int) {}
};
}  // namespace

TEST_CASE("result(std::in_place, arg) holds T(arg)", "[core][result]") {
    STATIC_REQUIRE(result<meters>(std::in_place, 42).value().value == 42);
    STATIC_REQUIRE(result<meters>(std::in_place, 42).has_value());
    STATIC_REQUIRE(std::is_nothrow_constructible_v<result<meters>, std::in_place_t, int>);
    STATIC_REQUIRE(!std::is_nothrow_constructible_v<result<may_throw>, std::in_place_t, int>);
    const result<meters> r(std::in_place, 7);
    CHECK(r->value == 7);
}

TEST_CASE("error converts to bool like std::error_code", "[core][result]") {
    STATIC_REQUIRE(!error{});
    STATIC_REQUIRE(static_cast<bool>(error{errc::too_short, 0}));
    STATIC_REQUIRE(static_cast<bool>(fail(errc::bad_json, 9)));
    STATIC_REQUIRE(!std::is_convertible_v<error, bool>);  // explicit: no accidental arithmetic
    int seen = 0;
    if (auto e = half(7).error()) seen = static_cast<int>(e.offset);
    CHECK(seen == 3);
}

TEST_CASE("error is four bytes; offsets past 65535 read 65535", "[core][result]") {
    STATIC_REQUIRE(sizeof(error) == 4);  // returned in a register on 32-bit cores
    STATIC_REQUIRE(fail(errc::bad_json, 65534).offset == 65534);
    STATIC_REQUIRE(fail(errc::bad_json, 65535).offset == 65535);
    STATIC_REQUIRE(fail(errc::bad_json, 65536).offset == 65535);
    volatile std::size_t far = 1000000;
    CHECK(fail(errc::bad_json, far).offset == 65535);
}

#if defined(__cpp_exceptions)
TEST_CASE("value() of an error throws bad_result_access", "[core][result]") {
    STATIC_REQUIRE(std::is_base_of_v<std::exception, bad_result_access>);
    STATIC_REQUIRE(!noexcept(std::declval<const result<int>&>().value()));
    const auto r = half(7);
    bool thrown = false;
    try {
        (void)r.value();
    } catch (const bad_result_access& e) {
        thrown = true;
        CHECK(std::string_view(e.what()) == "robowire: value() of a result that holds an error: value out of range at byte 3");
        CHECK(e.error() == error{errc::value_out_of_range, 3});
    }
    CHECK(thrown);
    CHECK_THROWS_AS(*r, bad_result_access);
    CHECK_THROWS_AS(half(8).error(), bad_result_access);
    CHECK_THROWS_WITH(half(8).error(), "robowire: error() of a result that holds a value");
    // the longest code text and a large offset still fit the fixed buffer
    const bad_result_access big(error{errc::missing_field, 65535});
    CHECK(std::string_view(big.what()) ==
          "robowire: value() of a result that holds an error: optional block present without the one before it "
          "at byte 65535");
}
#else
// The noexcept test target is built with -DROBOWIRE_BAD_RESULT_ACCESS_HANDLER=test_bad_result_access.
namespace {
std::jmp_buf handler_jump;
error handled{};
int read_value(const result<int>& r) { return r.value(); }
}  // namespace

void test_bad_result_access(robowire::error e) noexcept {
    handled = e;
    std::longjmp(handler_jump, 1);
}

TEST_CASE("without exceptions value() of an error calls the handler", "[core][result]") {
    STATIC_REQUIRE(noexcept(std::declval<const result<int>&>().value()));
    const auto r = half(7);
    int got = 0;
    if (setjmp(handler_jump) == 0) got = read_value(r);
    CHECK(got == 0);
    CHECK(handled == error{errc::value_out_of_range, 3});
}
#endif
