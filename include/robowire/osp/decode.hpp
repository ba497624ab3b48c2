// robowire/osp/decode.hpp - decode any OSP frame into a variant (host or
// device side), and serve(): answer requests on a device without heap or
// virtual calls.
#pragma once

#include <optional>
#include <span>
#include <type_traits>
#include <variant>

#include "../core/config.hpp"
#include "../core/dispatch.hpp"
#include "messages.hpp"

namespace robowire::osp {

class decode_result;
// Decodes one 10-byte frame (below). A template, so that nothing is
// instantiated in a translation unit that does not call it.
template <class Message = message>
[[nodiscard]] constexpr decode_result decode(std::span<const std::uint8_t> in) noexcept;

// The result of osp::decode: the message, or an error; frame() holds DEV,
// CMD and P1..P4 whenever the markers and length were right, so an
// unknown_message (or a bad field) still shows what came in.
class decode_result : public result<message> {
public:
    constexpr decode_result(result<message> r, std::optional<osp::frame> f) noexcept
        : result<message>(r), frame_(f) {}
    constexpr explicit decode_result(std::in_place_t) noexcept : result<message>(std::in_place) {}
    using result<message>::operator=;
    constexpr const std::optional<osp::frame>& frame() const noexcept { return frame_; }

private:
    template <class Message>
    friend constexpr decode_result decode(std::span<const std::uint8_t> in) noexcept;
    std::optional<osp::frame> frame_;
};

namespace impl {
// DEV << 8 | CMD of message M (its fixed bytes 2 and 3).
template <class M>
constexpr std::uint16_t key_of() noexcept {
    return static_cast<std::uint16_t>(robowire::detail::key_of<M>(2) << 8 | robowire::detail::key_of<M>(3));
}
// Every alternative of Message has a DEV/CMD pair of its own.
template <class Message, std::size_t... I>
constexpr bool keys_distinct(std::index_sequence<I...>) noexcept {
    constexpr std::uint16_t keys[] = {key_of<std::variant_alternative_t<I, Message>>()...};
    for (std::size_t a = 0; a < sizeof...(I); ++a)
        for (std::size_t b = a + 1; b < sizeof...(I); ++b)
            if (keys[a] == keys[b]) return false;
    return true;
}
// Fixed bytes checked by the frame already: makes the message and decodes its fields in place.
template <std::size_t I>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_message(decode_result& d, std::span<const std::uint8_t> in) noexcept {
    auto& m = robowire::detail::emplace_alternative<I>(*d);
    if (const error e = robowire::detail::decode_fields(m, in); e.code != errc::ok) d = e;
}
template <std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_by_key(decode_result& d, std::uint16_t key, std::span<const std::uint8_t> in,
                                                    std::index_sequence<I...>) noexcept {
    const bool known =
        ((key == key_of<std::variant_alternative_t<I, message>>() ? (decode_message<I>(d, in), true) : false) || ...);
    if (!known) d = fail(errc::unknown_message, 2);
}
}  // namespace impl

// Decodes one 10-byte frame into whichever message its DEV and CMD name.
// Errors: too_short / too_long, bad_header, bad_trailer, unknown_message
// (offset 2), and the message's own field errors.
template <class Message>
[[nodiscard]] constexpr decode_result decode(std::span<const std::uint8_t> in) noexcept {
    static_assert(impl::keys_distinct<Message>(std::make_index_sequence<std::variant_size_v<Message>>{}),
                  "osp::decode: two messages share a DEV/CMD pair (the second could never be decoded)");
    decode_result d{std::in_place};
    std::variant_alternative_t<0, std::variant<osp::frame, Message>> f{};
    if (const error e = robowire::decode_into(f, in); e.code != errc::ok) {
        d = e;
        return d;
    }
    d.frame_ = f;
    impl::decode_by_key(d, static_cast<std::uint16_t>(f.device << 8 | f.command), in,
                          std::make_index_sequence<std::variant_size_v<Message>>{});
    return d;
}

// Encodes any message of the variant. (Not the core encode(variant): that
// copies into a second buffer, which costs Cortex-M code size and stack.)
template <class Message = message>
[[nodiscard]] constexpr result<bytes<frame_size>> encode(const std::type_identity_t<Message>& m) noexcept {
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
