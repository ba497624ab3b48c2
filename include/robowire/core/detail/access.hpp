// robowire/core/detail/access.hpp - internal: a table's fields and fixed
// bytes as compile-time constants, for the encoder and the decoder.
#pragma once

#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>

#include "../table.hpp"

namespace robowire::detail {

template <class M>
concept reports_trailing = requires(M m) { m.ignored_trailing_bytes = std::size_t{}; };

// Field I of M's table, as a compile-time constant.
template <class M, std::size_t I>
inline constexpr const auto& field_v = std::get<I>(table_v<M>.fields);
template <class M>
inline constexpr std::size_t field_count_v = std::tuple_size_v<std::remove_cvref_t<decltype(table_v<M>.fields)>>;
template <class M, std::size_t I>
using field_t = std::remove_cvref_t<decltype(field_v<M, I>)>;
template <class M>
inline constexpr std::size_t fixed_count_v = table_v<M>.fixed.size();

// An array of bytes that needs no validation: copied whole (one memcpy at run time).
template <class M, std::size_t I>
inline constexpr bool plain_byte_array_v = [] {
    using F = field_t<M, I>;
    using E = typename F::element_type;
    if constexpr (!F::is_array || F::count < 4 || std::is_enum_v<E> || std::is_same_v<E, bool> || sizeof(E) != 1 ||
                  !std::is_integral_v<E>) {
        return false;
    } else if constexpr (F::kind != wire_kind::u8 && F::kind != wire_kind::i8) {
        return false;
    } else {
        return field_v<M, I>.valid.min == std::numeric_limits<E>::min() &&
               field_v<M, I>.valid.max == std::numeric_limits<E>::max();
    }
}();

}  // namespace robowire::detail
