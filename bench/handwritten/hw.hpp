// The hand-written baselines' error report, shared by the benchmarks
// (bench/*.cpp) and the differential fuzz harnesses (fuzz/diff_*.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace bench {

// ---- the hand-written baselines' error report
//
// What robowire reports, as a careful hand-written codec would: an error code
// (robowire::errc's values) and the byte offset it is about, packed into one
// register (code | offset << 8; 0: no error).
namespace hw {
enum errc : std::uint8_t {
    ok = 0, too_short = 1, too_long = 2, bad_length = 3, bad_header = 4, bad_trailer = 5, bad_command = 6,
    bad_device = 7, unknown_message = 8, value_out_of_range = 9, invalid_enum = 10, bad_padding = 11,
    reserved_not_zero = 12, missing_field = 13, buffer_too_small = 14, capacity_exceeded = 15, bad_sequence = 16,
    command_changed = 17, bad_json = 18
};
using error = std::uint16_t;
inline constexpr error good = 0;
inline error fail(errc code, std::size_t at) { return static_cast<error>(code | at << 8); }
// The result of a cold error function called on input that failed a check:
// never good, so the caller keeps no path that tests it again.
inline error never_good(error e) {
    if (e == good) __builtin_unreachable();
    return e;
}
// Length check in robowire's order: too short (at the length), then too long (at the maximum).
inline error length(std::size_t n, std::size_t want) {
    if (n < want) return fail(too_short, n);
    if (n > want) return fail(too_long, want);
    return good;
}
}  // namespace hw

}  // namespace bench
