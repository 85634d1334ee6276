#include "rift/sim/mass_model.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace rift {

namespace {

// Calls f(p0, p1, ..., p_{k-1}) style: visits the polygon of face <0,1>(d)
// vertex by vertex, stepping along alpha_1 o alpha_0.
template <class F>
void for_each_face_vertex(const GMap& map, Dart d, F&& f) {
  Dart cur = d;
  std::size_t guard = 0;
  do {
    f(cur);
    const Dart next_edge = map.alpha(map.alpha(cur, 0), 1);
    if (next_edge == map.alpha(cur, 0)) break;  // open polygon: stop at its end
    cur = next_edge;
  } while (cur != d && ++guard < (1u << 20));
}

Real polygon_area(const GMap& map, Dart face, const Embedding<Vec3>& position) {
  // Vector area: half the norm of the sum of p_i x p_{i+1}, valid for any
  // planar polygon placed anywhere in space.
  Vec3 twice_area = Vec3::Zero();
  const Vec3& first = position[face];
  Vec3 prev = first;
  bool started = false;
  for_each_face_vertex(map, face, [&](Dart x) {
    if (started) twice_area += prev.cross(position[x]);
    prev = position[x];
    started = true;
  });
  twice_area += prev.cross(first);
  return 0.5 * twice_area.norm();
}

}  // namespace

Real element_measure(const GMap& map, Dart element, const Embedding<Vec3>& position) {
  const int n = map.dimension();
  if (n == 2) return polygon_area(map, element, position);
  if (n != 3) throw std::invalid_argument("element_measure: map dimension must be 2 or 3");
  const Orbit volume = element_orbit(3);
  Vec3 centre = Vec3::Zero();
  int corners = 0;
  map.for_each_sub_orbit(element, volume, corner_orbit(3), [&](Dart x) {
    centre += position[x];
    ++corners;
  });
  centre /= corners;
  Real measure = 0;
  map.for_each_sub_orbit(element, volume, Orbit{0, 1}, [&](Dart face) {
    const Vec3 p0 = position[face] - centre;
    Vec3 prev = Vec3::Zero();
    int k = 0;
    for_each_face_vertex(map, face, [&](Dart x) {
      const Vec3 p = position[x] - centre;
      if (k >= 2) measure += std::abs(p0.dot(prev.cross(p))) / 6;
      prev = p;
      ++k;
    });
  });
  return measure;
}

namespace {

// One dart of each element, in for_each_cell's order, and its measure. Both
// mass set-ups walk the elements once: measuring each element twice (for the
// total, then for the masses) and walking its corners twice (to count them,
// then to share the mass) were a fifth of a 10^6-hexahedron set-up (issue 12).
struct MeasuredElements {
  std::vector<Dart> darts;
  std::vector<Real> measures;
};

MeasuredElements measure_elements(const GMap& map, const Embedding<Vec3>& position) {
  MeasuredElements out;
  map.for_each_cell(element_orbit(map.dimension()), [&](Dart e) {
    out.darts.push_back(e);
    out.measures.push_back(element_measure(map, e, position));
  });
  return out;
}

// Each element gets density * measure, shared equally by its corners; the
// total is summed in element order, as each element's mass is set.
Real share_masses(const GMap& map, const MeasuredElements& elements, Real density,
                  Embedding<Real>& corner_mass) {
  const int n = map.dimension();
  const Orbit element = element_orbit(n);
  const Orbit corner = corner_orbit(n);
  std::vector<Dart> corners;
  Real total = 0;
  for (std::size_t k = 0; k < elements.darts.size(); ++k) {
    const Real mass = density * elements.measures[k];
    corners.clear();
    map.for_each_sub_orbit(elements.darts[k], element, corner,
                           [&](Dart c) { corners.push_back(c); });
    const auto count = static_cast<int>(corners.size());
    for (Dart c : corners)
      corner_mass[c] = mass / count;
    total += mass;
  }
  return total;
}

}  // namespace

Real assign_corner_masses_by_density(GMap& map, Real density, Embedding<Real>& corner_mass,
                                     const Embedding<Vec3>& position) {
  return share_masses(map, measure_elements(map, position), density, corner_mass);
}

Real assign_corner_masses_by_total(GMap& map, Real total_mass, Embedding<Real>& corner_mass,
                                   const Embedding<Vec3>& position) {
  const MeasuredElements elements = measure_elements(map, position);
  Real measure = 0;
  for (Real m : elements.measures)
    measure += m;
  if (!(measure > 0)) throw std::invalid_argument("the mesh has zero area or volume");
  return share_masses(map, elements, total_mass / measure, corner_mass);
}

void update_vertex_mass(const GMap& map, Dart vertex, const Embedding<Real>& corner_mass,
                        Embedding<Real>& vertex_mass) {
  const int n = map.dimension();
  Real m = 0;
  map.for_each_sub_orbit(vertex, Orbit::cell(0, n), corner_orbit(n),
                         [&](Dart c) { m += corner_mass[c]; });
  vertex_mass[vertex] = m;
}

void update_all_vertex_masses(const GMap& map, const Embedding<Real>& corner_mass,
                              Embedding<Real>& vertex_mass) {
  map.for_each_cell(Orbit::cell(0, map.dimension()),
                    [&](Dart v) { update_vertex_mass(map, v, corner_mass, vertex_mass); });
}

}  // namespace rift
