// OSP frames: osp::decode keeps the frame decode<osp::frame> reads; re-encode
// (reserved bytes come back as 0).
#include <robowire/osp.hpp>

#include "common.hpp"

FUZZ_STRUCTURE_AWARE(robowire::osp::message)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace osp = robowire::osp;
    const std::span<const std::uint8_t> in(data, size);
    const auto m = osp::decode(in);
    const auto f = robowire::decode<osp::frame>(in);
    FUZZ_CHECK(m.frame().has_value() == f.has_value());
    if (f) FUZZ_CHECK(*m.frame() == *f);  // the same DEV, CMD and P1..P4
    if (!m) {
        FUZZ_CHECK(m.error().offset <= size);
        return 0;
    }
    const auto wire = osp::encode(*m);
    FUZZ_CHECK(wire.has_value());
    std::visit([&](const auto& msg) {
        using M = std::remove_cvref_t<decltype(msg)>;
        FUZZ_CHECK(fuzz::same_bytes(*wire, fuzz::without_reserved<M>(in)));
    }, *m);
    return 0;
}
