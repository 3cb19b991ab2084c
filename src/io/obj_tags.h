#pragma once
// OBJ tag lines (`t crease 2/1/0 ...`) for a mesh's tags: written by the OBJ
// writer, and by the glTF writer into subdiv's extras, where the glTF reader
// reads them back with the OBJ reader.

#include <string>

#include "subdiv/mesh/tags.h"

namespace subdiv::detail {

/// Appends one OBJ tag line per crease, corner, hole list, option and raw
/// tag. Throws InvalidInputError for a raw tag whose name or string is empty
/// or holds white space.
void append_obj_tag_lines(std::string& out, const Tags& tags);

}  // namespace subdiv::detail
