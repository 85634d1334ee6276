#include "rift/mesh/assemble.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "rift/core/huge_pages.hpp"
#include "rift/gmap/state_columns.hpp"
#include "rift/mesh/element_faces.hpp"
#include "rift/mesh/mesh_error.hpp"

namespace rift {

namespace {

// The sides of the shared entities (edges in 2D, faces in 3D) waiting for
// their twins, bucketed by their smallest vertex (a counting sort, O(n)) as
// they are made: twins are then found by comparing a handful of neighbours,
// read in order, instead of hashing. Each side is counted first
// (count(smallest vertex)), then placed in the same order.
//
// A bucket entry carries the rest of its side's key and its first dart:
// there is no side record to write and read back (4 M records of 24 bytes
// at 10^6 quads, the assembly's largest temporary), nor to read at random
// from the buckets (a sixth of that assembly's time, issue 12).
class SideBuckets {
 public:
  struct Side {
    std::array<std::uint32_t, 3> rest;  // the sorted key but its smallest id; unused = ~0u
    Dart first_dart;                    // first of the entity's consecutive darts
    /// The entity's vertex count.
    std::uint32_t ids() const { return 1 + (rest[0] != ~0u) + (rest[1] != ~0u) + (rest[2] != ~0u); }
    // Field by field: std::array's operator== called memcmp per pair.
    bool same_rest(const Side& o) const {
      return rest[0] == o.rest[0] && rest[1] == o.rest[1] && rest[2] == o.rest[2];
    }
  };

  explicit SideBuckets(std::size_t point_count) : start_(point_count + 1, 0) {}

  void count(std::uint32_t smallest) { ++start_[smallest + 1]; }

  /// After every count: room for the sides, each bucket empty.
  void start_placing() {
    for (std::size_t p = 0; p + 1 < start_.size(); ++p)
      start_[p + 1] += start_[p];
    fill_.assign(start_.begin(), start_.end() - 1);
    // As large as the map's links: advised for huge pages before its first
    // touch, like them (rift/core/huge_pages.hpp).
    grow_huge(sides_, start_.back(), Side{});
  }

  /// The side of `count` (at most four) vertex ids whose darts start at `first`.
  void place(const std::uint32_t* ids, std::uint32_t count, Dart first) {
    std::array<std::uint32_t, 4> key = {~0u, ~0u, ~0u, ~0u};
    // Insertion sort of at most four ids (std::sort trips GCC 12's
    // array-bounds analysis here).
    for (std::uint32_t i = 0; i < count; ++i) {
      std::uint32_t j = i;
      while (j > 0 && key[j - 1] > ids[i]) {
        key[j] = key[j - 1];
        --j;
      }
      key[j] = ids[i];
    }
    // A side placed that was not counted would spill into the next bucket.
    if (fill_[key[0]] == start_[key[0] + 1]) {
      throw std::logic_error("assemble_gmap: a side was placed that was not counted");
    }
    Side& s = sides_[fill_[key[0]]++];
    s.rest = {key[1], key[2], key[3]};
    s.first_dart = first;
  }

  /// Calls sew(a, b) for each pair of twins, in order of their smallest
  /// vertex, then of placing; returns the sides left free because a third
  /// one had the same key (a non-manifold edge or face).
  template <class Sew>
  std::size_t pair(Sew&& sew) {
    std::size_t nonmanifold = 0;
    for (std::size_t p = 0; p + 1 < start_.size(); ++p) {
      for (std::uint32_t a = start_[p]; a < start_[p + 1]; ++a) {
        Side& sa = sides_[a];
        if (sa.first_dart == kPaired) continue;
        bool paired = false;
        for (std::uint32_t b = a + 1; b < start_[p + 1]; ++b) {
          Side& sb = sides_[b];
          if (sb.first_dart == kPaired || !sb.same_rest(sa)) continue;
          if (!paired) {
            sew(sa, sb);
            paired = true;
          } else {
            ++nonmanifold;  // a third element on the same edge/face stays free there
          }
          sb.first_dart = kPaired;
        }
        sa.first_dart = kPaired;
      }
    }
    return nonmanifold;
  }

