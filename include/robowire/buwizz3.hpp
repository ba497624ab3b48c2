// robowire/buwizz3.hpp - BuWizz3: commands, status report, advertising, UUIDs, units.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "buwizz3/advertisement.hpp"
#include "buwizz3/commands.hpp"
#include "buwizz3/decode.hpp"
#include "buwizz3/protocol.hpp"
#include "buwizz3/status.hpp"
#include "buwizz3/units.hpp"
#include "buwizz3/uuids.hpp"
