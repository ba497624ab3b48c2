// robowire/osp/decode.hpp - decode any OSP frame into a variant (host or
// device side), and serve(): answer requests on a device without heap or
// virtual calls.
#pragma once

#include "../core/config.hpp"  // first: the C++ version check

#include <array>
#include <bit>
#include <cstring>
#include <new>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>

#include "../core/dispatch.hpp"
#include "../core/fields.hpp"
#include "messages.hpp"

namespace robowire::osp {

namespace impl {
template <class Message>
class decode_result_of;
// osp::message, named through template arguments: where the name does not
// depend on one, the compilers instantiate what it names (the variant,
// decode_result, every OSP table) in each file that includes this header.
template <auto...>
struct dependent_message {
    using type = message;
};
// osp::decode_result, named through template arguments (see dependent_message).
template <auto... X>
using decode_result_t = decode_result_of<typename dependent_message<X...>::type>;
template <class M>
constexpr void set_frame(decode_result_of<M>& d, const osp::frame* f) noexcept;
template <class M>
constexpr osp::frame& frame_in_place(decode_result_of<M>& d) noexcept;
}  // namespace impl
// The result of osp::decode (below). A template instance: a file that only
// includes this header instantiates neither it nor osp::message.
using decode_result = impl::decode_result_of<message>;
inline namespace ROBOWIRE_MODE_NAMESPACE {
// Decodes one 10-byte frame (below) into an osp::decode_result. A template,
// so that nothing is instantiated in a translation unit that does not call it.
template <class Message = message>
[[nodiscard]] constexpr impl::decode_result_t<sizeof(Message)> decode(std::span<const std::uint8_t> in) noexcept;
}  // namespace ROBOWIRE_MODE_NAMESPACE

// osp::decode_result: the message, or an error; frame() holds DEV, CMD and
// P1..P4 whenever the markers and length were right, so an unknown_message
// (or a bad field) still shows what came in.
template <class Message>
class impl::decode_result_of : public result<Message> {
public:
    constexpr decode_result_of(result<Message> r, std::optional<osp::frame> f) noexcept
        : result<Message>(r), frame_(f) {}
    constexpr explicit decode_result_of(std::in_place_t) noexcept
        : result<Message>(std::in_place), frame_(std::nullopt) {}
    // Neither a message nor an error yet (see result's constructor), and not
    // even "no frame": for osp::decode, which sets both on every path.
    constexpr explicit decode_result_of(codec::unset_t u) noexcept : result<Message>(u) {}
    using result<Message>::operator=;
    constexpr const std::optional<osp::frame>& frame() const noexcept { return frame_.f; }

private:
    template <class M>
    friend constexpr void impl::set_frame(decode_result_of<M>& d, const osp::frame* f) noexcept;
    template <class M>
    friend constexpr osp::frame& impl::frame_in_place(decode_result_of<M>& d) noexcept;
    union slot {  // a union: the unset constructor makes no store
        std::optional<osp::frame> f;
        constexpr slot() noexcept {}  // nothing yet
        constexpr slot(std::nullopt_t) noexcept : f() {}
        constexpr slot(const std::optional<osp::frame>& x) noexcept : f(x) {}
    };
    slot frame_;
};
// Makes d's frame *f, or none for nullptr, whatever it held (also nothing, after decode_result(unset_t)).
template <class M>
constexpr void impl::set_frame(decode_result_of<M>& d, const osp::frame* f) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) {  // a whole-union copy makes the member the active one
        d.frame_ = f ? std::optional<osp::frame>(std::in_place, *f) : std::optional<osp::frame>();
    } else if (f) {  // in place, a store per byte (a 7-byte union copy calls memcpy at -Os)
        ::new (static_cast<void*>(&d.frame_.f)) std::optional<osp::frame>(std::in_place, *f);
    } else {
        ::new (static_cast<void*>(&d.frame_.f)) std::optional<osp::frame>();
    }
}
// Makes d hold a frame, whatever it held, and returns it, to be written in place.
template <class M>
constexpr osp::frame& impl::frame_in_place(decode_result_of<M>& d) noexcept {
    if (ROBOWIRE_CONSTANT_EVALUATED()) d.frame_ = std::optional<osp::frame>(std::in_place);
    else ::new (static_cast<void*>(&d.frame_.f)) std::optional<osp::frame>(std::in_place);
    return *d.frame_.f;
}

