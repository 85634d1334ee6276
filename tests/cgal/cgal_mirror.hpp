// Builds, in CGAL's Generalized_map, the same map that rift::assemble_gmap
// builds from a MeshData, without any of rift's assembly code: each element is
// made of CGAL polygons (make_combinatorial_polygon), faces of a solid are
// 2-sewn with CGAL's sew<2>, and neighbouring elements are sewn with sew<2>
// (2D) or sew<3> (3D) after matching edges or faces on vertex ids here.
//
// Then compares the two maps: cell counts, validity, and an explicit dart
// isomorphism (a bijection that commutes with every alpha_i and keeps the
// vertex id of each dart).
#pragma once

#include <CGAL/Generalized_map.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/mesh_data.hpp"

namespace rift_cgal {

/// What every CGAL dart carries: the mesh vertex it sits on and its creation
/// serial (CGAL's own dart index costs O(sqrt n) per call).
struct DartInfo {
  std::uint32_t vertex = 0;
  std::uint32_t serial = 0;
};

struct Items {
  template <class Map>
  struct Dart_wrapper {
    using Dart_info = DartInfo;
    using Attributes = std::tuple<>;
  };
};

template <unsigned N>
using CgalMap = CGAL::Generalized_map<N, Items>;

/// Cell counts as `rift info` names them.
struct Counts {
  std::size_t darts = 0, vertices = 0, edges = 0, faces = 0, volumes = 0, components = 0,
              boundary = 0;
  bool valid = false;
  friend bool operator==(const Counts&, const Counts&) = default;
};

std::string to_string(const Counts& c);

/// Counts of a rift map, computed with GMap's own orbit functions.
Counts rift_counts(const rift::GMap& map);

/// Faces of a solid in VTK vertex order. Written here, independently of
/// rift's element_faces, so that a mistake there would show up as a mismatch.
struct SolidFace {
  int count;
  std::array<int, 4> v;
};
std::vector<SolidFace> solid_faces(rift::ElementType type);

template <unsigned N>
class CgalMirror {
 public:
  using Map = CgalMap<N>;
  using Dart = typename Map::Dart_handle;

  /// Builds the map of `mesh`. Sewing failures (two elements whose shared
  /// edge/face CGAL refuses to sew) are collected in errors().
  explicit CgalMirror(const rift::MeshData& mesh);

  Map& map() { return map_; }
  const Map& map() const { return map_; }
  Dart dart(std::uint32_t serial) const { return by_serial_[serial]; }
  std::size_t nonmanifold_shared() const { return nonmanifold_; }
  const std::vector<std::string>& errors() const { return errors_; }

  Counts counts() const;

  /// Builds the bijection rift dart -> CGAL dart by a simultaneous walk from
  /// matching roots (one per component), checking that it commutes with every
  /// alpha_i and that each pair of darts has the same vertex id (rift's
  /// "point_index"). Returns an empty string on success, else what differs.
  /// `rift_to_cgal` is indexed by rift dart, holding CGAL serials.
  std::string match_darts(const rift::GMap& rift_map, std::vector<std::uint32_t>& rift_to_cgal);

  /// After matching: the first dart where alpha_i of the two maps disagree.
  std::string compare_links(const rift::GMap& rift_map,
                            const std::vector<std::uint32_t>& rift_to_cgal) const;

  // Runtime-dimension wrappers of CGAL's templated operations, by serial.
  bool is_free(std::uint32_t d, int i) const;
  std::uint32_t alpha(std::uint32_t d, int i) const;
  bool is_sewable(std::uint32_t a, std::uint32_t b, int i) const;
  void sew(std::uint32_t a, std::uint32_t b, int i);
  void unsew(std::uint32_t d, int i);

 private:
  Dart new_polygon(const std::uint32_t* ids, int count);
  void sew_inside_solid(const std::vector<Dart>& face_darts);
  void sew_neighbours(const std::map<std::array<std::uint32_t, 4>, std::vector<Dart>>& sides);
  /// The dart of the face or edge of `d` that sits on `vertex` and whose
  /// 0-neighbour sits on `other`.
  std::optional<Dart> find_in_side(Dart d, std::uint32_t vertex, std::uint32_t other);

  Map map_;
  std::vector<Dart> by_serial_;
  std::size_t nonmanifold_ = 0;
  std::vector<std::string> errors_;
};

extern template class CgalMirror<2>;
extern template class CgalMirror<3>;

}  // namespace rift_cgal
