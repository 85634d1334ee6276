#include "rift/io/element_collector.hpp"

#include "rift/mesh/mesh_error.hpp"

namespace rift::io {

void ElementCollector::add(ElementType type, std::span<const std::uint32_t> vertices, int line,
                           std::optional<std::int64_t> tag) {
  const bool solid = element_dimension(type) == 3;
  MeshData& target = solid ? volume_ : surface_;
  target.add_element(type, vertices.begin(), vertices.end(), line);
  target.element_tags.push_back(tag.value_or(0));
  if (!tag) ++(solid ? untagged_volume_ : untagged_surface_);
}

void ElementCollector::finish(MeshData& mesh, int line) {
  MeshData& kept = volume_.elements.empty() ? surface_ : volume_;
  if (kept.elements.empty()) {
    std::string problem = "the file has no polygon or volume element";
    if (ignored_ > 0) {
      problem += " (" + std::to_string(ignored_) + " line or point elements were ignored)";
    }
    throw MeshError(mesh.source, line, problem);
  }
  mesh.dimension = volume_.elements.empty() ? 2 : 3;
  const std::size_t untagged = mesh.dimension == 3 ? untagged_volume_ : untagged_surface_;
  if (untagged == 0) mesh.element_tags = std::move(kept.element_tags);
  mesh.elements = std::move(kept.elements);
  mesh.element_vertices = std::move(kept.element_vertices);
}

}  // namespace rift::io
