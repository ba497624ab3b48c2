// robowire/core/config.hpp - every macro robowire defines or reads, in one
// place. A user sets ROBOWIRE_OPTIMIZE_SIZE, ROBOWIRE_ARRAY_LOOPS,
// ROBOWIRE_ALWAYS_INLINE and ROBOWIRE_BAD_RESULT_ACCESS_HANDLER (before any
// robowire header, or on the command line); the others are internal.
#pragma once

#if defined(_MSVC_LANG)
#define ROBOWIRE_CPLUSPLUS _MSVC_LANG
#else
#define ROBOWIRE_CPLUSPLUS __cplusplus
#endif
// Every robowire header includes this file first, so that a C++17 build sees
// this one message: the missing file below is a fatal error, which ends the
// compilation before any C++20 code (g++ and clang++ go on after #error).
#if ROBOWIRE_CPLUSPLUS < 202002L
#error "robowire needs C++20 (-std=c++20)"
#include <robowire needs C++20, compilation stopped>
#endif
#undef ROBOWIRE_CPLUSPLUS

// The version of these headers: 0.1.0 is 100 (major * 10000 + minor * 100 + patch).
// The one source of the version: CMake reads it, a test checks the package files.
#define ROBOWIRE_VERSION_MAJOR 0
#define ROBOWIRE_VERSION_MINOR 1
#define ROBOWIRE_VERSION_PATCH 0
#define ROBOWIRE_VERSION (ROBOWIRE_VERSION_MAJOR * 10000 + ROBOWIRE_VERSION_MINOR * 100 + ROBOWIRE_VERSION_PATCH)

// ROBOWIRE_ALWAYS_INLINE: forces inlining of the codec's per-field steps, so
// that a message's encoder / decoder becomes one straight-line function.
// Plain `inline` when not optimizing (-O0) or not g++ / clang++. Define it
// (to something that includes `inline`) to choose.
#ifndef ROBOWIRE_ALWAYS_INLINE
#if (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE__)
#define ROBOWIRE_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define ROBOWIRE_ALWAYS_INLINE inline
#endif
#endif

// Keeps an error path out of line and out of the hot code.
#if defined(__GNUC__) || defined(__clang__)
#define ROBOWIRE_COLD [[gnu::cold, gnu::noinline]]
#else
#define ROBOWIRE_COLD
#endif
// Keeps a function out of line: a loop entered rarely that runs long, whose
// registers would otherwise crowd the caller's hot loop.
#if defined(__GNUC__) || defined(__clang__)
#define ROBOWIRE_NOINLINE [[gnu::noinline]]
#else
#define ROBOWIRE_NOINLINE
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
#if (ROBOWIRE_OPTIMIZE_SIZE + 0) == 0 && (0 - ROBOWIRE_OPTIMIZE_SIZE - 1) == 1  // defined as nothing
#error "ROBOWIRE_OPTIMIZE_SIZE is defined empty: define it to 0 or 1"
#elif ROBOWIRE_OPTIMIZE_SIZE != 0 && ROBOWIRE_OPTIMIZE_SIZE != 1
#error "ROBOWIRE_OPTIMIZE_SIZE must be 0 or 1"
#endif
// Keeps a helper shared by several codecs out of line under ROBOWIRE_OPTIMIZE_SIZE.
#if ROBOWIRE_OPTIMIZE_SIZE && (defined(__GNUC__) || defined(__clang__))
#define ROBOWIRE_SIZE_NOINLINE [[gnu::noinline]]
#else
#define ROBOWIRE_SIZE_NOINLINE
#endif

// Inlines a protocol's dispatcher (decode_variant, decode_command, ...) into its
// caller; under ROBOWIRE_OPTIMIZE_SIZE it stays one out-of-line copy.
#if ROBOWIRE_OPTIMIZE_SIZE
#define ROBOWIRE_SPEED_INLINE inline
#else
#define ROBOWIRE_SPEED_INLINE ROBOWIRE_ALWAYS_INLINE
#endif

// ROBOWIRE_ARRAY_LOOPS: how array fields are coded (decode, encode).
//   0: one copy of the element's code per element (unrolled);
//   1: one copy of the element's code in a loop, for every array;
//   2: encoders loop over every array; decoders over arrays of 4 or more
//      elements that are not records (short arrays and records unrolled).
// Default 1 when optimizing for size (-Os / -Oz), else 0 (faster). 2 can be
// smaller for a program that reads only a few fields of a large message.
// Define it to choose.
#ifndef ROBOWIRE_ARRAY_LOOPS
#if defined(__OPTIMIZE_SIZE__)
#define ROBOWIRE_ARRAY_LOOPS 1
#else
#define ROBOWIRE_ARRAY_LOOPS 0
#endif
#endif
#if (ROBOWIRE_ARRAY_LOOPS + 0) == 0 && (0 - ROBOWIRE_ARRAY_LOOPS - 1) == 1  // defined as nothing
#error "ROBOWIRE_ARRAY_LOOPS is defined empty: define it to 0, 1 or 2"
#elif ROBOWIRE_ARRAY_LOOPS != 0 && ROBOWIRE_ARRAY_LOOPS != 1 && ROBOWIRE_ARRAY_LOOPS != 2
#error "ROBOWIRE_ARRAY_LOOPS must be 0, 1 or 2"
#endif
// std::is_constant_evaluated() as the compiler's builtin, folded where it is
// written: inside an always-inlined step g++ leaves a call to the library
// function until the outermost caller, with both branches copied into every
// step between.
#if defined(__has_builtin)
#if __has_builtin(__builtin_is_constant_evaluated)
#define ROBOWIRE_CONSTANT_EVALUATED() __builtin_is_constant_evaluated()
#else
#include <type_traits>
#define ROBOWIRE_CONSTANT_EVALUATED() std::is_constant_evaluated()
#endif
#elif defined(_MSC_VER)
#define ROBOWIRE_CONSTANT_EVALUATED() __builtin_is_constant_evaluated()
#else
#include <type_traits>
#define ROBOWIRE_CONSTANT_EVALUATED() std::is_constant_evaluated()
#endif

