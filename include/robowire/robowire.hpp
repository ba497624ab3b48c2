// robowire/robowire.hpp - every public header: the core, the three protocols, fuzz.hpp.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "buwizz3.hpp"
#include "core.hpp"
#include "fuzz.hpp"
#include "navbot.hpp"
#include "osp.hpp"
#include "protocols.hpp"
