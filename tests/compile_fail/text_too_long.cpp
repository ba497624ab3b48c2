// text<N> from a string literal longer than N.
// expect: (constraint|no viable conversion|could not convert|conversion from)
#include <robowire/core.hpp>

#ifdef ROBOWIRE_FIXED
constexpr robowire::text<5> name = "hello";
#else
constexpr robowire::text<4> name = "hello";
#endif
static_assert(name.size() > 0);
