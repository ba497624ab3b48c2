// robowire/core/detail/field_list.hpp - internal: the fields of a table, a
// minimal tuple (get<I>, each, apply) that costs less to compile than std::tuple.
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <cstddef>
#include <utility>

namespace robowire::detail {

template <std::size_t I, class F>
struct field_slot {
    F value;
};

template <class Indices, class... F>
struct field_list_base;
template <std::size_t... I, class... F>
struct field_list_base<std::index_sequence<I...>, F...> : field_slot<I, F>... {};

template <std::size_t I, class F>
constexpr const F& slot_of(const field_slot<I, F>& s) noexcept {
    return s.value;
}

// Fields F... in table order.
template <class... F>
struct field_list : field_list_base<std::index_sequence_for<F...>, F...> {
    static constexpr std::size_t size = sizeof...(F);

    constexpr explicit field_list(const F&... f) noexcept
        : field_list_base<std::index_sequence_for<F...>, F...>{{f}...} {}

    // Field I.
    template <std::size_t I>
    constexpr const auto& get() const noexcept {
        return slot_of<I>(*this);
    }
    // fn(field) for each field, in order.
    template <class Fn>
    constexpr void each(Fn&& fn) const {
        apply([&](const F&... f) { (fn(f), ...); });
    }
    // fn(fields...).
    template <class Fn>
    constexpr decltype(auto) apply(Fn&& fn) const {
        return apply_impl(fn, std::index_sequence_for<F...>{});
    }

private:
    template <class Fn, std::size_t... I>
    constexpr decltype(auto) apply_impl(Fn& fn, std::index_sequence<I...>) const {
        return fn(slot_of<I>(*this)...);
    }
};

}  // namespace robowire::detail
