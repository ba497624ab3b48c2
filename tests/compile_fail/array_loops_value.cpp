// ROBOWIRE_ARRAY_LOOPS with a value it does not have.
// expect: ROBOWIRE_ARRAY_LOOPS must be 0, 1 or 2
#ifdef ROBOWIRE_FIXED
#define ROBOWIRE_ARRAY_LOOPS 0
#else
#define ROBOWIRE_ARRAY_LOOPS 3
#endif
#include <robowire/core.hpp>