// A loop the compiler keeps rolled (ROBOWIRE_ARRAY_LOOPS).
#if defined(__GNUC__) || defined(__clang__)
#define ROBOWIRE_NO_UNROLL _Pragma("GCC unroll 1")
#else
#define ROBOWIRE_NO_UNROLL
#endif

// ROBOWIRE_COPY_RUNS: 1 lets decode copy each run of fields whose wire bytes
// are their members' bytes at once (one memcpy of a constant size). Default 1
// on little-endian targets that load unaligned words (x86, AArch64, ARMv7-M
// and later, WebAssembly), and under ROBOWIRE_OPTIMIZE_SIZE on the other
// little-endian Arm and RISC-V cores (Cortex-M0/M0+, RV32: runs of up to 4
// bytes copied byte by byte, longer ones by memcpy; less code than field by
// field); else 0 (field by field, no library memcpy linked). Results are the
// same either way; define it alike in every file of a program.
#ifndef ROBOWIRE_COPY_RUNS
#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64) || defined(_M_IX86) || defined(__aarch64__) || \
    defined(_M_ARM64) || defined(__ARM_FEATURE_UNALIGNED) || defined(__wasm__) ||                              \
    (ROBOWIRE_OPTIMIZE_SIZE && defined(__arm__) && defined(__ARMEL__)) ||                                      \
    (ROBOWIRE_OPTIMIZE_SIZE && defined(__riscv) && defined(__BYTE_ORDER__) &&                                  \
     __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__)
#define ROBOWIRE_COPY_RUNS 1
#else
#define ROBOWIRE_COPY_RUNS 0
#endif
#endif
#if ROBOWIRE_COPY_RUNS != 0 && ROBOWIRE_COPY_RUNS != 1
#error "ROBOWIRE_COPY_RUNS must be 0 or 1"
#endif

// ROBOWIRE_SSE2: 1 lets the OSP scanner look for start bytes 64 at a time
// with SSE2 vector compares, inline, in chunks of 64 bytes or more (16 at a
// time in shorter ones), and (not under ROBOWIRE_OPTIMIZE_SIZE) decode and
// encode check the ranges of a message's one-byte fields (and fixed bytes)
// with one vector test, flag bytes as one word, where that takes fewer
// instructions; 0 calls memchr and checks field by field. Default 1 where g++ or clang++ targets SSE2 (x86-64 always),
// else 0. Same results either way.
#ifndef ROBOWIRE_SSE2
#if defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define ROBOWIRE_SSE2 1
#else
#define ROBOWIRE_SSE2 0
#endif
#endif
#if (ROBOWIRE_SSE2 + 0) == 0 && (0 - ROBOWIRE_SSE2 - 1) == 1  // defined as nothing
#error "ROBOWIRE_SSE2 is defined empty: define it to 0 or 1"
#elif ROBOWIRE_SSE2 != 0 && ROBOWIRE_SSE2 != 1
#error "ROBOWIRE_SSE2 must be 0 or 1"
#elif ROBOWIRE_SSE2 && !(defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__)))
#error "ROBOWIRE_SSE2 is 1, but the compiler is not g++ or clang++ targeting SSE2"
#endif

// The inline namespace of the code that depends on the two macros above
// (robowire::detail::size1_loops1 at -Os): files built with different
// settings link into one program, each with its own copy of that code,
// instead of two different definitions under one name (ill-formed, and the
// linker would keep either).
#if ROBOWIRE_OPTIMIZE_SIZE == 0 && ROBOWIRE_ARRAY_LOOPS == 0
#define ROBOWIRE_MODE_NAMESPACE size0_loops0
#elif ROBOWIRE_OPTIMIZE_SIZE == 0 && ROBOWIRE_ARRAY_LOOPS == 1
#define ROBOWIRE_MODE_NAMESPACE size0_loops1
#elif ROBOWIRE_OPTIMIZE_SIZE == 0
#define ROBOWIRE_MODE_NAMESPACE size0_loops2
#elif ROBOWIRE_ARRAY_LOOPS == 0
#define ROBOWIRE_MODE_NAMESPACE size1_loops0
#elif ROBOWIRE_ARRAY_LOOPS == 1
#define ROBOWIRE_MODE_NAMESPACE size1_loops1
#else
#define ROBOWIRE_MODE_NAMESPACE size1_loops2
#endif

// ROBOWIRE_BAD_RESULT_ACCESS_HANDLER: not defined by robowire. Without
// exceptions, a wrong access to a result (value() of an error, error() of a
// value) calls the function it names, then traps; not defined: traps. Define
// it the same for every file (-DROBOWIRE_BAD_RESULT_ACCESS_HANDLER=on_bad_access)
// and define that function once, at global scope; it must not return:
//   void on_bad_access(robowire::error e) noexcept { log(e); reset(); }
#if defined(ROBOWIRE_BAD_RESULT_ACCESS_HANDLER) && !defined(__cpp_exceptions)
namespace robowire {
struct error;
}
void ROBOWIRE_BAD_RESULT_ACCESS_HANDLER(robowire::error) noexcept;
#endif