 private:
  static constexpr Dart kPaired = kNoDart;  // a placed side's dart once it is paired
  std::vector<std::uint32_t> start_;        // bucket p: sides_[start_[p], start_[p + 1])
  std::vector<std::uint32_t> fill_;         // next free entry of each bucket
  std::vector<Side> sides_;
};

// Local alpha_2 pairing inside one solid: dart k (0-based over its faces'
// darts) is 2-linked with pairing[k]. Computed once per element type.
struct SolidLayout {
  std::vector<std::uint8_t> dart_vertex;  // local vertex of each dart
  std::vector<std::uint8_t> pairing;
  std::vector<std::uint8_t> face_first;  // first local dart of each face
};

SolidLayout make_layout(ElementType type) {
  SolidLayout layout;
  std::vector<std::uint8_t> other;  // the other vertex of the dart's edge
  for (const LocalFace& f : element_faces(type)) {
    layout.face_first.push_back(static_cast<std::uint8_t>(layout.dart_vertex.size()));
    for (int e = 0; e < f.count; ++e) {
      const std::uint8_t a = f.v[e];
      const std::uint8_t b = f.v[(e + 1) % f.count];
      layout.dart_vertex.push_back(a);
      other.push_back(b);
      layout.dart_vertex.push_back(b);
      other.push_back(a);
    }
  }
  const std::size_t n = layout.dart_vertex.size();
  layout.pairing.assign(n, 0);
  auto face_of = [&](std::size_t k) {
    std::size_t f = 0;
    while (f + 1 < layout.face_first.size() && layout.face_first[f + 1] <= k)
      ++f;
    return f;
  };
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t m = 0; m < n; ++m) {
      if (m != k && face_of(m) != face_of(k) && layout.dart_vertex[m] == layout.dart_vertex[k] &&
          other[m] == other[k]) {
        layout.pairing[k] = static_cast<std::uint8_t>(m);
      }
    }
  }
  return layout;
}

const SolidLayout& layout_of(ElementType type) {
  static const SolidLayout kLayouts[] = {
      SolidLayout{}, make_layout(ElementType::Tetra), make_layout(ElementType::Hexa),
      make_layout(ElementType::Wedge), make_layout(ElementType::Pyramid)};
  return kLayouts[static_cast<int>(type)];
}

// `seen[p]` holds the index of the last element that visited point p, which
// finds a repeated vertex in one pass however large the element (a single
// polygon of 300,000 vertices is a valid 2D mesh).
void validate_element(const MeshData& mesh, const MeshElement& e, std::size_t index,
                      std::vector<std::uint32_t>& seen) {
  auto fail = [&](const std::string& what) {
    throw MeshError(
        mesh.source, e.source_line,
        std::string(element_name(e.type)) + " (element " + std::to_string(index + 1) + ") " + what);
  };
  if (element_dimension(e.type) != mesh.dimension) {
    fail("does not belong in a " + std::to_string(mesh.dimension) + "D mesh");
  }
  const int expected = element_vertex_count(e.type);
  if (expected == 0 ? e.count < 3 : static_cast<int>(e.count) != expected) {
    fail("has " + std::to_string(e.count) + " vertices, expected " +
         (expected == 0 ? std::string("at least 3") : std::to_string(expected)));
  }
  const std::uint32_t* v = mesh.vertices_of(e);
  const auto stamp = static_cast<std::uint32_t>(index);
  for (std::uint32_t k = 0; k < e.count; ++k) {
    if (v[k] >= mesh.points.size()) {
      fail("refers to vertex " + std::to_string(v[k] + 1) + " but the mesh has " +
           std::to_string(mesh.points.size()) + " vertices");
    }
    if (seen[v[k]] == stamp) {
      fail("repeats vertex " + std::to_string(v[k] + 1) +
           (expected == 0 ? std::string()
                          : " (a collapsed element: write it as the element it collapses to, "
                            "a wedge, pyramid or tetrahedron)"));
    }
    seen[v[k]] = stamp;
  }
}

