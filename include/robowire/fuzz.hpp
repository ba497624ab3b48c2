// robowire/fuzz.hpp - the former path of robowire/ext/fuzz.hpp (fuzz harness
// helpers), kept so that existing includes still compile. New code includes
// <robowire/ext/fuzz.hpp>. Not in the umbrella robowire.hpp.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "ext/fuzz.hpp"
