// robowire/navbot.hpp - NAVBOT-ES02: frames, maneuver, multi-frame messages, BLE constants.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "navbot/decode.hpp"
#include "navbot/frame.hpp"
#include "navbot/maneuver.hpp"
#include "navbot/multiframe.hpp"
#include "navbot/protocol.hpp"