static_assert(sizeof(frame) == 6 && std::is_trivially_copyable_v<frame>, "osp::frame: DEV, CMD, P1..P4, no padding");

namespace impl {
// DEV << 8 | CMD of message M (its fixed bytes 2 and 3).
template <class M>
constexpr std::uint16_t frame_key_of() noexcept {
    return static_cast<std::uint16_t>(codec::key_of<M>(2) << 8 | codec::key_of<M>(3));
}
// DEV << 8 | CMD of each alternative, in flash (a local array would be copied to the stack).
template <class Message, class = std::make_index_sequence<std::variant_size_v<Message>>>
inline constexpr std::uint16_t keys_v[1] = {};
template <class Message, std::size_t... I>
inline constexpr std::uint16_t keys_v<Message, std::index_sequence<I...>>[sizeof...(I)] = {
    frame_key_of<std::variant_alternative_t<I, Message>>()...};
// Every alternative of Message has a DEV/CMD pair of its own.
template <class Message>
constexpr bool keys_distinct() noexcept {
    const auto& keys = keys_v<Message>;
    for (std::size_t a = 0; a < std::size(keys); ++a)
        for (std::size_t b = a + 1; b < std::size(keys); ++b)
            if (keys[a] == keys[b]) return false;
    return true;
}
// The n fixed bytes f are those of fixed(DEV, CMD): the markers, DEV and
// CMD, in that order. Not a template, and no std::array calls: cheap for
// g++ to evaluate for every message.
constexpr bool plain_fixed(const fixed_byte* f, std::size_t n) noexcept {
    constexpr std::size_t offsets[6] = {0, 1, 2, 3, 8, 9};
    if (n != 6) return false;
    for (std::size_t k = 0; k < 6; ++k)
        if (f[k].offset != offsets[k]) return false;
    return f[0].value == start1 && f[1].value == start2 && f[4].value == end1 && f[5].value == end2;
}
// M is a 10-byte frame whose fixed bytes are exactly the markers, DEV and CMD:
// what the shared frame check and frame writer below assume. The sizes from
// min_size_v and max_size_v, which the codecs evaluate anyway.
template <class M>
constexpr bool plain_frame() noexcept {
    constexpr auto& t = table_v<M>;
    return min_size_v<M> == frame_size &&
           (t.declared_max_input ? t.declared_max_input : max_size_v<M>) == frame_size &&  // max_input()
           plain_fixed(t.fixed.data(), t.fixed.size());
}
// The four markers: the fixed bytes of osp::frame (a copy of them alone, so
// that the loop below keeps only 32 bytes of the table in flash).
// A template (F is osp::frame): including this header evaluates no table.
template <class F>
inline constexpr auto markers = table_v<F>.fixed;
inline namespace ROBOWIRE_MODE_NAMESPACE {
// Which of the checks below a frame failed, in decode_into<frame>'s order
// (out of line: the good path is one test per byte).
template <class F = osp::frame>
ROBOWIRE_COLD constexpr error frame_error(std::span<const std::uint8_t> in) noexcept {
    constexpr auto all = std::make_index_sequence<markers<F>.size()>{};
    if (const error e = codec::check_fixed<F>(in, all)) return e;
    if (in.size() < frame_size) return codec::fail_at(errc::too_short, in.size());
    return fail(errc::too_long, frame_size);
}
// Markers and length of any frame: the checks of decode_into<frame>, shared by every message.
template <class F = osp::frame>
constexpr error check_frame(std::span<const std::uint8_t> in) noexcept {
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {  // a loop over the four
        for (const auto& m : markers<F>)
            if (m.offset < in.size() && in[m.offset] != m.value) return codec::fail_at(m.code, m.offset);
        if (in.size() < frame_size) return codec::fail_at(errc::too_short, in.size());
        if (in.size() > frame_size) return fail(errc::too_long, frame_size);
        return {};
    } else {  // the markers as two words: faster on hosts (clang++ 14 too: it keeps four byte compares)
        if (in.size() == frame_size && codec::fixed_bytes_match<F>(in)) [[likely]]
            return {};
        return frame_error<F>(in);
    }
}
// Fixed bytes checked by the frame already: makes the message and decodes its fields in place.
// FlagSet: d's flag is stored (true) already, with the frame (decode_at).
template <std::size_t I, bool FlagSet = false>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_message(decode_result_t<I>& d, std::span<const std::uint8_t> in) noexcept {
    using M = std::variant_alternative_t<I, typename dependent_message<I>::type>;
    if constexpr (table_v<M>.field_count == 0) {  // a request: nothing to decode (and no field code to compile)
        if constexpr (FlagSet) (void)codec::make_alternative_keep_flag<I>(d);
        else (void)codec::make_alternative<I>(d);
    } else if constexpr (FlagSet) {
        auto& m = codec::make_alternative_keep_flag<I>(d);
        if (const error e = codec::decode_fields(m, in, codec::discarded_on_error); e.code != errc::ok) d = e;
    } else if (const error e = codec::decode_fields(codec::make_alternative<I>(d), in, codec::discarded_on_error);
               e.code != errc::ok) {
        d = e;
    }
}
// The message whose key is `key`, by one compare per message (less code).
template <std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_by_key_chain(decode_result_t<I...>& d, std::uint16_t key,
                                                          std::span<const std::uint8_t> in,
                                                          std::index_sequence<I...>) noexcept {
    const bool known =
        ((key == frame_key_of<std::variant_alternative_t<I, message>>() ? (decode_message<I>(d, in), true) : false) ||
         ...);
    if (!known) d = fail(errc::unknown_message, 2);
}
// DEV | CMD << 8: bytes 2 and 3 as one little-endian load (no byte swap on hosts).
constexpr std::uint16_t wire_key(std::uint16_t key) noexcept {
    return static_cast<std::uint16_t>(key >> 8 | (key & 0xFF) << 8);
}
// (wire_key, alternative index) of each alternative, sorted by wire_key.
template <class Message>
inline constexpr auto sorted_keys_v = [] {
    constexpr std::size_t n = std::variant_size_v<Message>;
    std::array<std::array<std::uint16_t, 2>, n> k{};
    for (std::size_t i = 0; i < n; ++i) k[i] = {wire_key(keys_v<Message>[i]), static_cast<std::uint16_t>(i)};
    for (std::size_t i = 1; i < n; ++i)
        for (std::size_t j = i; j > 0 && k[j - 1][0] > k[j][0]; --j) std::swap(k[j - 1], k[j]);
    return k;
}();
// A compare tree over sorted_keys_v[Lo, Hi); `key` is a wire_key. With g++
// each node tests its key for equal, then greater, on the flags of one
// compare (as g++ lowers a `switch`): 11 keys take 8 instructions on
// average, where a tree that tests for equal only at its leaves (clang++'s
// best) takes 9.
template <std::size_t Lo, std::size_t Hi, bool FlagSet>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_in_range(decode_result_t<Lo>& d, std::uint16_t key,
                                                      std::span<const std::uint8_t> in) noexcept {
    constexpr auto& k = sorted_keys_v<typename dependent_message<Lo>::type>;
#if defined(__clang__)  // clang++ makes `key > k` a second compare (`key < k + 1`), in either order
    if constexpr (Hi - Lo == 1) {
        if (key == k[Lo][0]) decode_message<k[Lo][1], FlagSet>(d, in);
        else d = fail(errc::unknown_message, 2);
    } else {
        constexpr std::size_t mid = Lo + (Hi - Lo) / 2;
        if (key < k[mid][0]) decode_in_range<Lo, mid, FlagSet>(d, key, in);
        else decode_in_range<mid, Hi, FlagSet>(d, key, in);
    }
#else  // not `key < k`, which g++ makes `key <= k - 1`
    if constexpr (Hi == Lo) {
        d = fail(errc::unknown_message, 2);
    } else {
        constexpr std::size_t mid = Lo + (Hi - Lo) / 2;
        if (key == k[mid][0]) decode_message<k[mid][1], FlagSet>(d, in);
        else if (key > k[mid][0]) decode_in_range<mid + 1, Hi, FlagSet>(d, key, in);
        else decode_in_range<Lo, mid, FlagSet>(d, key, in);
    }
#endif
}
// The message whose DEV and CMD are in[2] and in[3], or unknown_message. At
// speed, a compare tree on the wire_key: g++ turns the chain into a jump
// table, whose load costs more.
template <bool FlagSet = false, std::size_t... I>
ROBOWIRE_ALWAYS_INLINE constexpr void decode_by_key(decode_result_t<I...>& d, std::span<const std::uint8_t> in,
                                                    std::index_sequence<I...> all) noexcept {
    if constexpr (ROBOWIRE_OPTIMIZE_SIZE) {
        if (ROBOWIRE_CONSTANT_EVALUATED()) {
            decode_by_key_chain(d, static_cast<std::uint16_t>(in[2] << 8 | in[3]), in, all);
        } else {  // the key's index by a loop over keys_v (in flash), then a dense switch on it
            const auto key = static_cast<std::uint16_t>(in[2] << 8 | in[3]);
            std::size_t i = 0;
            while (i < sizeof...(I) && keys_v<typename dependent_message<I...>::type>[i] != key) ++i;
            if (i == sizeof...(I)) d = fail(errc::unknown_message, 2);
            else ((i == I ? decode_message<I>(d, in) : void()), ...);
        }
    } else {
        decode_in_range<0, sizeof...(I), FlagSet>(d, static_cast<std::uint16_t>(in[2] | in[3] << 8), in);
    }
}
// Checks m's fields and writes them into `out` (FF AA DEV CMD 00 00 00 00 55 77 written
// already; encode checks plain_frame<M>).
template <class M>
ROBOWIRE_ALWAYS_INLINE constexpr error encode_fields(const M& m, std::span<std::uint8_t, frame_size> out) noexcept {
    error err{};
    if (codec::check_fields(m, err)) codec::store_fields(m, out);
    return err;
}
// out[0..9] becomes the frame of a message with key DEV << 8 | CMD and no parameters.
ROBOWIRE_SIZE_NOINLINE constexpr void write_frame(std::uint8_t* out, std::uint16_t key) noexcept {
    out[0] = start1;
    out[1] = start2;
    out[2] = static_cast<std::uint8_t>(key >> 8);
    out[3] = static_cast<std::uint8_t>(key);
    out[4] = out[5] = out[6] = out[7] = 0;
    out[8] = end1;
    out[9] = end2;
}
// b becomes the frame of a message with key DEV << 8 | CMD and no parameters.
ROBOWIRE_ALWAYS_INLINE constexpr void write_frame(bytes<frame_size>& b, std::uint16_t key) noexcept {
    codec::set_written_size(b, frame_size);
    write_frame(b.data(), key);
}
// Checks the fields of `answer`, then writes its whole frame into out[0..9]:
// out is not touched on an error.
template <class M>
ROBOWIRE_ALWAYS_INLINE constexpr error write_answer(const M& answer, std::uint8_t* out) noexcept {
    static_assert(plain_frame<M>(), "osp: a message must be one 10-byte frame with the markers, DEV and CMD fixed");
    error err{};
    if (!codec::check_fields(answer, err)) return err;
    write_frame(out, frame_key_of<M>());
    codec::store_fields(answer, std::span<std::uint8_t, frame_size>(out, frame_size));
    return err;
}
// Calls handler(msg) for the message m holds and on_answer(a) for the answer
// a it returns, if any (see serve). not_handled (offset 2) when the handler
// has no overload for that message. The call's expression tested and typed
// directly: std::is_invocable and std::invoke_result cost g++ 0.9 MB of
// compile memory for the 11 messages (firmware/osp.cpp).
template <class Handler, class OnAnswer>
constexpr error call_handler(Handler& handler, const message& m, OnAnswer&& on_answer) {
    error err{};
    codec::visit_held(m, [&](const auto& msg) {
        if constexpr (!requires { handler(msg); }) {
            err = fail(errc::not_handled, 2);
        } else {
            using R = decltype(handler(msg));
            if constexpr (std::is_void_v<R>) {
                handler(msg);
            } else if constexpr (requires(const R& a) {
                                     a.has_value();
                                     *a;
                                 }) {
                const R a = handler(msg);
                if (a) err = on_answer(*a);
            } else {
                err = on_answer(handler(msg));
            }
        }
    });
    return err;
}
}  // namespace ROBOWIRE_MODE_NAMESPACE
}  // namespace impl

