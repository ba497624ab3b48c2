// robowire/core/encode.hpp - encode a message to bytes, driven by its table.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>

#include "bytes.hpp"
#include "detail/encode.hpp"
#include "result.hpp"
#include "table.hpp"

namespace robowire {

namespace detail::inline ROBOWIRE_MODE_NAMESPACE {
// The first of m's fields that fails its check (m fails one).
template <described M>
ROBOWIRE_COLD constexpr error field_error(const M& m) noexcept {
    error err{};
    (void)check_record<M>(m, 0, err, std::make_index_sequence<field_count_v<M>>{});
    return err;
}
// Sets an encoder's `written`: a size, or a bytes<N>'s size.
constexpr void set_written(std::size_t& written, std::size_t n) noexcept { written = n; }
template <std::size_t N>
constexpr void set_written(bytes<N>& written, std::size_t n) noexcept {
    codec::set_written_size(written, n);
}
#if ROBOWIRE_SSE2
// The window of M's encode plan that m's loads use (plan_fits: 0 or 1), when
// its members lie as their wire bytes, base bytes on; else 2. (Constants
// once inlined.)
template <described M>
ROBOWIRE_ALWAYS_INLINE std::size_t member_window(const M& m, std::size_t& base) noexcept {
    constexpr const lane_plan& p = lanes_v<M, true>;
    const auto obj = reinterpret_cast<const unsigned char*>(&m);
    base = offset_in(obj, &(m.*(field_v<M, p.anchor>.member))) - p.first;
    const std::size_t w = plan_fits(p, base, sizeof(M));
    return w < 2 && members_as_wire<M, p.mirror>(m, base, std::make_index_sequence<field_count_v<M>>{}) ? w : 2;
}
// The D offset of the output's first wire byte (image_of): 1 for a bytes<N>
// (its size byte first), written through its object.
template <class Written>
inline constexpr std::size_t lead_v = 0;
template <std::size_t N>
inline constexpr std::size_t lead_v<bytes<N>> = bytes<N>::size_byte_then_data() ? 1 : 0;
// encode_into for a message whose frame is image_v<M, W, Lead>: the test,
// then the frame from the test's register.
template <described M, std::size_t W, std::size_t Lead, class Written>
ROBOWIRE_ALWAYS_INLINE error encode_image(const M& m, std::size_t base, std::uint8_t* out_data, std::size_t out_size,
                                          Written& written) noexcept {
    constexpr const lane_plan& p = lanes_v<M, true>;
    const lane_bytes x = lanes_load<p, W>(reinterpret_cast<const unsigned char*>(&m), base);
    if (!lanes_test<p, W>(x)) [[unlikely]]
        return field_error(m);
    if (max_size_v < M >> out_size) return codec::fail_at(errc::buffer_too_small, max_size_v<M>);
    constexpr auto lanes = std::make_index_sequence<16>{};
    if constexpr (Lead != 0) {  // the size byte in the image: out_data is written.data()
        store_image<image_v<M, W, Lead>>(reinterpret_cast<unsigned char*>(&written), x, lanes);
    } else {
        store_image<image_v<M, W, Lead>>(out_data, x, lanes);
        set_written(written, max_size_v<M>);
    }
    return error{};
}
#endif
}  // namespace detail::inline ROBOWIRE_MODE_NAMESPACE

namespace codec::inline ROBOWIRE_MODE_NAMESPACE {
// Checks M's fields in m (ranges, enums, text without NUL), in table order:
// false at the first error, which is stored in err. Pair with store_fields.
template <described M>
ROBOWIRE_ALWAYS_INLINE constexpr bool check_fields(const M& m, error& err) noexcept {
    constexpr auto fields = std::make_index_sequence<detail::field_count_v<M>>{};
    if constexpr (detail::copy_then_check_v<M>) {  // the function decode checks M with
        if (!ROBOWIRE_CONSTANT_EVALUATED()) {
            err = detail::check_members(m);
            return err.code == errc::ok;
        }
    }
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {
        return detail::check_record<M>(m, 0, err, fields);
    } else {             // as one yes/no; which one failed, out of line: no error set up on the good path
        error ignore{};  // its stores are dead: dropped
#if ROBOWIRE_SSE2
        if constexpr (detail::field_count_v<M> >= detail::lanes_min_fields) {
            if constexpr (detail::lanes_v<M, true>.use) {  // the one-byte fields' ranges as one vector test
                if (!ROBOWIRE_CONSTANT_EVALUATED()) {
                    constexpr const detail::lane_plan& p = detail::lanes_v<M, true>;
                    const auto obj = reinterpret_cast<const unsigned char*>(&m);
                    std::size_t base = 0;
                    const std::size_t w = detail::member_window(m, base);
                    if (w < 2) {
                        bool valid = false;
                        if constexpr (p.win[1].loads != 0)
                            valid = w == 0 ? detail::plan_valid<p, 0>(obj, base) : detail::plan_valid<p, 1>(obj, base);
                        else valid = detail::plan_valid<p, 0>(obj, base);
                        if (valid &&
                            detail::check_record<M>(
                                m, 0, ignore,
                                detail::kept_fields_t<detail::lanes_v<M, true>.covered, detail::field_count_v<M>>{}))
                            [[likely]]
                            return true;
                        err = detail::field_error(m);
                        return false;
                    }
                }
            }
        }
#endif
        if (detail::check_record<M>(m, 0, ignore, fields)) [[likely]]
            return true;
        err = detail::field_error(m);
        return false;
    }
}
// Writes M's fields of m, checked by check_fields, into `out` (at least
// max_size_v<M> bytes; fixed and reserved bytes are not written).
template <described M>
ROBOWIRE_ALWAYS_INLINE constexpr void store_fields(const M& m, std::span<std::uint8_t> out) noexcept {
    detail::store_record<M>(m, out, 0, std::make_index_sequence<detail::field_count_v<M>>{});
}
}  // namespace codec::inline ROBOWIRE_MODE_NAMESPACE

namespace detail::inline ROBOWIRE_MODE_NAMESPACE {
// Encodes m into out_data (at most out_size bytes) and sets `written`: the
// error, if any, is returned in a register and the output is left unchanged.
// Pointer and size, not a span: a span passed on by value from an inlined
// caller is copied through the stack first.
template <described M, class Written>
constexpr error encode_into(const M& m, std::uint8_t* out_data, std::size_t out_size, Written& written) noexcept {
#if ROBOWIRE_SSE2
    if constexpr (!ROBOWIRE_OPTIMIZE_SIZE && field_count_v<M> >= lanes_min_fields && min_size_v<M> == max_size_v<M>) {
        if constexpr (lanes_v<M, true>.use &&
                      (image_v<M, 0, lead_v<Written>>.use || image_v<M, 1, lead_v<Written>>.use)) {
            if (!ROBOWIRE_CONSTANT_EVALUATED()) {  // the frame from the test's register
                std::size_t base = 0;
                const std::size_t w = member_window(m, base);
                if constexpr (image_v<M, 0, lead_v<Written>>.use)
                    if (w == 0) return encode_image<M, 0, lead_v<Written>>(m, base, out_data, out_size, written);
                if constexpr (image_v<M, 1, lead_v<Written>>.use)
                    if (w == 1) return encode_image<M, 1, lead_v<Written>>(m, base, out_data, out_size, written);
            }
        }
    }
#endif
    const out_bytes out(out_data, out_size);  // (no std::span<std::uint8_t> built: less to compile)
    constexpr auto fields = std::make_index_sequence<field_count_v<M>>{};
    auto size = encoded_size(m, fields);
    if (!size) return codec::unchecked_error(size);
    if (error err{}; !codec::check_fields(m, err)) return err;
    if (codec::unchecked_value(size) > out.size())
        return codec::fail_at(errc::buffer_too_small, codec::unchecked_value(size));
    const auto dst = out.first(codec::unchecked_value(size));
    // The size first: next to the first byte, which is often fixed; their stores join.
    set_written(written, codec::unchecked_value(size));
    clear_bytes<M>(dst);
    write_fixed<M>(dst, std::make_index_sequence<fixed_count_v<M>>{});
    if constexpr (sizeof(M) > 16 && !ROBOWIRE_OPTIMIZE_SIZE && !ROBOWIRE_COPY_RUNS) {  // (runs: copied at once)
        const M copy =
            m;  // a local cannot alias `out`: its loads need not wait behind byte stores, so wide fields merge
        store_record<M>(copy, dst, 0, fields);
    } else {
        store_record<M>(m, dst, 0, fields);  // a few bytes: copied as they are
    }
    return error{};
}
}  // namespace detail::inline ROBOWIRE_MODE_NAMESPACE

inline namespace ROBOWIRE_MODE_NAMESPACE {

// Encodes m into a caller's buffer (e.g. the radio's transmit buffer);
// returns the number of bytes written. Errors as for encode(), then
// buffer_too_small; on an error `out` is unchanged.
template <described M>
[[nodiscard]] constexpr result<std::size_t> encode_to(const M& m, std::span<std::uint8_t> out) noexcept {
    std::size_t n = 0;
    if (const error e = detail::encode_into(m, out.data(), out.size(), n); e.code != errc::ok) return e;
    return n;
}

// Encodes m; out-of-range values and invalid enums are errors (never truncated).
template <described M>
[[nodiscard]] constexpr result<bytes<max_size_v<M>>> encode(const M& m) noexcept {
    using out_t = bytes<max_size_v<M>>;
    // A message of one size writes every byte (cleared, then fields): nothing to clear first.
    using init = std::conditional_t<min_size_v<M> == max_size_v<M>, codec::unset_t, out_t>;
    result<out_t> r{std::in_place, init{}};
    auto& b = codec::unchecked_value(r);
    if (const error e = detail::encode_into(m, b.data(), max_size_v<M>, b); e.code != errc::ok) r = e;
    return r;
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

}  // namespace robowire
