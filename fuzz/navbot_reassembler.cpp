// NAVBOT multi-frame messages: the input, cut into frames (a length byte
// before each), goes through a reassembler; then the input is fragmented and
// reassembled again, which must give it back.
#include <robowire/navbot.hpp>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace nb = robowire::navbot;
    fuzz::reader r{{data, size}};
    nb::reassembler<60> small;
    while (!r.empty()) {
        const std::size_t len = r.byte() % 24;  // mostly 20, sometimes not a frame
        std::uint8_t frame[24] = {};
        for (std::size_t i = 0; i < len; ++i) frame[i] = r.byte();
        const auto st = small.push(std::span<const std::uint8_t>(frame, len));
        FUZZ_CHECK(small.payload().size() <= 60 && small.payload().size() % 15 == 0);
        if (st && *st == nb::reassembly::complete) FUZZ_CHECK(!small.payload().empty());
        if (!st) FUZZ_CHECK(st.error().offset < 20 || len != 20);
    }
    // Fragment the whole input as one payload and put it back together.
    const std::span<const std::uint8_t> payload(data, size < nb::max_payload ? size : nb::max_payload);
    const auto frames = nb::make_frames(0x02, payload);
    FUZZ_CHECK(frames.has_value());
    nb::reassembler<nb::max_payload> big;
    std::size_t i = 0;
    for (const auto& f : *frames) {
        const auto st = big.push(f);
        FUZZ_CHECK(st.has_value());
        FUZZ_CHECK(*st == (++i == frames->size() ? nb::reassembly::complete : nb::reassembly::need_more));
    }
    FUZZ_CHECK(big.payload().size() == frames->size() * 15);
    FUZZ_CHECK(fuzz::same_bytes(big.payload().first(payload.size()), payload));
    return 0;
}