namespace impl::inline ROBOWIRE_MODE_NAMESPACE {
// How decode copies DEV, CMD and P1..P4 fastest: clang++ merges a memcpy into
// the frame made in place and drops its zeroing; g++ keeps the zeroing, and
// merges the six byte copies instead.
// Both store result's flag, the frame and its flag as one word where the
// layout allows (frame_word_offset). clang++ would take DEV and CMD for the
// compare tree out of that word with shifts: the word's address is hidden
// from it (frame_word_source), so that DEV and CMD stay one 16-bit load.
#if defined(__clang__)
inline constexpr bool frame_by_memcpy = true;
#else
inline constexpr bool frame_by_memcpy = false;
#endif
#if defined(__clang__) && !defined(__x86_64__) && !defined(__aarch64__)
inline constexpr bool frame_by_word = false;  // no empty asm to hide the address with (frame_word_source)
#else
inline constexpr bool frame_by_word = ROBOWIRE_COPY_RUNS && std::endian::native == std::endian::little;
#endif
// The 8-byte word's address: p, unknown to clang++'s optimizer (an empty
// asm, no instruction); p itself elsewhere.
ROBOWIRE_ALWAYS_INLINE const std::uint8_t* frame_word_source(const std::uint8_t* p) noexcept {
#if defined(__clang__) && (defined(__x86_64__) || defined(__aarch64__))
    __asm__("" : "+r"(p));
#endif
    return p;
}
// Where decode_result keeps result's flag, DEV, CMD, P1..P4 and the frame's
// flag as 8 bytes in a row (64-bit hosts), the offset of the first; else 0.
// Little-endian hosts only. Read from two decode_results built at run time:
// folds to a constant. A template: including this header compiles none of it.
template <class Message>
std::size_t frame_word_offset() noexcept {
    using R = decode_result_t<sizeof(Message)>;
    using M = typename dependent_message<sizeof(Message)>::type;
    const R v(result<M>(Message{}), osp::frame{2, 3, {4, 5, 6, 7}});
    const R e(result<M>(fail(errc::unknown_message, 2)), std::nullopt);
    const auto* vb = reinterpret_cast<const unsigned char*>(&v);
    const auto at = static_cast<std::size_t>(reinterpret_cast<const unsigned char*>(&*v.frame()) - vb);
    if (at == 0 || at + 7 > sizeof(R)) return 0;
    std::uint64_t wv, we;  // little-endian: the first byte lowest
    std::memcpy(&wv, vb + at - 1, 8);
    std::memcpy(&we, reinterpret_cast<const unsigned char*>(&e) + at - 1, 8);
    return wv == 0x0107'0605'0403'0201u && (we & 0xFF00'0000'0000'00FFu) == 0 ? at - 1 : 0;
}
// decode's work, out of line: the input as pointer and size (a span that an
// inlined caller passes on by value is copied through the stack first).
template <class Message>
constexpr decode_result_t<sizeof(Message)> decode_at(const std::uint8_t* data, std::size_t size) noexcept {
    using R = decode_result_t<sizeof(Message)>;
    const std::span<const std::uint8_t> in(data, size);
    // A message or an error on every path below (under ROBOWIRE_OPTIMIZE_SIZE: a
    // default message first, less code).
    R d = ROBOWIRE_OPTIMIZE_SIZE ? R{std::in_place} : R{codec::unset_t{}};
    if (const error e = check_frame<codec::deferred_t<osp::frame, Message>>(in)) {
        set_frame(d, nullptr);
        d = e;
        return d;
    }
    if constexpr (!ROBOWIRE_OPTIMIZE_SIZE && frame_by_word) {  // one compare tree only (FlagSet)
        if (std::size_t at = 0; !ROBOWIRE_CONSTANT_EVALUATED() && (at = frame_word_offset<Message>()) != 0) {
            // Bytes 1..8 (AA DEV CMD P1..P4 55, the markers checked) become
            // 01 DEV CMD P1..P4 01: result's flag, the frame and its flag, one store.
            std::uint64_t w;
            std::memcpy(&w, frame_word_source(data + 1), 8);
            w ^= std::uint64_t{start2 ^ 1u} | std::uint64_t{end1 ^ 1u} << 56;
            std::memcpy(reinterpret_cast<unsigned char*>(&d) + at, &w, 8);
        } else {  // another layout, or a constant expression (where the message sets the flag)
            const osp::frame f{in[2], in[3], {in[4], in[5], in[6], in[7]}};
            set_frame(d, &f);
            using M = typename dependent_message<sizeof(Message)>::type;
            if (!ROBOWIRE_CONSTANT_EVALUATED()) static_cast<result<M>&>(d) = result<M>(M{});
        }
        decode_by_key<true>(d, in, std::make_index_sequence<std::variant_size_v<Message>>{});
    } else {
        if (ROBOWIRE_OPTIMIZE_SIZE || ROBOWIRE_CONSTANT_EVALUATED() || !frame_by_memcpy) {
            const osp::frame f{in[2], in[3], {in[4], in[5], in[6], in[7]}};
            set_frame(d, &f);
        } else {  // one wide copy, not six bytes
            std::memcpy(&frame_in_place(d), data + 2, sizeof(osp::frame));
        }
        decode_by_key(d, in, std::make_index_sequence<std::variant_size_v<Message>>{});
    }
    return d;
}
}  // namespace impl::inline ROBOWIRE_MODE_NAMESPACE

