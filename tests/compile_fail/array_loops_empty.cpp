// ROBOWIRE_ARRAY_LOOPS defined as nothing (-DROBOWIRE_ARRAY_LOOPS=).
// expect: ROBOWIRE_ARRAY_LOOPS is defined empty
#ifdef ROBOWIRE_FIXED
#define ROBOWIRE_ARRAY_LOOPS 2
#else
#define ROBOWIRE_ARRAY_LOOPS
#endif
#include <robowire/core.hpp>
