// A constant-expression encode of a value outside its field's range
// (maneuver::pitch is -100..100).
// expect: result_holds_error.*value_out_of_range
#include <robowire/navbot.hpp>

#ifdef ROBOWIRE_FIXED
constexpr std::int8_t pitch = -100;
#else
constexpr std::int8_t pitch = -101;
#endif
constexpr auto frame = robowire::encode(robowire::navbot::maneuver{.pitch = pitch}).value();
static_assert(frame.size() == 20);
