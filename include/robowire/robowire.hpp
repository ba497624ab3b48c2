// robowire/robowire.hpp - every protocol.
#pragma once

#include "core.hpp"
#include "osp.hpp"
