// Test helpers driven by a protocol's variant (its one list of messages):
// fill a message's fields with small non-zero values, so per-message loops
// (robowire::for_each_alternative, reflect.hpp) need no hand list.
#pragma once

#include <robowire/core.hpp>
#include <robowire/reflect.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

namespace test {

template <class M>
constexpr void fill(M& m, unsigned& k);

// One value moved off its default: integers by 1..3, floats by 0.5 * k, bools
// set, enums to the next code; text and byte strings keep their default.
template <class E>
constexpr void fill_element(E& v, unsigned& k) {
    if constexpr (std::is_same_v<E, bool>) {
        v = true;
    } else if constexpr (std::is_enum_v<E>) {
        using U = std::underlying_type_t<E>;
        v = static_cast<E>(static_cast<U>(static_cast<U>(v) + 1));  // the next code, if the message takes it
    } else if constexpr (std::is_floating_point_v<E>) {
        v = v + static_cast<E>(++k) / 2;
    } else if constexpr (std::is_integral_v<E>) {
        v = static_cast<E>(v + static_cast<E>(++k % 3 + 1));
    } else if constexpr (requires { v.capacity(); }) {  // text<N>, bytes<N>
    } else {
        fill(v, k);  // a record with a table of its own
    }
}

// One field of m: optional fields made present, arrays filled element by element.
template <class F, class M>
constexpr void fill_field(const F& f, M& m, unsigned& k) {
    auto& member = m.*f.member;
    if constexpr (F::is_optional) {
        auto& v = member.emplace();
        if constexpr (F::is_array) {
            for (auto& e : v) fill_element(e, k);
        } else {
            fill_element(v, k);
        }
    } else if constexpr (F::is_array) {
        for (auto& e : member) fill_element(e, k);
    } else {
        fill_element(member, k);
    }
}

template <class M>
constexpr void fill(M& m, unsigned& k) {
    robowire::for_each_field<M>([&](const auto& f) { fill_field(f, m, k); });
}

// M with every field moved off its default, field by field, keeping each
// change only while the message still encodes (so documented ranges hold).
template <class M>
constexpr M filled() {
    M m{};
    unsigned k = 0;
    robowire::for_each_field<M>([&](const auto& f) {
        M next = m;
        fill_field(f, next, k);
        if (robowire::encode(next)) m = next;
    });
    return m;
}

}  // namespace test
