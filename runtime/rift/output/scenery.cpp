#include "rift/output/scenery.hpp"

namespace rift {

void make_scenery(std::span<const Vec3> points,
                  std::span<const std::array<std::uint32_t, 3>> triangles, FrameMesh& out) {
  out = FrameMesh{};
  out.dimension = 2;
  out.points.assign(points.begin(), points.end());
  for (const auto& t : triangles) {
    for (std::uint32_t v : t) {
      out.connectivity.push_back(v);
      out.face_vertices.push_back(v);
      out.face_edge_kind.push_back(EdgeKind::kInner);
    }
    out.offsets.push_back(static_cast<std::int64_t>(out.connectivity.size()));
    out.cell_types.push_back(VtkCell::kTriangle);
    out.element_ids.push_back(static_cast<std::int64_t>(out.element_ids.size()));
    out.torn.push_back(0);
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_vertices.size()));
    out.face_element.push_back(FrameMesh::kNoElement);
    out.face_torn.push_back(0);
  }
}

}  // namespace rift
