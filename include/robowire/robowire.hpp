// robowire/robowire.hpp - every protocol.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "buwizz3.hpp"
#include "core.hpp"
#include "navbot.hpp"
#include "osp.hpp"
