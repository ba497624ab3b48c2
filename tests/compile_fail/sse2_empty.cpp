// ROBOWIRE_SSE2 defined as nothing (-DROBOWIRE_SSE2=).
// expect: ROBOWIRE_SSE2 is defined empty
#ifdef ROBOWIRE_FIXED
#define ROBOWIRE_SSE2 0
#else
#define ROBOWIRE_SSE2
#endif
#include <robowire/osp.hpp>
