// ROBOWIRE_OPTIMIZE_SIZE with a value it does not have.
// expect: ROBOWIRE_OPTIMIZE_SIZE must be 0 or 1
#ifdef ROBOWIRE_FIXED
#define ROBOWIRE_OPTIMIZE_SIZE 0
#else
#define ROBOWIRE_OPTIMIZE_SIZE -2
#endif
#include <robowire/core.hpp>
