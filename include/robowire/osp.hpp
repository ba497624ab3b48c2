// robowire/osp.hpp - OSP (Open Serial Peripheral): frames, messages, scanner, dispatch.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "osp/decode.hpp"
#include "osp/frame.hpp"
#include "osp/messages.hpp"
#include "osp/protocol.hpp"
#include "osp/scanner.hpp"
#include "osp/units.hpp"
