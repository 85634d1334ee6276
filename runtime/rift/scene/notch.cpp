#include "rift/scene/notch.hpp"

#include <array>
#include <cmath>

namespace rift {

namespace {

// Mean position of the darts of an orbit (a centre good enough to tell which
// side of a plane an element lies on).
Vec3 orbit_centre(const GMap& map, const Embedding<Vec3>& position, Dart d, Orbit o) {
  Vec3 sum = Vec3::Zero();
  Real count = 0;
  map.for_each_in_orbit(d, o, [&](Dart x) {
    sum += position[x];
    count += 1;
  });
  return sum / count;
}

// Unnormalised normal of the face of d in a 2D map (Newell).
Vec3 face_normal(const GMap& map, const Embedding<Vec3>& position, Dart face) {
  Vec3 n = Vec3::Zero();
  Dart d = face;
  int guard = 0;
  do {
    const Dart next = map.alpha(map.alpha(d, 0), 1);
    n += position[d].cross(position[map.alpha(d, 0)]);
    d = next;
  } while (d != face && ++guard < 1024);
  return n;
}

}  // namespace

std::vector<Dart> notch_cut_darts(const GMap& map, const SceneNotch& notch) {
  const Embedding<Vec3> position = map.embedding<Vec3>("position");
  const int n = map.dimension();
  const Vec3 d = notch.to - notch.from;
  std::vector<Dart> cut;
  if (n == 2) {
    map.for_each_cell(Orbit{0, 2}, [&](Dart a) {
      if (map.is_free(a, 2)) return;
      const Dart b = map.alpha(a, 2);
      const Vec3& p = position[a];
      const Vec3& q = position[map.alpha(a, 0)];
      const Vec3 mid = 0.5 * (p + q);
      const Real length = (q - p).norm();
      const Real s = (mid - notch.from).dot(d) / d.squaredNorm();
      if (s < 0 || s > 1) return;
      // Close to the segment's line, in 3D (the sheet may be curved).
      const Vec3 off = mid - notch.from - s * d;
      if (off.norm() > length) return;
      // Walked from a and from b = a@2, the two faces run along their common
      // edge in the same direction, so their normals come out opposite.
      const Vec3 sheet = face_normal(map, position, a) - face_normal(map, position, b);
      const Vec3 across = d.cross(sheet);
      if (across.norm() == 0) return;
      const Real s1 = (orbit_centre(map, position, a, Orbit{0, 1}) - notch.from).dot(across);
      const Real s2 = (orbit_centre(map, position, b, Orbit{0, 1}) - notch.from).dot(across);
      if ((s1 >= 0) != (s2 >= 0)) cut.push_back(a);
    });
    return cut;
  }
  // 3D: the patch from + s d + u e, s, u in [0, 1].
  const Vec3 e = notch.depth;
  const Vec3 normal = d.cross(e);
  if (normal.norm() == 0) return cut;
  const Real dd = d.dot(d), de = d.dot(e), ee = e.dot(e);
  const Real det = dd * ee - de * de;
  map.for_each_cell(Orbit{0, 1, 3}, [&](Dart a) {
    if (map.is_free(a, 3)) return;
    const Vec3 mid = orbit_centre(map, position, a, Orbit{0, 1});
    const Vec3 r = mid - notch.from;
    const Real rd = r.dot(d), re = r.dot(e);
    const Real s = (ee * rd - de * re) / det;
    const Real u = (dd * re - de * rd) / det;
    if (s < 0 || s > 1 || u < 0 || u > 1) return;
    const Real s1 = (orbit_centre(map, position, a, Orbit{0, 1, 2}) - notch.from).dot(normal);
    const Real s2 =
        (orbit_centre(map, position, map.alpha(a, 3), Orbit{0, 1, 2}) - notch.from).dot(normal);
    if ((s1 >= 0) != (s2 >= 0)) cut.push_back(a);
  });
  return cut;
}

std::size_t cut_notch(GMap& map, const SceneNotch& notch, Rule& separate,
                      std::vector<Dart>& touched) {
  const int n = map.dimension();
  std::size_t applied = 0;
  for (Dart a : notch_cut_darts(map, notch)) {
    if (!map.is_alive(a) || map.is_free(a, n)) continue;
    const std::array<Dart, 1> hooks{a};
    if (separate.apply(map, hooks, {}, touched)) ++applied;
  }
  return applied;
}

}  // namespace rift
