// robowire/core/detail/traits.hpp - internal: what a field's member type is
// (optional, array, text, bytes) and whether it fits its wire type.
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

#include "../bits.hpp"
#include "../bytes.hpp"
#include "../text.hpp"
#include "../wire.hpp"

namespace robowire {

namespace detail {
template <class T>
struct optional_traits {
    static constexpr bool value = false;
    using type = T;
};
template <class T>
struct optional_traits<std::optional<T>> {
    static constexpr bool value = true;
    using type = T;
};
template <class T>
struct array_traits {
    static constexpr std::size_t count = 1;
    using element = T;
    static constexpr bool value = false;
};
template <class T, std::size_t N>
struct array_traits<std::array<T, N>> {
    static constexpr std::size_t count = N;
    using element = T;
    static constexpr bool value = true;
};
template <class T>
struct text_traits {
    static constexpr std::size_t size = 0;
};
template <std::size_t N>
struct text_traits<robowire::text<N>> {
    static constexpr std::size_t size = N;
};
template <class T>
struct bytes_traits {
    static constexpr std::size_t size = 0;
};
template <std::size_t N>
struct bytes_traits<robowire::bytes<N>> {
    static constexpr std::size_t size = N;
};

template <class T>
using value_t = typename optional_traits<T>::type;  // optional<X> -> X
template <class T>
using element_t = typename array_traits<value_t<T>>::element;  // array<E,N> -> E

template <class W, class E>
constexpr std::size_t element_size() noexcept {
    if constexpr (W::kind == wire_kind::bits) return 1;
    else if constexpr (W::kind == wire_kind::text) return text_traits<E>::size;
    else if constexpr (W::kind == wire_kind::tail) return 0;
    else if constexpr (W::kind == wire_kind::record)
        return table_of(std::type_identity<E>{}).max_size();  // found by ADL
    else return sizeof(typename W::raw_type);
}

template <class W, class E>
constexpr range default_range() noexcept {
    if constexpr (std::is_same_v<E, bool>) return {0, 1};
    else if constexpr (W::kind == wire_kind::bits) return {0, low_mask(W::width)};
    else if constexpr (W::kind == wire_kind::text || W::kind == wire_kind::tail || W::kind == wire_kind::record ||
                       W::kind == wire_kind::f32le)
        return {0, 0};
    else {
        using R = typename W::raw_type;
        return {std::numeric_limits<R>::min(), std::numeric_limits<R>::max()};
    }
}

template <class W, class E>
constexpr bool wire_fits() noexcept {
    if constexpr (W::kind == wire_kind::text) return text_traits<E>::size > 0;
    else if constexpr (W::kind == wire_kind::tail) return bytes_traits<E>::size > 0;
    else if constexpr (W::kind == wire_kind::record) return std::is_class_v<E>;
    else if constexpr (W::kind == wire_kind::bits) return std::is_enum_v<E> || std::is_unsigned_v<E>;
    else if constexpr (W::kind == wire_kind::f32le) return std::is_same_v<E, float>;
    else if constexpr (std::is_enum_v<E> || std::is_same_v<E, bool>) return sizeof(typename W::raw_type) == 1;
    else
        return std::is_integral_v<E> && std::is_signed_v<E> == std::is_signed_v<typename W::raw_type> &&
               sizeof(E) >= sizeof(typename W::raw_type);
}
}  // namespace detail

}  // namespace robowire
