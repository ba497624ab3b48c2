// robowire/robowire.hpp - the core, the three protocols, their descriptors and
// reflect.hpp (not the optional extras under ext/, nor fuzz.hpp, their former path).
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "buwizz3.hpp"
#include "core.hpp"
#include "navbot.hpp"
#include "osp.hpp"
#include "protocols.hpp"
#include "reflect.hpp"
