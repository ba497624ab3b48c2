// One init function per protocol submodule (buwizz3.cpp, navbot.cpp, osp.cpp), and the log reader's.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

#include <robowire/core/fields.hpp>

#include "text.hpp"

namespace rwpy {
void init_buwizz3(pybind11::module_& m);
void init_navbot(pybind11::module_& m);
void init_osp(pybind11::module_& m);
void init_logs(pybind11::module_& m);  // logs.cpp: LogReader

using robowire::tools::valid_lengths;  // "1 byte", "54 or 68..129 bytes" (tools/lib/text.hpp)
}  // namespace rwpy
