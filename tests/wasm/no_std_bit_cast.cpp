// Every robowire header compiles without std::bit_cast (emscripten 3.1.6's
// libc++ has none): the standard headers first, then bit_cast is poisoned, so
// that any later use of std::bit_cast in a robowire header is an error.
// Compiled (not run) into robowire_tests, and by tests/wasm/run with em++.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <initializer_list>
#include <limits>
#include <new>
#include <numbers>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#pragma GCC poison bit_cast

#include <robowire/ext/fuzz.hpp>
#include <robowire/robowire.hpp>

// The builtin keeps floats' bit patterns, NaN payloads included, in constant evaluation.
static_assert(robowire::detail::builtin_bit_cast<std::uint32_t>(1.0f) == 0x3F800000u);
static_assert(robowire::detail::builtin_bit_cast<float>(0xC0000000u) == -2.0f);
