// robowire/core.hpp - every core header.
#pragma once

#include "core/config.hpp"  // first: the C++ version check

#include "core/advertising.hpp"
#include "core/bits.hpp"
#include "core/bytes.hpp"
#include "core/decode.hpp"
#include "core/descriptor.hpp"
#include "core/dispatch.hpp"
#include "core/divide.hpp"
#include "core/encode.hpp"
#include "core/endian.hpp"
#include "core/fields.hpp"
#include "core/flag_bits.hpp"
#include "core/result.hpp"
#include "core/table.hpp"
#include "core/text.hpp"
#include "core/uuid.hpp"
#include "core/wire.hpp"