// For each corner of a solid in VTK ordering, three neighbours (a, b, c) such
// that (p_a - p)x(p_b - p).(p_c - p) > 0 when the solid is positively oriented.
// A pyramid's apex has four neighbours and is left out: its base corners decide.
struct Corner {
  std::uint8_t at, a, b, c;
};
constexpr Corner kTetraCorners[] = {{0, 1, 2, 3}};
constexpr Corner kHexaCorners[] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                   {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
// VTK's wedge has its first triangle's normal pointing out of the element.
constexpr Corner kWedgeCorners[] = {{0, 2, 1, 3}, {1, 0, 2, 4}, {2, 1, 0, 5},
                                    {3, 4, 5, 0}, {4, 5, 3, 1}, {5, 3, 4, 2}};
constexpr Corner kPyramidCorners[] = {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}};

std::span<const Corner> corners_of(ElementType type) {
  switch (type) {
    case ElementType::Tetra:
      return kTetraCorners;
    case ElementType::Hexa:
      return kHexaCorners;
    case ElementType::Wedge:
      return kWedgeCorners;
    case ElementType::Pyramid:
      return kPyramidCorners;
    case ElementType::Polygon:
      break;
  }
  return {};
}

// The vertex order of the mirror image: what turns an inverted solid around.
void reverse_orientation(ElementType type, std::array<std::uint32_t, 8>& ids) {
  switch (type) {
    case ElementType::Tetra:
      std::swap(ids[1], ids[2]);
      break;
    case ElementType::Hexa:
      std::swap_ranges(ids.begin(), ids.begin() + 4, ids.begin() + 4);
      break;
    case ElementType::Wedge:
      std::swap_ranges(ids.begin(), ids.begin() + 3, ids.begin() + 3);
      break;
    case ElementType::Pyramid:
      std::swap(ids[1], ids[3]);
      break;
    case ElementType::Polygon:
      break;
  }
}

enum class Shape { kGood, kFlat, kInverted, kTangled, kTangledMostlyInverted };

// A corner whose triple product is within `tolerance` of zero (relative to the
// longest edge cubed) is degenerate, not inverted: a hexahedron with a
// collapsed edge is still a valid solid.
Shape solid_shape(const MeshData& mesh, ElementType type, const std::array<std::uint32_t, 8>& ids) {
  constexpr Real kTolerance = 1e-13;
  Real longest = 0;
  std::array<Real, 8> det{};
  const auto corners = corners_of(type);
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Corner& c = corners[k];
    const Vec3& p = mesh.points[ids[c.at]];
    const Vec3 a = mesh.points[ids[c.a]] - p;
    const Vec3 b = mesh.points[ids[c.b]] - p;
    const Vec3 d = mesh.points[ids[c.c]] - p;
    longest = std::max({longest, a.squaredNorm(), b.squaredNorm(), d.squaredNorm()});
    det[k] = a.cross(b).dot(d);
  }
  const Real tolerance = kTolerance * longest * std::sqrt(longest);
  Real sum = 0;  // not the volume, but its sign says which orientation dominates
  int positive = 0, negative = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    sum += det[k];
    positive += det[k] > tolerance;
    negative += det[k] < -tolerance;
  }
  if (positive > 0 && negative > 0) {
    return sum < 0 ? Shape::kTangledMostlyInverted : Shape::kTangled;
  }
  if (positive == 0 && negative == 0) return Shape::kFlat;
  return negative > 0 ? Shape::kInverted : Shape::kGood;
}

