#include "rift/output/frame_mesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "rift/output/volume_cells.hpp"

namespace rift {

namespace {

constexpr std::uint32_t kNoPoint = ~0u;

Orbit vertex_orbit_of(int dimension) {
  return Orbit::cell(0, dimension);
}
Orbit element_orbit_of(int dimension) {
  return Orbit::cell(dimension, dimension);
}
// The darts of one face of an element, walked in order: <0,1> in 2D and
// inside a volume in 3D.
constexpr Orbit kFaceInElement{0, 1};

VtkCell polygon_cell(std::size_t count) {
  return count == 3 ? VtkCell::kTriangle : count == 4 ? VtkCell::kQuad : VtkCell::kPolygon;
}

// Walks the face of `start` (alpha_0 then alpha_1, around the polygon) and
// calls visit(dart) with the dart at each corner, on the edge to the next
// corner. Returns false when the face is open (a free alpha_0 or alpha_1).
template <class Visit>
bool walk_face(const GMap& map, Dart start, std::size_t limit, Visit&& visit) {
  Dart cur = start;
  for (std::size_t steps = 0; steps < limit; ++steps) {
    const Dart across = map.alpha(cur, 0);
    if (across == cur) return false;
    visit(cur);
    const Dart next = map.alpha(across, 1);
    if (next == across) return false;
    if (next == start) return true;
    cur = next;
  }
  return false;
}

// Reads one embedding value as a row of doubles or ints into `array`.
template <class T>
void gather(const GMap& map, const std::string& name, std::span<const Dart> darts,
            FrameArray& array) {
  const Embedding<T> e = map.embedding<T>(name);
  const std::size_t n = darts.size();
  if constexpr (std::is_same_v<T, Vec3>) {
    array.components = 3;
    array.integral = false;
    array.reals.resize(3 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& v = e[darts[k]];
      array.reals[3 * k] = v.x();
      array.reals[3 * k + 1] = v.y();
      array.reals[3 * k + 2] = v.z();
    }
  } else if constexpr (std::is_same_v<T, Real>) {
    array.components = 1;
    array.integral = false;
    array.reals.resize(n);
    for (std::size_t k = 0; k < n; ++k)
      array.reals[k] = e[darts[k]];
  } else {
    array.components = 1;
    array.integral = true;
    array.ints.resize(n);
    for (std::size_t k = 0; k < n; ++k)
      array.ints[k] = static_cast<std::int64_t>(e[darts[k]]);
  }
}

// Fills `arrays` from the embeddings named in `names` that live on `orbit`.
void gather_named(const GMap& map, const std::vector<std::string>& names, Orbit orbit,
                  std::span<const Dart> darts, std::vector<FrameArray>& arrays,
                  std::vector<std::string>& unsupported) {
  std::size_t used = 0;
  for (const std::string& name : names) {
    const ColumnBase* column = map.find_column(name);
    if (!column) continue;
    const OrbitAttachment* attachment = map.attachment_of(name);
    const ValueType type = column->type();
    if (attachment->orbit() != orbit || type == ValueType::kMat3) {
      unsupported.push_back(name);
      continue;
    }
    if (arrays.size() <= used) arrays.emplace_back();
    FrameArray& array = arrays[used++];
    array.name = name;
    switch (type) {
      case ValueType::kVec3:
        gather<Vec3>(map, name, darts, array);
        break;
      case ValueType::kReal:
        gather<Real>(map, name, darts, array);
        break;
      case ValueType::kInt:
        gather<std::int64_t>(map, name, darts, array);
        break;
      case ValueType::kBool:
        gather<Bool>(map, name, darts, array);
        break;
      case ValueType::kMat3:
        break;
    }
  }
  arrays.resize(used);
}

}  // namespace

std::size_t FrameMesh::torn_count() const {
  return static_cast<std::size_t>(std::count(torn.begin(), torn.end(), std::uint8_t{1}));
}

bool FrameMesh::bounding_box(Vec3& lo, Vec3& hi) const {
  if (points.empty()) return false;
  lo = hi = points.front();
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return true;
}

std::vector<std::uint8_t> record_boundary_darts(const GMap& map) {
  std::vector<std::uint8_t> flags(map.capacity(), 0);
  const int n = map.dimension();
  map.for_each_dart([&](Dart d) { flags[d] = map.is_free(d, n) ? 1 : 0; });
  return flags;
}

std::vector<std::uint8_t> remap_dart_flags(std::span<const std::uint8_t> flags,
                                           const std::vector<Dart>& new_index) {
  std::size_t size = 0;
  for (Dart d : new_index) {
    if (d != kNoDart) size = std::max<std::size_t>(size, d + 1);
  }
  std::vector<std::uint8_t> out(size, 0);
  for (std::size_t old = 0; old < new_index.size() && old < flags.size(); ++old) {
    if (new_index[old] != kNoDart) out[new_index[old]] = flags[old];
  }
  return out;
}

bool has_free_link(const GMap& map, Dart d) {
  const int n = map.dimension();
  bool free = false;
  map.for_each_in_orbit(d, element_orbit_of(n), [&](Dart x) { free = free || map.is_free(x, n); });
  return free;
}

FrameMesh extract_frame_mesh(const GMap& map, const FrameOptions& options) {
  FrameExtractor extractor(options);
  extractor.extract(map);
  return extractor.frame();
}

bool FrameExtractor::is_tear_dart(const GMap& map, Dart d) const {
  if (!map.is_free(d, map.dimension())) return false;
  if (!options_.torn_darts.empty()) return d < options_.torn_darts.size() && options_.torn_darts[d];
  if (!options_.original_boundary.empty()) {
    return d >= options_.original_boundary.size() || !options_.original_boundary[d];
  }
  return true;
}

const FrameMesh& FrameExtractor::extract(const GMap& map) {
  const int n = map.dimension();
  if (n != 2 && n != 3) {
    throw std::invalid_argument("frame output needs a 2D or 3D map, not " + std::to_string(n) +
                                "D");
  }
  const ColumnBase* position = map.find_column(options_.position);
  position_attachment_ = map.attachment_of(options_.position);
  if (!position || position->type() != ValueType::kVec3 ||
      position_attachment_->orbit() != vertex_orbit_of(n)) {
    throw std::invalid_argument("frame output needs a vec3 embedding '" + options_.position +
                                "' on the vertex orbit " + vertex_orbit_of(n).str());
  }
  if (!options_.element_id.empty()) {
    const ColumnBase* ids = map.find_column(options_.element_id);
    if (ids && (ids->type() != ValueType::kInt ||
                map.attachment_of(options_.element_id)->orbit() != element_orbit_of(n))) {
      throw std::invalid_argument("element id embedding '" + options_.element_id +
                                  "' must hold int values on the element orbit " +
                                  element_orbit_of(n).str());
    }
  }

  FrameMesh& f = frame_;
  f.dimension = n;
  f.connectivity.clear();
  f.offsets.clear();
  f.cell_types.clear();
  f.element_dart.clear();
  f.element_ids.clear();
  f.torn.clear();
  f.polyhedron_faces.clear();
  f.polyhedron_face_offsets.clear();
  f.skipped_elements = 0;
  f.face_vertices.clear();
  f.face_offsets.assign(1, 0);
  f.face_element.clear();
  f.face_torn.clear();
  f.face_edge_kind.clear();
  f.unsupported_arrays.clear();

  number_points(map);
  if (n == 2) {
    extract_faces_2d(map);
  } else {
    extract_volumes_3d(map);
  }
  if (f.polyhedron_faces.empty()) f.polyhedron_face_offsets.clear();
  gather_arrays(map);
  return f;
}

void FrameExtractor::number_points(const GMap& map) {
  // Every vertex orbit owns exactly one position slot, so numbering the live
  // slots numbers the orbits: O(darts), no traversal, and the order stays put
  // from frame to frame until a split appends a slot.
  const OrbitAttachment& att = *position_attachment_;
  const std::size_t slots = att.slot_capacity();
  frame_.point_dart.assign(slots, kNoDart);
  map.for_each_dart([&](Dart d) {
    const Slot s = att.slot(d);
    if (s != kNoSlot && frame_.point_dart[s] == kNoDart) frame_.point_dart[s] = d;
  });
  slot_point_.assign(slots, kNoPoint);
  const Embedding<Vec3> position = map.embedding<Vec3>(options_.position);
  frame_.points.clear();
  std::size_t kept = 0;
  for (std::size_t s = 0; s < slots; ++s) {
    const Dart d = frame_.point_dart[s];
    if (d == kNoDart) continue;
    slot_point_[s] = static_cast<std::uint32_t>(kept);
    frame_.point_dart[kept++] = d;
    frame_.points.push_back(position[d]);
  }
  frame_.point_dart.resize(kept);
}

void FrameExtractor::extract_faces_2d(const GMap& map) {
  FrameMesh& f = frame_;
  const std::size_t limit = map.capacity() + 1;
  map.for_each_cell(kFaceInElement, [&](Dart start) {
    const std::size_t first = f.face_vertices.size();
    bool torn = false;
    const bool closed = walk_face(map, start, limit, [&](Dart d) {
      f.face_vertices.push_back(point_of(d));
      EdgeKind kind = EdgeKind::kInner;
      if (map.is_free(d, 2)) {
        const bool tear = is_tear_dart(map, d) || is_tear_dart(map, map.alpha(d, 0));
        kind = tear ? EdgeKind::kTear : EdgeKind::kBoundary;
        torn = torn || tear;
      }
      f.face_edge_kind.push_back(kind);
    });
    const std::size_t count = f.face_vertices.size() - first;
    const bool positioned = std::find(f.face_vertices.begin() + static_cast<std::ptrdiff_t>(first),
                                      f.face_vertices.end(), kNoPoint) == f.face_vertices.end();
    if (!closed || count < 3 || !positioned) {
      f.face_vertices.resize(first);
      f.face_edge_kind.resize(first);
      ++f.skipped_elements;
      return;
    }
    const auto element = static_cast<std::uint32_t>(f.cell_types.size());
    f.face_offsets.push_back(static_cast<std::uint32_t>(f.face_vertices.size()));
    f.face_element.push_back(element);
    f.face_torn.push_back(torn ? 1 : 0);
    for (std::size_t k = first; k < f.face_vertices.size(); ++k)
      f.connectivity.push_back(f.face_vertices[k]);
    f.offsets.push_back(static_cast<std::int64_t>(f.connectivity.size()));
    f.cell_types.push_back(polygon_cell(count));
    f.element_dart.push_back(start);
    f.torn.push_back(torn ? 1 : 0);
  });
}

void FrameExtractor::extract_volumes_3d(const GMap& map) {
  FrameMesh& f = frame_;
  const std::size_t limit = map.capacity() + 1;
  const Mark seen = map.reserve_mark();
  const PointLookup lookup{position_attachment_, slot_point_.data(), slot_point_.size()};
  VolumeCell cell;
  map.for_each_cell(element_orbit_of(3), [&](Dart start) {
    volume_darts_.clear();
    map.for_each_in_orbit(start, element_orbit_of(3), [&](Dart d) { volume_darts_.push_back(d); });
    local_points_.clear();
    local_darts_.clear();
    local_offsets_.assign(1, 0);
    bool open = false;
    bool torn = false;
    for (Dart d : volume_darts_) {
      torn = torn || is_tear_dart(map, d);
      if (map.is_marked(d, seen)) continue;
      open = !walk_face(map, d, limit, [&](Dart x) {
        map.mark(x, seen);
        map.mark(map.alpha(x, 0), seen);
        local_points_.push_back(point_of(x));
        local_darts_.push_back(x);
      }) || open;
      local_offsets_.push_back(static_cast<std::uint32_t>(local_points_.size()));
    }
    for (Dart d : volume_darts_)
      map.unmark(d, seen);
    // A dart without a position cannot be drawn: treat its volume as open.
    open = open ||
           std::find(local_points_.begin(), local_points_.end(), kNoPoint) != local_points_.end();

    const VolumeFaces faces{local_points_, local_darts_, local_offsets_};
    std::uint32_t element = FrameMesh::kNoElement;
    if (!open && recognise_volume(map, faces, lookup, f.points, cell)) {
      element = static_cast<std::uint32_t>(f.cell_types.size());
      f.connectivity.insert(f.connectivity.end(), cell.v.begin(), cell.v.begin() + cell.count);
      f.cell_types.push_back(cell.type);
      f.polyhedron_face_offsets.push_back(-1);
    } else if (!open && options_.polyhedra) {
      element = static_cast<std::uint32_t>(f.cell_types.size());
      const std::size_t first = f.connectivity.size();
      for (std::uint32_t p : local_points_) {
        if (std::find(f.connectivity.begin() + static_cast<std::ptrdiff_t>(first),
                      f.connectivity.end(), p) == f.connectivity.end()) {
          f.connectivity.push_back(p);
        }
      }
      f.polyhedron_faces.push_back(static_cast<std::int64_t>(faces.face_count()));
      for (std::size_t k = 0; k < faces.face_count(); ++k) {
        f.polyhedron_faces.push_back(local_offsets_[k + 1] - local_offsets_[k]);
        for (std::uint32_t m = local_offsets_[k]; m < local_offsets_[k + 1]; ++m)
          f.polyhedron_faces.push_back(local_points_[m]);
      }
      f.polyhedron_face_offsets.push_back(static_cast<std::int64_t>(f.polyhedron_faces.size()));
      f.cell_types.push_back(VtkCell::kPolyhedron);
    } else {
      ++f.skipped_elements;
    }
    if (element != FrameMesh::kNoElement) {
      f.offsets.push_back(static_cast<std::int64_t>(f.connectivity.size()));
      f.element_dart.push_back(start);
      f.torn.push_back(torn ? 1 : 0);
    }
    if (open) return;

    // Faces with a 3-free dart bound the solid: they are what a renderer sees.
    for (std::size_t k = 0; k < faces.face_count(); ++k) {
      const Dart d0 = local_darts_[local_offsets_[k]];
      if (!map.is_free(d0, 3)) continue;
      const bool face_tear = is_tear_dart(map, d0);
      for (std::uint32_t m = local_offsets_[k]; m < local_offsets_[k + 1]; ++m) {
        f.face_vertices.push_back(local_points_[m]);
        // Turn around the edge through the solid to the next surface face: an
        // edge between a crack face and an original face is the crack's rim.
        const Dart x = local_darts_[m];
        Dart e = map.alpha(x, 2);
        EdgeKind kind = e == x ? EdgeKind::kBoundary : EdgeKind::kInner;
        for (std::size_t steps = 0; steps < limit && !map.is_free(e, 3); ++steps)
          e = map.alpha(map.alpha(e, 3), 2);
        if (kind == EdgeKind::kInner && is_tear_dart(map, e) != face_tear) kind = EdgeKind::kTear;
        f.face_edge_kind.push_back(kind);
      }
      f.face_offsets.push_back(static_cast<std::uint32_t>(f.face_vertices.size()));
      f.face_element.push_back(element);
      f.face_torn.push_back(face_tear ? 1 : 0);
    }
  });
  map.free_mark(seen);
}

void FrameExtractor::gather_arrays(const GMap& map) {
  FrameMesh& f = frame_;
  const int n = map.dimension();
  f.element_ids.resize(f.element_dart.size());
  const ColumnBase* ids =
      options_.element_id.empty() ? nullptr : map.find_column(options_.element_id);
  if (ids) {
    const Embedding<std::int64_t> e = map.embedding<std::int64_t>(options_.element_id);
    for (std::size_t k = 0; k < f.element_dart.size(); ++k)
      f.element_ids[k] = e[f.element_dart[k]];
  } else {
    for (std::size_t k = 0; k < f.element_dart.size(); ++k)
      f.element_ids[k] = static_cast<std::int64_t>(k);
  }
  if (!options_.torn_element.empty() && map.find_column(options_.torn_element)) {
    const ColumnBase* column = map.find_column(options_.torn_element);
    const bool integral = column->type() == ValueType::kInt;
    if ((!integral && column->type() != ValueType::kBool) ||
        map.attachment_of(options_.torn_element)->orbit() != element_orbit_of(n)) {
      throw std::invalid_argument("torn flag embedding '" + options_.torn_element +
                                  "' must hold int or bool values on the element orbit " +
                                  element_orbit_of(n).str());
    }
    for (std::size_t k = 0; k < f.element_dart.size(); ++k) {
      const Dart d = f.element_dart[k];
      const bool torn = integral ? map.embedding<std::int64_t>(options_.torn_element)[d] != 0
                                 : static_cast<bool>(map.embedding<Bool>(options_.torn_element)[d]);
      f.torn[k] = torn ? 1 : 0;
    }
    if (n == 2) {
      for (std::size_t k = 0; k < f.face_element.size(); ++k)
        f.face_torn[k] = f.torn[f.face_element[k]];
    }
  }
  gather_named(map, options_.point_arrays, vertex_orbit_of(n), f.point_dart, f.point_data,
               f.unsupported_arrays);
  gather_named(map, options_.cell_arrays, element_orbit_of(n), f.element_dart, f.cell_data,
               f.unsupported_arrays);
}

}  // namespace rift
