// BuWizz3 host -> device packets: decode_command, then re-encode.
#include <robowire/buwizz3.hpp>

#include "common.hpp"

FUZZ_STRUCTURE_AWARE(robowire::buwizz3::command)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> in(data, size);
    const auto cmd = robowire::buwizz3::decode_command(in);
    fuzz::check_text(cmd);
    fuzz::check_decode_into<robowire::buwizz3::command>(in);
    if (!cmd) {
        FUZZ_CHECK(cmd.error().offset <= size);
        return 0;
    }
    // Every command has one wire form: re-encoding gives the input back.
    const auto wire = robowire::encode(*cmd);
    FUZZ_CHECK(wire.has_value());
    FUZZ_CHECK(fuzz::same_bytes(*wire, in));
    return 0;
}