// Newell's normal: twice the vector area of a polygon, planar or not.
bool polygon_is_flat(const MeshData& mesh, const std::uint32_t* v, std::uint32_t count) {
  Vec3 twice_area = Vec3::Zero();
  Real longest = 0;
  // Relative to the first vertex, so that a small polygon far from the origin
  // does not lose its area to cancellation.
  const Vec3& origin = mesh.points[v[0]];
  for (std::uint32_t i = 0; i < count; ++i) {
    const Vec3 p = mesh.points[v[i]] - origin;
    const Vec3 q = mesh.points[v[(i + 1) % count]] - origin;
    twice_area += p.cross(q);
    longest = std::max(longest, (q - p).squaredNorm());
  }
  return twice_area.norm() <= 2e-13 * longest;
}

void note(std::size_t& count, ElementExample& first, const MeshElement& e, std::size_t index) {
  if (count++ == 0) first = {index, e.source_line, e.type};
}

std::string example(const ElementExample& e) {
  std::string s = std::string(element_name(e.type)) + " " + std::to_string(e.index + 1);
  if (e.line > 0) s += ", line " + std::to_string(e.line);
  return s;
}

}  // namespace

std::vector<std::string> assembly_warnings(const AssemblyReport& r, int dimension) {
  std::vector<std::string> out;
  if (r.reoriented_solids > 0) {
    out.push_back(std::to_string(r.reoriented_solids) +
                  " inverted solids were reoriented (first: " + example(r.first_reoriented) + ")");
  }
  if (r.flat_elements > 0) {
    out.push_back(std::to_string(r.flat_elements) + " elements have zero " +
                  (dimension == 3 ? "volume" : "area") +
                  " and carry no mass or stiffness (first: " + example(r.first_flat) + ")");
  }
  if (r.tangled_solids > 0) {
    out.push_back(std::to_string(r.tangled_solids) +
                  " solids are tangled: their corners disagree on the orientation (first: " +
                  example(r.first_tangled) + ")");
  }
  if (r.nonmanifold_shared > 0) {
    out.push_back(std::to_string(r.nonmanifold_shared) + " " +
                  (dimension == 3 ? "faces" : "edges") +
                  " shared by more than two elements were left unsewn");
  }
  return out;
}

