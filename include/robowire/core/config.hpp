// robowire/core/config.hpp - every macro robowire defines, in one place.
#pragma once

#if defined(_MSVC_LANG)
#define ROBOWIRE_CPLUSPLUS _MSVC_LANG
#else
#define ROBOWIRE_CPLUSPLUS __cplusplus
#endif
#if ROBOWIRE_CPLUSPLUS < 202002L
#error "robowire needs C++20 (-std=c++20)"
#endif
#undef ROBOWIRE_CPLUSPLUS

// Forces inlining of the codec's per-field steps, so that a message's
// encoder / decoder becomes one straight-line function.
#if defined(__GNUC__) || defined(__clang__)
#define ROBOWIRE_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define ROBOWIRE_ALWAYS_INLINE inline
#endif