inline namespace ROBOWIRE_MODE_NAMESPACE {
// Decodes one 10-byte frame into whichever message its DEV and CMD name.
// Errors: too_short / too_long, bad_header, bad_trailer, unknown_message
// (offset 2), and the message's own field errors.
template <class Message>
[[nodiscard]] ROBOWIRE_ALWAYS_INLINE constexpr impl::decode_result_t<sizeof(Message)> decode(
    std::span<const std::uint8_t> in) noexcept {
    static_assert(impl::keys_distinct<Message>(),
                  "osp::decode: two messages share a DEV/CMD pair (the second could never be decoded)");
    return impl::decode_at<Message>(in.data(), in.size());
}

// Encodes any message of the variant: one frame writer for all of them, then
// the message's own fields. Errors: the message's field errors;
// unknown_message for a variant left valueless by an exception.
template <class Message = message>
[[nodiscard]] constexpr result<bytes<frame_size>> encode(const std::type_identity_t<Message>& m) noexcept {
    result<bytes<frame_size>> r{std::in_place, codec::unset_t{}};  // write_frame sets every byte
#if defined(__cpp_exceptions)                                      // valueless only after an exception
    if (m.valueless_by_exception()) {
        r = fail(errc::unknown_message, 2);
        return r;
    }
#endif
    auto& b = codec::unchecked_value(r);
    impl::write_frame(b, impl::keys_v<Message>[m.index()]);
    const auto out = std::span<std::uint8_t, frame_size>(b.data(), frame_size);
    codec::visit_held(m, [&](const auto& x) {
        using M = std::remove_cvref_t<decltype(x)>;
        static_assert(impl::plain_frame<M>(),
                      "osp: a message must be one 10-byte frame with the markers, DEV and CMD fixed");
        if constexpr (table_v<M>.field_count != 0)  // a request: write_frame wrote it whole (no field code to compile)
            if (const error e = impl::encode_fields(x, out)) r = e;
    });
    return r;
}

// Device role. Decodes `request` and calls handler(msg) for the message it
// holds, if the handler accepts that type. The handler returns void (no
// answer), a message (the answer), or std::optional of a message.
// Returns the encoded answer, nullopt when there is none, or an error: the
// request's decode error; not_handled (offset 2) when the frame is valid but
// the handler has no overload for its message (another device's frame on a
// shared bus); the answer's field error. serve_to writes into your buffer instead.
template <class Handler>
[[nodiscard]] constexpr result<std::optional<bytes<frame_size>>> serve(std::span<const std::uint8_t> request,
                                                                       Handler&& handler) {
    result<std::optional<bytes<frame_size>>> r{std::in_place};  // no answer (yet)
    auto d = decode(codec::deferred<Handler>(request));         // instantiated with serve
    if (!d) {
        r = codec::unchecked_error(d);
        return r;
    }
    const error e = impl::call_handler(handler, codec::unchecked_value(d), [&r](const auto& answer) {
        auto& out = codec::unchecked_value(r).emplace(codec::unset_t{});  // encoded straight into r
        codec::set_written_size(out, frame_size);
        return impl::write_answer(answer, out.data());
    });
    if (e.code != errc::ok) r = e;
    return r;
}

// Device role, zero-copy: as serve, but the answer's frame is written into
// `out` (a UART transmit buffer; at least 10 bytes). Returns the bytes
// written: 10 for an answer, 0 when there is nothing to send. Errors: as
// serve (not_handled at offset 2 for a valid frame the handler does not
// take), and buffer_too_small (offset 10) when `out` is shorter than a
// frame, found before the request is decoded (the handler is not called).
// On an error `out` is left as it was.
template <class Handler>
[[nodiscard]] constexpr result<std::size_t> serve_to(Handler&& handler, std::span<const std::uint8_t> request,
                                                     std::span<std::uint8_t> out) {
    if (out.size() < frame_size) return fail(errc::buffer_too_small, frame_size);
    auto d = decode(codec::deferred<Handler>(request));  // instantiated with serve_to
    if (!d) return codec::unchecked_error(d);
    std::size_t written = 0;
    const error e = impl::call_handler(handler, codec::unchecked_value(d), [&](const auto& answer) {
        const error a = impl::write_answer(answer, out.data());
        if (a.code == errc::ok) written = frame_size;
        return a;
    });
    if (e.code != errc::ok) return e;
    return written;
}
}  // namespace ROBOWIRE_MODE_NAMESPACE

