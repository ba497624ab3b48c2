// OSP stream scanner: chunk sizes come from the input; the frames found must
// be exactly those of a simple reference (leftmost window with the markers,
// consumed whole), whatever the chunking, and the counters those of the same
// stream pushed one byte at a time.
#include <robowire/osp.hpp>

#include <vector>

#include "common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace osp = robowire::osp;
    if (size < 1) return 0;
    const std::size_t chunk_seed = data[0];
    const std::span<const std::uint8_t> stream(data + 1, size - 1);

    std::vector<std::size_t> want;  // offsets of reference frames
    for (std::size_t i = 0; i + 10 <= stream.size();) {
        if (stream[i] == 0xFF && stream[i + 1] == 0xAA && stream[i + 8] == 0x55 && stream[i + 9] == 0x77) {
            want.push_back(i);
            i += 10;
        } else {
            ++i;
        }
    }

    osp::scanner sc;
    std::size_t found = 0;
    std::size_t pos = 0, k = 0;
    while (pos < stream.size()) {
        // 1..23, or (first byte 128 and up) 10..265, varying
        const std::size_t chunk = chunk_seed < 128 ? 1 + (chunk_seed * (k + 7) + k) % 23
                                                   : 10 + (chunk_seed * (k + 7) + k) % 256;
        const std::size_t n = std::min(chunk, stream.size() - pos);
        sc.feed(stream.subspan(pos, n), [&](osp::scanner::frame_bytes f) {
            FUZZ_CHECK(f[0] == 0xFF && f[1] == 0xAA && f[8] == 0x55 && f[9] == 0x77);
            FUZZ_CHECK(found < want.size());
            FUZZ_CHECK(fuzz::same_bytes(f, stream.subspan(want[found], 10)));
            ++found;
        });
        pos += n;
        ++k;
    }
    FUZZ_CHECK(found == want.size());
    FUZZ_CHECK(sc.frames() == found);
    FUZZ_CHECK(found <= stream.size() / 10);
    FUZZ_CHECK(sc.skipped() + 10 * found + sc.pending() == stream.size());
    osp::scanner bytewise;
    for (std::uint8_t b : stream) (void)bytewise.push(b);
    FUZZ_CHECK(bytewise.frames() == found && bytewise.skipped() == sc.skipped() &&
               bytewise.false_starts() == sc.false_starts() && bytewise.pending() == sc.pending());
    return 0;
}
