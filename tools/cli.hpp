// robowire command-line tool: its commands (main.cpp, CLI11) over the tools
// library (lib/tools.hpp).
#pragma once

#include "tools.hpp"

namespace CLI {
class App;
}

namespace robowire::cli {

using namespace robowire::tools;

// ---- more subcommands
// Adds `robowire dissector <protocol> [--output DIR]` (dissector_command.cpp).
// Other subcommands are added the same way: a function taking the app,
// declared here, called from main.cpp's add_extra_commands().
void add_dissector_command(CLI::App& app);

}  // namespace robowire::cli
