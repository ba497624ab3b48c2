// robowire/core/encode.hpp - encode a message to bytes, driven by its table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

#include "bytes.hpp"
#include "detail/encode.hpp"
#include "result.hpp"
#include "table.hpp"

namespace robowire {


// Encodes m into a caller's buffer (e.g. the radio's transmit buffer);
// returns the number of bytes written. Errors as for encode(), then
// buffer_too_small; on an error `out` is unchanged.
template <described M>
[[nodiscard]] constexpr result<std::size_t> encode_to(const M& m, std::span<std::uint8_t> out) noexcept {
    constexpr auto fields = std::make_index_sequence<detail::field_count_v<M>>{};
    const auto size = detail::encoded_size(m, fields);
    if (!size) return detail::held_error(size);
    error err{};
    if (!detail::check_record<M>(m, 0, err, fields)) return err;
    if (*size > out.size()) return detail::fail_at(errc::buffer_too_small, *size);
    const auto dst = out.first(*size);
    detail::clear_bytes<M>(dst);
    detail::write_fixed<M>(dst, std::make_index_sequence<detail::fixed_count_v<M>>{});
    if constexpr (sizeof(M) > 16 && !ROBOWIRE_OPTIMIZE_SIZE) {
        const M copy = m;  // a local cannot alias `out`: its loads need not wait behind byte stores, so wide fields merge
        detail::store_record<M>(copy, dst, 0, fields);
    } else {
        detail::store_record<M>(m, dst, 0, fields);  // a few bytes: copied as they are
    }
    return *size;
}

// Encodes m; out-of-range values and invalid enums are errors (never truncated).
template <described M>
[[nodiscard]] constexpr result<bytes<max_size_v<M>>> encode(const M& m) noexcept {
    result<bytes<max_size_v<M>>> r{std::in_place};
    auto& b = detail::built_value(r);
    auto n = encode_to(m, std::span<std::uint8_t>(b.data(), max_size_v<M>));
    if (!n) { r = detail::held_error(n); return r; }
    detail::set_written_size(b, detail::built_value(n));
    return r;
}

}  // namespace robowire

