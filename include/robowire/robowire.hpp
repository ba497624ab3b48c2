// robowire/robowire.hpp - every protocol.
#pragma once

#include "core.hpp"
#include "navbot.hpp"
#include "osp.hpp"
