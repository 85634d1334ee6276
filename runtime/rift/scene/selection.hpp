// Selections: which vertices a handle, a load or an initial velocity acts
// on. One spelling for every feature of a scene (docs/scenes.md):
//   "top", "left", ...            a side of the bounding box
//   "top-left", ...               a named corner
//   "all"
//   { vertices = [0, 5] }         point indices of the mesh file
//   { box = { min = [..], max = [..] } }
//   { sphere = { center = [..], radius = r } }
//   { group = 3 }                 elements (or VTU points) of a physical group (Gmsh physical
//                                 tag, Medit reference, VTU cell or point data)
//   { side = "left", within = 0.05 }   a band along a side
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rift/gmap/gmap.hpp"

namespace rift {

struct Selection {
  enum class Kind { kAll, kSide, kCorner, kVertices, kBox, kSphere, kGroup };
  Kind kind = Kind::kAll;
  std::string name;                           ///< side or corner name
  Real within = 0;                            ///< side: distance from it (0: on it)
  std::vector<std::int64_t> vertices;         ///< point indices
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  ///< box
  Vec3 centre = Vec3::Zero();
  Real radius = 0;         ///< sphere
  std::int64_t group = 0;  ///< physical group tag
  int line = 0;            ///< in the scene file, for messages

  /// How the selection reads in a message, e.g. "side 'top'".
  std::string describe() const;
};

inline const std::vector<std::string>& side_names() {
  static const std::vector<std::string> names = {"top", "bottom", "left", "right", "front", "back"};
  return names;
}
inline const std::vector<std::string>& corner_names() {
  static const std::vector<std::string> names = {"top-left", "top-right", "bottom-left",
                                                 "bottom-right"};
  return names;
}

/// "Up" without gravity: +z, or +y for a body flat in the x-y plane.
Vec3 default_up(const Vec3& lo, const Vec3& hi);

/// One dart per selected vertex orbit. `up` is the direction against
/// gravity ("top"), zero for default_up; "left"/"right" run along the widest horizontal axis,
/// "front"/"back" along the third one (front toward the default camera).
/// Throws std::invalid_argument for point indices that are not in the mesh.
std::vector<Dart> select_vertices(const GMap& map, const Selection& selection, const Vec3& up);

/// select_vertices for several selections of one map whose vertices and
/// positions do not change between them (a scene's handles, loads and
/// initial velocities): the list of the vertices (a pass over every dart)
/// and the frame of sides and corners (a pass over every vertex) are found
/// at the first selection that needs them and kept. A 10⁶-vertex cloth
/// pinned by two corners swept its 8·10⁶ darts once per corner.
class VertexSelector {
 public:
  VertexSelector(const GMap& map, const Vec3& up) : map_(map), up_(up) {}
  std::vector<Dart> select(const Selection& selection);

  /// The parts found so far, reused by later selections.
  struct Frame {
    Vec3 lo, hi;
    Vec3 up, right, front;
    Real scale = 0;
  };

 private:
  const std::vector<Dart>& vertices();
  const Frame& frame();

  const GMap& map_;
  Vec3 up_;
  bool have_vertices_ = false, have_frame_ = false;
  std::vector<Dart> vertices_;
  Frame frame_;
};

}  // namespace rift
