// A reassembler whose capacity is not a whole number of frame payloads.
// expect: Capacity is payload bytes, a multiple of 15
#include <robowire/navbot/multiframe.hpp>

#ifdef ROBOWIRE_FIXED
robowire::navbot::reassembler<30> r;
#else
robowire::navbot::reassembler<20> r;
#endif
bool in_progress() { return r.in_progress(); }
