// OSP frames: osp::decode keeps the frame decode<osp::frame> reads; re-encode
// (reserved bytes come back as 0). On a frame with the right markers and
// length, each message's own decoder, robowire::decode<M>, agrees with
// osp::decode: the message it chose decodes to the same bytes, every other
// one rejects the frame.
#include <robowire/osp.hpp>

#include <utility>

#include "common.hpp"

FUZZ_STRUCTURE_AWARE(robowire::osp::message)

namespace {
namespace osp = robowire::osp;

template <std::size_t I>
void check_alternative(std::span<const std::uint8_t> in, const robowire::result<osp::message>& m) {
    using M = std::variant_alternative_t<I, osp::message>;
    const auto r = robowire::decode<M>(in);
    fuzz::check_text(r);
    if (!m || m->index() != I) {
        FUZZ_CHECK(!r.has_value());
        // a frame osp::decode gives to another message fails on that message's DEV or CMD
        if (m) FUZZ_CHECK(r.error().code == robowire::errc::bad_device || r.error().code == robowire::errc::bad_command);
        return;
    }
    FUZZ_CHECK(r.has_value());
    const auto mine = robowire::encode(*r), theirs = osp::encode(*m);
    FUZZ_CHECK(mine.has_value() && theirs.has_value() && fuzz::same_bytes(*mine, *theirs));
}
template <std::size_t... I>
void check_alternatives(std::span<const std::uint8_t> in, const robowire::result<osp::message>& m,
                        std::index_sequence<I...>) {
    (check_alternative<I>(in, m), ...);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> in(data, size);
    const auto m = osp::decode(in);
    const auto f = robowire::decode<osp::frame>(in);
    fuzz::check_text(m);
    fuzz::check_text(f);
    FUZZ_CHECK(m.frame().has_value() == f.has_value());
    if (f) FUZZ_CHECK(*m.frame() == *f);  // the same DEV, CMD and P1..P4
    // Only on frames decode<osp::frame> accepts: on every input, the eleven
    // decodes cut libFuzzer's speed to a third.
    if (f) {
        check_alternatives(in, m, std::make_index_sequence<std::variant_size_v<osp::message>>{});
        fuzz::check_decode_into<osp::message>(in);
    }
    if (!m) {
        FUZZ_CHECK(m.error().offset <= size);
        return 0;
    }
    const auto wire = osp::encode(*m);
    FUZZ_CHECK(wire.has_value());
    std::visit([&](const auto& msg) {
        using M = std::remove_cvref_t<decltype(msg)>;
        FUZZ_CHECK(fuzz::same_bytes(*wire, fuzz::without_reserved<M>(in)));
        // a strict receiver: check_reserved finds the first reserved byte that is not zero
        const auto strict = robowire::check_reserved<M>(in);
        fuzz::check_text(strict);
        FUZZ_CHECK(strict.has_value() == fuzz::same_bytes(*wire, in));
        if (strict) return;
        const std::size_t at = strict.error().offset;
        FUZZ_CHECK(strict.error().code == robowire::errc::reserved_not_zero);
        FUZZ_CHECK(at < in.size() && robowire::reserved_bytes<M>()[at] && in[at] != 0);
    }, *m);
    return 0;
}
