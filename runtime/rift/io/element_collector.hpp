// Gathers the elements a reader finds and decides what the mesh is. Gmsh,
// Medit and VTK files mix dimensions: a volume mesh usually carries its
// boundary triangles, edges and corner points as markers. The rule, the same
// for every format: if there is any solid, the mesh is a 3D volume mesh of its
// solids and the polygons are dropped; otherwise it is a 2D map of its polygons.
// Lines and points are never part of a map; readers only count them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "rift/mesh/mesh_data.hpp"

namespace rift::io {

class ElementCollector {
 public:
  /// `vertices` are 0-based point indices the reader has already checked.
  /// `tag`: the element's physical group (Gmsh physical tag, Medit
  /// reference); groups are kept when every kept element has one.
  void add(ElementType type, std::span<const std::uint32_t> vertices, int line,
           std::optional<std::int64_t> tag = std::nullopt);
  /// A line or point element, ignored but mentioned if nothing else is found.
  void ignore_lower_dimensional() { ++ignored_; }

  std::size_t polygons() const { return surface_.elements.size(); }
  std::size_t solids() const { return volume_.elements.size(); }

  /// Moves the kept elements into `mesh` and sets its dimension. Throws a
  /// MeshError at `line` (0: the whole file) if there is no element at all.
  void finish(MeshData& mesh, int line);

 private:
  MeshData surface_;
  MeshData volume_;
  std::size_t ignored_ = 0;
  std::size_t untagged_surface_ = 0, untagged_volume_ = 0;
};

}  // namespace rift::io
