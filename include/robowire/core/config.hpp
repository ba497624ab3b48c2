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

// ROBOWIRE_OPTIMIZE_SIZE: 1 takes the smaller of robowire's equivalent code
// paths, with the same results (OSP scanner byte by byte, records and optional
// blocks decoded in place, key lists instead of 256-byte dispatch tables, ...;
// docs/architecture.md lists them). Default 1 when compiling with -Os / -Oz.
// Define it to choose.
#ifndef ROBOWIRE_OPTIMIZE_SIZE
#if defined(__OPTIMIZE_SIZE__)
#define ROBOWIRE_OPTIMIZE_SIZE 1
#else
#define ROBOWIRE_OPTIMIZE_SIZE 0
#endif
#endif
// Keeps a helper shared by several codecs out of line under ROBOWIRE_OPTIMIZE_SIZE.
#if ROBOWIRE_OPTIMIZE_SIZE && (defined(__GNUC__) || defined(__clang__))
#define ROBOWIRE_SIZE_NOINLINE [[gnu::noinline]]
#else
#define ROBOWIRE_SIZE_NOINLINE
#endif

// ROBOWIRE_ARRAY_LOOPS: 1 codes an array field (decode, encode) as one copy of
// the element's code in a loop, 0 as one copy per element. Default 1 only when
// optimizing for size for a core without unaligned loads (Cortex-M0/M0+), where
// it saves flash; elsewhere the unrolled form is smaller or faster. Define it
// to choose.
#ifndef ROBOWIRE_ARRAY_LOOPS
#if defined(__OPTIMIZE_SIZE__) && defined(__arm__) && !defined(__ARM_FEATURE_UNALIGNED)
#define ROBOWIRE_ARRAY_LOOPS 1
#else
#define ROBOWIRE_ARRAY_LOOPS 0
#endif
#endif
