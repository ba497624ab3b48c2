// `robowire list --json`: the tables as one JSON document (tools/lib/schema.hpp,
// the same generator as Python's robowire.schema()).
#include "schema.hpp"
#include "tools.hpp"

namespace robowire::tools {

std::string list_json(std::string_view protocol) { return robowire::schema::all(protocol).dump(); }

}  // namespace robowire::tools
