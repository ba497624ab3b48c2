// robowire/robowire.hpp - every protocol.
#pragma once

#include "buwizz3.hpp"
#include "core.hpp"
#include "navbot.hpp"
#include "osp.hpp"
