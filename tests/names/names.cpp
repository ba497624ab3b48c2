// Every name in the protocols' tables is the C++ name it stands for: a
// table's name is its type's, a field's its member's, an enum entry's its
// enumerator's. The C++ names come from the compiler (the pretty name of a
// function template instantiated for the type, member pointer or
// enumerator), not from parsing the headers. The tables are reached from
// each protocol's list of messages (their records and enums with them) and
// osp::frame, the one table outside a list.
#include <robowire/robowire.hpp>

#include <catch2/catch.hpp>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

using namespace robowire;

namespace {

// The trailing identifier of s: "&robowire::navbot::maneuver::roll" -> "roll".
constexpr std::string_view last_identifier(std::string_view s) {
    std::size_t i = s.size();
    while (i > 0) {
        const char c = s[i - 1];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) break;
        --i;
    }
    return s.substr(i);
}
// g++: "constexpr const char* {anonymous}::pretty() [with auto V = &robowire::navbot::maneuver::roll]";
// clang++: "const char *(anonymous namespace)::pretty() [V = &robowire::navbot::maneuver::roll]".
template <auto V>
constexpr const char* pretty() { return __PRETTY_FUNCTION__; }
template <class T>
constexpr const char* pretty() { return __PRETTY_FUNCTION__; }
constexpr std::string_view argument_name(std::string_view pretty_name) {
    return last_identifier(pretty_name.substr(0, pretty_name.rfind(']')));
}
// The C++ name of a member (from a member pointer) or enumerator, and of a type.
template <auto V>
constexpr std::string_view cxx_name = argument_name(pretty<V>());
template <class T>
constexpr std::string_view cxx_type_name = argument_name(pretty<T>());

static_assert(cxx_name<&navbot::maneuver::ball_x> == "ball_x");
static_assert(cxx_name<navbot::switch_d::ball_poise> == "ball_poise");
static_assert(cxx_type_name<osp::obp1::voltage> == "voltage");

template <class M, class Fn>
constexpr void each_name(Fn& fn);
template <class E, class Fn>
constexpr void each_enum_name(Fn& fn) {
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        (fn(cxx_type_name<E>, enum_table_v<E>[K].name, cxx_name<enum_table_v<E>[K].value>), ...);
    }(std::make_index_sequence<enum_table_v<E>.size()>{});
}
template <class M, std::size_t I, class Fn>
constexpr void each_field_name(Fn& fn) {
    constexpr const auto& f = table_v<M>.fields.template get<I>();
    using F = std::remove_cvref_t<decltype(f)>;
    constexpr auto member = f.member;
    fn(table_v<M>.name, f.name, cxx_name<member>);
    if constexpr (F::is_enum) each_enum_name<typename F::element_type>(fn);
    else if constexpr (F::kind == wire_kind::record) each_name<typename F::element_type>(fn);
}
// fn(where, name, C++ name) for M's table, its fields, and the records and
// enums they hold.
template <class M, class Fn>
constexpr void each_name(Fn& fn) {
    fn(std::string_view("table"), table_v<M>.name, cxx_type_name<M>);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (each_field_name<M, I>(fn), ...);
    }(std::make_index_sequence<table_v<M>.field_count>{});
}
template <class... M, class Fn>
constexpr void each_name(std::type_identity<std::variant<M...>>, Fn& fn) {
    (each_name<M>(fn), ...);
}

// Every list of messages, and osp::frame.
template <class Fn>
constexpr void each_protocol_name(Fn& fn) {
    each_name(std::type_identity<buwizz3::command>{}, fn);
    each_name(std::type_identity<buwizz3::notification>{}, fn);
    each_name(std::type_identity<navbot::message>{}, fn);
    each_name(std::type_identity<osp::message>{}, fn);
    each_name<osp::frame>(fn);
}

struct counts {
    std::size_t names = 0, differ = 0;
};
constexpr counts name_counts() {
    counts c;
    auto fn = [&](std::string_view, std::string_view name, std::string_view cxx) {
        ++c.names;
        c.differ += name != cxx;
    };
    each_protocol_name(fn);
    return c;
}

// The first name that differs, as "where: name != C++ name" (all zero if none).
struct difference {
    char text[120]{};
};
constexpr difference first_difference() {
    difference d;
    std::size_t n = 0;
    auto fn = [&](std::string_view where, std::string_view name, std::string_view cxx) {
        if (n != 0 || name == cxx) return;
        for (std::string_view part : {where, std::string_view(": "), name, std::string_view(" != "), cxx})
            for (char c : part)
                if (n + 1 < sizeof d.text) d.text[n++] = c;
    };
    each_protocol_name(fn);
    return d;
}
// Complete only for no difference: otherwise the compile error shows the
// type, with the text of the first difference (g++ as a string, clang++ as codes).
template <difference D>
struct table_name_differs_from_cxx_name;
template <>
struct table_name_differs_from_cxx_name<difference{}> {};
static_assert(sizeof(table_name_differs_from_cxx_name<first_difference()>) > 0);

// errc_table: each row's name is its code's enumerator, and the value after
// the last row is no enumerator (an errc added without its row: the pretty
// name of a value that is no enumerator is "(robowire::errc)N").
template <std::size_t... I>
constexpr bool errc_names_match(std::index_sequence<I...>) {
    return ((errc_table[I].name == cxx_name<errc_table[I].code>) && ...);
}
constexpr bool is_enumerator_name(std::string_view s) { return !s.empty() && !(s[0] >= '0' && s[0] <= '9'); }
static_assert(cxx_name<errc::not_handled> == "not_handled");
static_assert(!is_enumerator_name(cxx_name<static_cast<errc>(1000)>));

}  // namespace

TEST_CASE("errc_table names every error code, and no code lacks a row", "[names]") {
    STATIC_REQUIRE(errc_names_match(std::make_index_sequence<errc_count>{}));
    STATIC_REQUIRE(!is_enumerator_name(cxx_name<static_cast<errc>(errc_count)>));
    STATIC_REQUIRE(errc_count == 20);  // ok .. not_handled
}

TEST_CASE("table, field and enum names are the C++ names they stand for", "[names]") {
    STATIC_REQUIRE(name_counts().differ == 0);
    // 42 tables, 91 fields, 32 enum entries; records once per message that holds them
    STATIC_REQUIRE(name_counts().names >= 42 + 91 + 32);
    CHECK(name_counts().differ == 0);
}
