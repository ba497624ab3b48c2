// ROBOWIRE_SSE2 with a value it does not have.
// expect: ROBOWIRE_SSE2 must be 0 or 1
#ifdef ROBOWIRE_FIXED
#define ROBOWIRE_SSE2 0
#else
#define ROBOWIRE_SSE2 2
#endif
#include <robowire/osp.hpp>
