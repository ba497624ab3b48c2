// robowire dissector generator: Wireshark Lua plugins built from the field tables.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace robowire::tool {

// The Lua plugin for one protocol ("buwizz3", "navbot" or "osp"): a data part
// generated from table_v<M> of every message, then the fixed runtime.
// Empty string for an unknown protocol.
std::string dissector_lua(std::string_view protocol);

// Writes DIR/robowire_<protocol>.lua for `protocol` ("all": the three).
// Returns 0, 1 when a file cannot be written, 2 for an unknown protocol;
// messages go to `err`.
int write_dissectors(std::string_view protocol, const char* dir, std::FILE* err);

}  // namespace robowire::tool
