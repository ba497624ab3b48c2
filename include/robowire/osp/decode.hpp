// robowire/osp/decode.hpp - decode any OSP frame into a variant (host or
// device side), and serve(): answer requests on a device without heap or
// virtual calls.
#pragma once

#include <optional>
#include <span>
#include <type_traits>
#include <variant>

#include "messages.hpp"

namespace robowire::osp {

// Every OSP message.
using message = std::variant<generic::request_device_type, generic::device_type, arm1::set_angle, obp1::request_soc,
                             obp1::request_voltage, obp1::request_current, obp1::request_status, obp1::soc,
                             obp1::voltage, obp1::current, obp1::status>;

// The result of osp::decode: the message, or an error; frame() holds DEV,
// CMD and P1..P4 whenever the markers and length were right, so an
// unknown_message (or a bad field) still shows what came in.
class decode_result : public result<message> {
public:
    constexpr decode_result(result<message> r, std::optional<osp::frame> f) noexcept
        : result<message>(std::move(r)), frame_(f) {}
    constexpr const std::optional<osp::frame>& frame() const noexcept { return frame_; }

private:
    std::optional<osp::frame> frame_;
};

namespace detail {
template <class M>
constexpr std::uint16_t key_of() noexcept {
    constexpr const auto& t = table_v<M>;
    return static_cast<std::uint16_t>(t.fixed[2].value << 8 | t.fixed[3].value);
}
template <std::size_t I = 0>
constexpr result<message> decode_by_key(std::uint16_t key, std::span<const std::uint8_t> in) noexcept {
    if constexpr (I == std::variant_size_v<message>) {
        return fail(errc::unknown_message, 2);
    } else {
        using M = std::variant_alternative_t<I, message>;
        if (key == key_of<M>()) {
            auto r = robowire::decode<M>(in);
            if (!r) return r.error();
            return message{std::in_place_index<I>, *r};
        }
        return decode_by_key<I + 1>(key, in);
    }
}
}  // namespace detail

// Decodes one 10-byte frame into whichever message its DEV and CMD name.
// Errors: too_short / too_long, bad_header, bad_trailer, unknown_message
// (offset 2), and the message's own field errors.
[[nodiscard]] constexpr decode_result decode(std::span<const std::uint8_t> in) noexcept {
    const auto f = robowire::decode<osp::frame>(in);
    if (!f) return {f.error(), std::nullopt};
    const auto key = static_cast<std::uint16_t>(f->device << 8 | f->command);
    return {detail::decode_by_key(key, in), *f};
}

// Encodes any message of the variant. (Not the core encode(variant): that
// copies into a second buffer, which costs Cortex-M code size and stack.)
[[nodiscard]] constexpr result<bytes<frame_size>> encode(const message& m) noexcept {
    return std::visit([](const auto& x) -> result<bytes<frame_size>> { return robowire::encode(x); }, m);
}

// Device role. Decodes `request` and calls handler(msg) for the message it
// holds, if the handler accepts that type. The handler returns void (no
// answer), a message (the answer), or std::optional of a message.
// Returns the encoded answer, nullopt when there is none, or an error:
// unknown_message when the frame is valid but the handler does not take it.
template <class Handler>
[[nodiscard]] constexpr result<std::optional<bytes<frame_size>>> serve(std::span<const std::uint8_t> request,
                                                                       Handler&& handler) {
    using answer = std::optional<bytes<frame_size>>;
    const auto d = decode(request);
    if (!d) return d.error();
    return std::visit(
        [&](const auto& msg) -> result<answer> {
            using M = std::remove_cvref_t<decltype(msg)>;
            if constexpr (!std::is_invocable_v<Handler&, const M&>) {
                return fail(errc::unknown_message, 2);
            } else {
                using R = std::invoke_result_t<Handler&, const M&>;
                if constexpr (std::is_void_v<R>) {
                    handler(msg);
                    return answer{};
                } else if constexpr (requires(const R& r) { r.has_value(); *r; }) {
                    const R r = handler(msg);
                    if (!r) return answer{};
                    const auto out = robowire::encode(*r);
                    if (!out) return out.error();
                    return answer{*out};
                } else {
                    const auto out = robowire::encode(handler(msg));
                    if (!out) return out.error();
                    return answer{*out};
                }
            }
        },
        *d);
}

}  // namespace robowire::osp
