#include "rift/scene/selection.hpp"

#include <cmath>
#include <cstdint>
#include <set>
#include <span>
#include <stdexcept>

#include "rift/core/state_embeddings.hpp"

namespace rift {

namespace {

using Frame = VertexSelector::Frame;

// Positions read through a reader: two plain loads a vertex, where an
// Embedding's read also checks the column's storage with an acquire load
// (selecting two corners of a 10^6-vertex cloth took 0.86x the time so).
using PositionReader = EmbeddingReader<Vec3>;

Frame frame_of(std::span<const Dart> vertices, const PositionReader& position,
               const Vec3& up_hint) {
  Frame f;
  f.lo = Vec3::Constant(INFINITY);
  f.hi = Vec3::Constant(-INFINITY);
  for (const Dart d : vertices) {
    f.lo = f.lo.cwiseMin(position[d]);
    f.hi = f.hi.cwiseMax(position[d]);
  }
  f.up = up_hint.norm() > 0 ? Vec3(up_hint.normalized()) : default_up(f.lo, f.hi);
  // The horizontal axis: the coordinate axis least aligned with `up` among
  // those with the largest extent.
  int axis = 0;
  Real best = -1;
  for (int a = 0; a < 3; ++a) {
    const Real extent = (f.hi[a] - f.lo[a]) * (1 - std::abs(f.up[a]));
    if (extent > best + 1e-12) {
      best = extent;
      axis = a;
    }
  }
  f.right = Vec3::Unit(axis);
  f.right = (f.right - f.right.dot(f.up) * f.up).normalized();
  f.front = f.up.cross(f.right);
  f.scale = std::max((f.hi - f.lo).norm(), Real(1e-300));
  return f;
}

}  // namespace

Vec3 default_up(const Vec3& lo, const Vec3& hi) {
  // A sheet lying in the x-y plane is seen from above: y is up on screen.
  const Real extent = (hi - lo).norm();
  if (extent > 0 && hi.z() - lo.z() <= 1e-9 * extent) return Vec3(0, 1, 0);
  return Vec3(0, 0, 1);
}

std::string Selection::describe() const {
  switch (kind) {
    case Kind::kAll:
      return "every vertex";
    case Kind::kSide:
      return "side '" + name + "'";
    case Kind::kCorner:
      return "corner '" + name + "'";
    case Kind::kVertices:
      return "vertices";
    case Kind::kBox:
      return "box";
    case Kind::kSphere:
      return "sphere";
    case Kind::kGroup:
      return "group " + std::to_string(group);
  }
  return "selection";
}

std::vector<Dart> select_vertices(const GMap& map, const Selection& sel, const Vec3& up) {
  return VertexSelector(map, up).select(sel);
}

const std::vector<Dart>& VertexSelector::vertices() {
  if (!have_vertices_) {
    // One dart per vertex: its smallest, in increasing order (for_each_cell).
    vertices_.reserve(map_.embedding<Vec3>(state::kPosition).attachment().live_slots());
    map_.for_each_cell(Orbit::cell(0, map_.dimension()), [&](Dart d) { vertices_.push_back(d); });
    have_vertices_ = true;
  }
  return vertices_;
}

const Frame& VertexSelector::frame() {
  if (!have_frame_) {
    frame_ = frame_of(vertices(), map_.embedding<Vec3>(state::kPosition).reader(), up_);
    have_frame_ = true;
  }
  return frame_;
}

std::vector<Dart> VertexSelector::select(const Selection& sel) {
  const GMap& map = map_;
  // Nothing here adds darts or gives a column storage: a reader holds.
  const PositionReader position = map.embedding<Vec3>(state::kPosition).reader();
  const Orbit vertex = Orbit::cell(0, map.dimension());
  std::vector<Dart> found;
  // The vertices, listed once for every selection's sweeps (the group's
  // walk lists its own).
  const std::vector<Dart> none;
  const std::vector<Dart>& vertices = sel.kind != Selection::Kind::kGroup ? this->vertices() : none;
  auto take_where = [&](auto&& pred) {
    for (const Dart d : vertices) {
      if (pred(d)) found.push_back(d);
    }
  };
  switch (sel.kind) {
    case Selection::Kind::kAll:
      take_where([](Dart) { return true; });
      break;
    case Selection::Kind::kBox:
      take_where([&](Dart d) {
        const Vec3& p = position[d];
        return (p.array() >= sel.lo.array()).all() && (p.array() <= sel.hi.array()).all();
      });
      break;
    case Selection::Kind::kSphere:
      take_where([&](Dart d) { return (position[d] - sel.centre).norm() <= sel.radius; });
      break;
    case Selection::Kind::kVertices: {
      const Embedding<std::int64_t> point = map.embedding<std::int64_t>(state::kPointIndex);
      if (!point) throw std::invalid_argument("the mesh has no point numbers to select from");
      std::set<std::int64_t> wanted(sel.vertices.begin(), sel.vertices.end());
      std::set<std::int64_t> seen;
      take_where([&](Dart d) {
        if (!wanted.count(point[d])) return false;
        seen.insert(point[d]);
        return true;
      });
      for (std::int64_t w : wanted) {
        if (!seen.count(w)) {
          throw std::invalid_argument("vertex " + std::to_string(w) +
                                      " is not a point of the mesh (points are numbered from 0)");
        }
      }
      break;
    }
    case Selection::Kind::kGroup: {
      // The vertices of the group's elements, and the points of the group
      // (VTU point data).
      const Embedding<std::int64_t> tag = map.embedding<std::int64_t>("element_tag");
      const Embedding<std::int64_t> point_tag = map.embedding<std::int64_t>("point_tag");
      if (!tag && !point_tag) break;  // no groups: the caller reports an empty selection
      const Mark m = map.reserve_mark();
      std::vector<Dart> marked;
      map.for_each_dart([&](Dart d) {
        const bool in_group =
            (tag && tag[d] == sel.group) || (point_tag && point_tag[d] == sel.group);
        if (!in_group || map.is_marked(d, m)) return;
        map.for_each_in_orbit(d, vertex, [&](Dart x) {
          map.mark(x, m);
          marked.push_back(x);
        });
        found.push_back(d);
      });
      for (Dart d : marked)
        map.unmark(d, m);
      map.free_mark(m);
      break;
    }
    case Selection::Kind::kSide:
    case Selection::Kind::kCorner: {
      const Frame& f = frame();
      if (sel.kind == Selection::Kind::kSide) {
        Vec3 axis = f.up;
        if (sel.name == "bottom") axis = -f.up;
        if (sel.name == "right") axis = f.right;
        if (sel.name == "left") axis = -f.right;
        if (sel.name == "front") axis = f.front;
        if (sel.name == "back") axis = -f.front;
        Real extreme = -INFINITY;
        for (const Dart d : vertices)
          extreme = std::max(extreme, position[d].dot(axis));
        const Real tolerance = std::max(sel.within, 1e-9 * f.scale);
        take_where([&](Dart d) { return position[d].dot(axis) >= extreme - tolerance; });
      } else {
        const Real sr = sel.name.ends_with("left") ? -1 : 1;
        const Real su = sel.name.starts_with("top") ? 1 : -1;
        Real best_score = -INFINITY;
        Vec3 best_point = Vec3::Zero();
        for (const Dart d : vertices) {
          const Real score = (sr * position[d].dot(f.right) + su * position[d].dot(f.up)) / f.scale;
          if (score > best_score + 1e-12) {
            best_score = score;
            best_point = position[d];
          }
        }
        const Real tolerance = std::max(sel.within, 1e-9 * f.scale);
        take_where([&](Dart d) { return (position[d] - best_point).norm() <= tolerance; });
      }
      break;
    }
  }
  return found;
}

}  // namespace rift
