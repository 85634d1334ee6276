#include "rift/output/volume_cells.hpp"

#include <algorithm>

namespace rift {

namespace {

// Newell's normal of a polygon given by point ids: robust for non-planar quads.
Vec3 polygon_normal(std::span<const Vec3> positions, const std::uint32_t* ids, int count) {
  Vec3 n = Vec3::Zero();
  for (int k = 0; k < count; ++k) {
    const Vec3& a = positions[ids[k]];
    const Vec3& b = positions[ids[(k + 1) % count]];
    n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
              (a.x() - b.x()) * (a.y() + b.y()));
  }
  return n;
}

Vec3 centroid(std::span<const Vec3> positions, const std::uint32_t* ids, int count) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < count; ++k)
    c += positions[ids[k]];
  return c / static_cast<Real>(count);
}

bool contains(const std::uint32_t* ids, int count, std::uint32_t p) {
  return std::find(ids, ids + count, p) != ids + count;
}

// Distinct points of the volume, at most `limit` (returns limit + 1 beyond).
int distinct_points(const VolumeFaces& faces, std::array<std::uint32_t, 9>& out, int limit) {
  int n = 0;
  for (std::uint32_t p : faces.points) {
    if (contains(out.data(), n, p)) continue;
    if (n == limit) return limit + 1;
    out[static_cast<std::size_t>(n++)] = p;
  }
  return n;
}

// For a prism-like volume (wedge, hexahedron) with base face f: the point
// across the side face from each base corner. darts[k] is at base corner k on
// edge (k, k+1); alpha_2 reaches the side face on that edge, alpha_1 turns to
// the side edge at corner k, alpha_0 crosses to the opposite corner.
bool opposite_corners(const GMap& map, const VolumeFaces& faces, std::size_t f,
                      PointLookup point_of, std::uint32_t* top) {
  for (std::uint32_t k = faces.offsets[f]; k < faces.offsets[f + 1]; ++k) {
    const Dart d = faces.darts[k];
    const Dart side = map.alpha(d, 2);
    if (side == d) return false;
    const Dart up = map.alpha(side, 1);
    const Dart opposite = map.alpha(up, 0);
    if (up == side || opposite == up) return false;
    *top++ = point_of(opposite);
  }
  return true;
}

bool is_permutation_of(const std::uint32_t* a, const std::array<std::uint32_t, 9>& all, int count) {
  for (int k = 0; k < count; ++k) {
    if (!contains(all.data(), count, a[k])) return false;
    for (int m = 0; m < k; ++m) {
      if (a[m] == a[k]) return false;
    }
  }
  return true;
}

}  // namespace

bool recognise_volume(const GMap& map, const VolumeFaces& faces, PointLookup point_of,
                      std::span<const Vec3> positions, VolumeCell& cell) {
  const std::size_t face_count = faces.face_count();
  if (face_count < 4 || face_count > 6) return false;
  int triangles = 0;
  int quads = 0;
  for (std::size_t f = 0; f < face_count; ++f) {
    const std::uint32_t size = faces.offsets[f + 1] - faces.offsets[f];
    triangles += size == 3;
    quads += size == 4;
  }
  if (triangles + quads != static_cast<int>(face_count)) return false;
  std::array<std::uint32_t, 9> unique{};
  const int points = distinct_points(faces, unique, 8);
  std::uint32_t* v = cell.v.data();

  if (triangles == 4 && quads == 0 && points == 4) {
    // VTK: (1-0) x (2-0) points toward 3.
    std::copy(faces.points.data(), faces.points.data() + 3, v);
    for (int k = 0; k < 4; ++k) {
      if (!contains(v, 3, unique[static_cast<std::size_t>(k)]))
        v[3] = unique[static_cast<std::size_t>(k)];
    }
    const Vec3& p0 = positions[v[0]];
    if ((positions[v[1]] - p0).cross(positions[v[2]] - p0).dot(positions[v[3]] - p0) < 0) {
      std::swap(v[1], v[2]);
    }
    cell.type = VtkCell::kTetra;
    cell.count = 4;
    return true;
  }
  if (triangles == 4 && quads == 1 && points == 5) {
    // VTK: the quad base 0-3 with its right-hand normal toward the apex 4.
    std::size_t q = 0;
    while (faces.offsets[q + 1] - faces.offsets[q] != 4)
      ++q;
    std::copy(faces.points.data() + faces.offsets[q], faces.points.data() + faces.offsets[q] + 4,
              v);
    for (int k = 0; k < 5; ++k) {
      if (!contains(v, 4, unique[static_cast<std::size_t>(k)]))
        v[4] = unique[static_cast<std::size_t>(k)];
    }
    if (polygon_normal(positions, v, 4).dot(positions[v[4]] - centroid(positions, v, 4)) < 0) {
      std::swap(v[1], v[3]);
    }
    cell.type = VtkCell::kPyramid;
    cell.count = 5;
    return true;
  }
  const bool wedge = triangles == 2 && quads == 3 && points == 6;
  const bool hexahedron = quads == 6 && points == 8;
  if (!wedge && !hexahedron) return false;
  const std::uint32_t base_size = wedge ? 3 : 4;
  std::size_t base = 0;
  while (faces.offsets[base + 1] - faces.offsets[base] != base_size)
    ++base;
  std::copy(faces.points.data() + faces.offsets[base],
            faces.points.data() + faces.offsets[base + 1], v);
  if (!opposite_corners(map, faces, base, point_of, v + base_size)) return false;
  const int corners = static_cast<int>(base_size);
  if (!is_permutation_of(v, unique, 2 * corners)) return false;
  // VTK: a hexahedron's base normal points toward its top, a wedge's away from it.
  const Real toward_top =
      polygon_normal(positions, v, corners)
          .dot(centroid(positions, v + corners, corners) - centroid(positions, v, corners));
  if (corners == 4 ? toward_top < 0 : toward_top > 0) {
    std::swap(v[1], v[corners - 1]);
    std::swap(v[corners + 1], v[2 * corners - 1]);
  }
  cell.type = corners == 4 ? VtkCell::kHexahedron : VtkCell::kWedge;
  cell.count = 2 * corners;
  return true;
}

}  // namespace rift
