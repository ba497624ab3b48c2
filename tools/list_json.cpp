// `robowire list --json`: the tables as one JSON document (tools/schema.hpp,
// the same generator as Python's robowire.schema()).
#include "cli.hpp"
#include "schema.hpp"

namespace robowire::cli {

std::string list_json(std::string_view protocol) { return robowire::schema::all(protocol).dump(); }

}  // namespace robowire::cli