// describe_error for an OSP error (osp::decode, serve, serve_to, a scanned
// frame): the line of the message whose DEV and CMD `in` carries
// ("voltage: input too short (10 bytes) at byte 9", "set_angle: message not
// handled at byte 2"); "unknown key 0x03 0x01 at byte 2" for a DEV/CMD pair
// no message has; osp::frame's line when `in` does not reach CMD. Pass the
// input the error came from; cut to fit `buf`.
template <class Message = message>
constexpr std::string_view describe_error(const error& e, std::span<const std::uint8_t> in,
                                          std::span<char> buf) noexcept {
    if (in.size() < 4) return robowire::describe_error<codec::deferred_t<osp::frame, Message>>(e, buf);
    return codec::describe_keyed_error<Message, 2, 3>(e, in, buf);
}
// The same for the error of osp::decode's result, from the DEV and CMD it
// keeps (frame()); osp::frame's line when the markers or the length were wrong.
template <class Message = message>
constexpr std::string_view describe_error(const impl::decode_result_t<sizeof(Message)>& d,
                                          std::span<char> buf) noexcept {
    const error e = d.code() == errc::ok ? error{} : codec::unchecked_error(d);
    if (!d.frame()) return robowire::describe_error<codec::deferred_t<osp::frame, Message>>(e, buf);
    const auto& f = *d.frame();
    const std::uint8_t in[frame_size] = {start1,      start2,      f.device,    f.command, f.params[0],
                                         f.params[1], f.params[2], f.params[3], end1,      end2};
    return codec::describe_keyed_error<Message, 2, 3>(e, in, buf);
}

}  // namespace robowire::osp