GMap assemble_gmap(const MeshData& mesh, AssemblyReport* report) {
  AssemblyReport local;
  AssemblyReport& rep = report ? *report : local;
  rep = {};
  if (mesh.dimension != 2 && mesh.dimension != 3) {
    throw MeshError(mesh.source, 0, "unsupported mesh dimension " + std::to_string(mesh.dimension));
  }
  if (mesh.elements.empty()) throw MeshError(mesh.source, 0, "the mesh has no element");
  for (std::size_t p = 0; p < mesh.points.size(); ++p) {
    if (!mesh.points[p].allFinite()) {
      throw MeshError(mesh.source, 0,
                      "vertex " + std::to_string(p + 1) + " has a non-finite coordinate");
    }
    if (mesh.points[p].cwiseAbs().maxCoeff() > kMaxCoordinate) {
      throw MeshError(mesh.source, 0,
                      "vertex " + std::to_string(p + 1) +
                          " has a coordinate beyond +-1e30, the largest rift accepts (areas and "
                          "volumes would overflow); rescale the mesh");
    }
  }

  std::size_t dart_count = 0;
  {
    std::vector<std::uint32_t> seen(mesh.points.size(), ~0u);
    for (std::size_t k = 0; k < mesh.elements.size(); ++k)
      validate_element(mesh, mesh.elements[k], k, seen);
  }
  // The darts, and each side counted in its bucket: a side's smallest vertex
  // does not depend on the order of its vertices, which a reoriented solid
  // changes below.
  SideBuckets sides(mesh.points.size());
  for (const MeshElement& e : mesh.elements) {
    const std::uint32_t* v = mesh.vertices_of(e);
    if (mesh.dimension == 2) {
      dart_count += 2 * std::size_t{e.count};
      for (std::uint32_t i = 0; i < e.count; ++i)
        sides.count(std::min(v[i], v[i + 1 == e.count ? 0 : i + 1]));
      continue;
    }
    dart_count += layout_of(e.type).dart_vertex.size();
    for (const LocalFace& f : element_faces(e.type)) {
      std::uint32_t smallest = v[f.v[0]];
      for (int i = 1; i < f.count; ++i)
        smallest = std::min(smallest, v[f.v[i]]);
      sides.count(smallest);
    }
  }
  sides.start_placing();

  const int n = mesh.dimension;
  GMap map(n);
  const Dart first = map.create_darts(dart_count);
  // Per-dart scratch, advised for huge pages before the first touch: faulted
  // in 4 KiB at a time it was a tenth of a large set-up's page faults
  // (issue 12).
  std::vector<std::uint32_t> dart_point;
  grow_huge(dart_point, dart_count, 0u);

  Dart next = first;
  // Each element's first dart: its darts are [start, next start), one orbit
  // of the element cells (number_orbits_by_runs below).
  std::vector<Dart> element_start;
  element_start.reserve(mesh.elements.size());
  std::array<std::uint32_t, 8> ids{};
  for (std::size_t index = 0; index < mesh.elements.size(); ++index) {
    const MeshElement& e = mesh.elements[index];
    element_start.push_back(next);
    const std::uint32_t* v = mesh.vertices_of(e);
    if (n == 2) {
      const std::uint32_t k = e.count;
      if (polygon_is_flat(mesh, v, k)) note(rep.flat_elements, rep.first_flat, e, index);
      for (std::uint32_t i = 0; i < k; ++i) {
        const std::uint32_t after = i + 1 == k ? 0 : i + 1;  // not `% k`: a division per dart
        const Dart d0 = next + 2 * i;                        // at v[i], on edge v[i] v[i+1]
        const Dart d1 = d0 + 1;                              // at v[i+1]
        map.link(d0, d1, 0);
        map.link(d1, next + 2 * after, 1);
        dart_point[d0 - first] = v[i];
        dart_point[d1 - first] = v[after];
        const std::uint32_t edge[2] = {v[i], v[after]};
        sides.place(edge, 2, d0);
      }
      next += 2 * k;
      continue;
    }
    std::copy(v, v + e.count, ids.begin());
    switch (solid_shape(mesh, e.type, ids)) {
      case Shape::kGood:
        break;
      case Shape::kFlat:
        note(rep.flat_elements, rep.first_flat, e, index);
        break;
      case Shape::kInverted:
        reverse_orientation(e.type, ids);
        note(rep.reoriented_solids, rep.first_reoriented, e, index);
        break;
      case Shape::kTangledMostlyInverted:
        reverse_orientation(e.type, ids);
        [[fallthrough]];
      case Shape::kTangled:
        note(rep.tangled_solids, rep.first_tangled, e, index);
        break;
    }
    const SolidLayout& layout = layout_of(e.type);
    const auto faces = element_faces(e.type);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const std::uint32_t c = faces[f].count;
      const Dart fd = next + layout.face_first[f];
      for (std::uint32_t i = 0; i < c; ++i) {
        map.link(fd + 2 * i, fd + 2 * i + 1, 0);
        map.link(fd + 2 * i + 1, fd + 2 * (i + 1 == c ? 0 : i + 1), 1);
      }
      std::uint32_t face_ids[4];
      for (std::uint32_t i = 0; i < c; ++i)
        face_ids[i] = ids[faces[f].v[i]];
      sides.place(face_ids, c, fd);
    }
    for (std::size_t k = 0; k < layout.dart_vertex.size(); ++k) {
      dart_point[next + k - first] = ids[layout.dart_vertex[k]];
      if (k < layout.pairing[k]) map.link(next + k, next + layout.pairing[k], 2);
    }
    next += static_cast<Dart>(layout.dart_vertex.size());
  }

  const int sew_dim = n;  // 2-sew edges in 2D, 3-sew faces in 3D
  using Side = SideBuckets::Side;
  rep.nonmanifold_shared = sides.pair([&](const Side& a, const Side& b) {
    if (n == 2) {
      // An edge's two darts: same first vertex, or the edge runs the
      // other way in b's face.
      const bool same = dart_point[a.first_dart - first] == dart_point[b.first_dart - first];
      map.link(a.first_dart, b.first_dart + (same ? 0 : 1), sew_dim);
      map.link(a.first_dart + 1, b.first_dart + (same ? 1 : 0), sew_dim);
      return;
    }
    // Pair darts by (vertex, other end of their edge): that respects alpha_0
    // and alpha_1 whatever the two elements' orientations.
    const std::uint32_t darts = 2 * a.ids();  // a face's, on either side
    for (std::uint32_t i = 0; i < darts; ++i) {
      const Dart da = a.first_dart + i;
      const std::uint32_t pa = dart_point[da - first];
      const std::uint32_t qa = dart_point[map.alpha(da, 0) - first];
      for (std::uint32_t j = 0; j < darts; ++j) {
        const Dart db = b.first_dart + j;
        if (dart_point[db - first] == pa && dart_point[map.alpha(db, 0) - first] == qa) {
          map.link(da, db, sew_dim);
          break;
        }
      }
    }
  });

  // The sides are the largest temporary: freed before the embeddings
  // allocate their slot arrays, to keep the peak memory low.
  sides = SideBuckets(0);

  Embedding<Vec3> position = state_embedding<Vec3>(map, state::kPosition);
  Embedding<std::int64_t> point_index = state_embedding<std::int64_t>(map, state::kPointIndex);
  // An element's darts are linked below the map's dimension only among
  // themselves, all of them: each element is one orbit of the element cells,
  // numbered by its run of darts rather than walked (the walk of a 10^6-vertex
  // hexahedral block's volumes looked at each of its 4.7·10^7 darts three times).
  map.number_orbits_by_runs(Orbit::all(n - 1), element_start);
  Embedding<std::int64_t> element_index = state_embedding<std::int64_t>(map, state::kElementIndex);
  // Physical groups, when the file gave one per element (scene selections).
  Embedding<std::int64_t> element_tag;
  if (!mesh.element_tags.empty() && mesh.element_tags.size() == mesh.elements.size()) {
    element_tag = map.add_embedding<std::int64_t>("element_tag", Orbit::all(n - 1),
                                                  MergePolicy::kKeepFirst, 0);
  }
  for (std::size_t k = 0; k < mesh.elements.size(); ++k) {
    element_index[element_start[k]] = static_cast<std::int64_t>(k);
    if (element_tag) element_tag[element_start[k]] = mesh.element_tags[k];
  }
  element_start = {};
  // Point groups (VTU point data), for the same selections.
  Embedding<std::int64_t> point_tag;
  if (!mesh.point_tags.empty() && mesh.point_tags.size() == mesh.points.size()) {
    point_tag =
        map.add_embedding<std::int64_t>("point_tag", vertex_orbit(n), MergePolicy::kKeepFirst, 0);
  }
  // The three live on the vertices' one attachment, fresh: its slots were
  // numbered in the order of each orbit's smallest dart, so the sweep below
  // meets slot s for the first time after every slot before it. Each vertex
  // is written once, by its first dart, instead of by each of its darts.
  const OrbitAttachment& vertices = position.attachment();
  std::vector<Vec3>& position_of = position.values();
  std::vector<std::int64_t>& point_of = point_index.values();
  std::vector<std::int64_t>* tag_of = point_tag ? &point_tag.values() : nullptr;
  std::vector<std::uint8_t> referenced(mesh.points.size(), 0);
  Slot written = 0;  // slots below it hold their values
  for (std::size_t k = 0; k < dart_count; ++k) {
    const std::uint32_t p = dart_point[k];
    referenced[p] = 1;
    const Slot s = vertices.slot(first + static_cast<Dart>(k));
    if (s < written) continue;
    position_of[s] = mesh.points[p];
    point_of[s] = p;
    if (tag_of) (*tag_of)[s] = mesh.point_tags[p];
    if (s == written) ++written;
  }
  rep.unused_points = static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), 0));
  return map;
}

}  // namespace rift
