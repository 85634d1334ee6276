#include "rift/io/load_map.hpp"

#include "rift/io/read_mesh.hpp"
#include "rift/mesh/generators.hpp"

namespace rift {

GMap load_map(const std::string& spec, AssemblyReport* report) {
  const MeshData mesh = is_generator_spec(spec) ? make_generated_mesh(spec) : read_mesh_file(spec);
  return assemble_gmap(mesh, report);
}

}  // namespace rift
