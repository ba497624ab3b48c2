// ROBOWIRE_OPTIMIZE_SIZE defined as nothing (-DROBOWIRE_OPTIMIZE_SIZE=).
// expect: ROBOWIRE_OPTIMIZE_SIZE is defined empty
#ifdef ROBOWIRE_FIXED
#define ROBOWIRE_OPTIMIZE_SIZE 1
#else
#define ROBOWIRE_OPTIMIZE_SIZE
#endif
#include <robowire/core.hpp>
