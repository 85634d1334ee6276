// One entry point for "a mesh named on the command line or in a scene":
// a generator spelling (grid:quad:10x10) or a mesh file.
#pragma once

#include <string>

#include "rift/mesh/assemble.hpp"

namespace rift {

/// Builds the G-map of a generator spelling or a mesh file. Throws MeshError
/// (files) or std::invalid_argument (spellings) with a message for the user.
GMap load_map(const std::string& spec, AssemblyReport* report = nullptr);

}  // namespace rift
