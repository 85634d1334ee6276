#include "rift/sim/mass_model.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "rift/core/huge_pages.hpp"

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

// The corners of element e (its dart), as share_masses counts them.
int count_corners(const GMap& map, Dart e) {
  int count = 0;
  map.for_each_sub_orbit(e, element_orbit(map.dimension()), corner_orbit(map.dimension()),
                         [&](Dart) { ++count; });
  return count;
}

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

// density * measure of each element, as share_masses computes it.
ElementMasses with_density(MeasuredElements elements, Real density) {
  ElementMasses out;
  out.darts = std::move(elements.darts);
  out.masses = std::move(elements.measures);
  for (Real& m : out.masses)
    m = density * m;
  return out;
}

// The density assign_corner_masses_by_total shares the total with.
Real density_for_total(const MeasuredElements& elements, Real total_mass) {
  Real measure = 0;
  for (Real m : elements.measures)
    measure += m;
  if (!(measure > 0)) throw std::invalid_argument("the mesh has zero area or volume");
  return total_mass / measure;
}

// Sets each vertex's mass to the sum of its corners' masses, mass_of(c)
// read at the corner's first dart c. One pass over the darts instead of a
// marked walk of every vertex orbit (48 darts around an inner vertex of a
// hexahedral block: a tenth of its set-up at 10^6 vertices, issue 12): a
// corner lies in one vertex, and is added once, when its first dart in dart
// order is met, so a vertex sums its corners in the order of their first
// darts, whether the masses come from corner slots or from per-dart shares
// (the same bits either way). update_vertex_mass (after a tear) sums in the
// order of its walk, which may round the last bit otherwise. Darts without
// a vertex slot yet (made by hand) get a walk per vertex, in its order.
template <class MassOf>
void sum_corners_into_vertices(const GMap& map, MassOf&& mass_of, Embedding<Real>& vertex_mass) {
  const int n = map.dimension();
  const Orbit vertex = Orbit::cell(0, n);
  const Orbit corner = corner_orbit(n);
  if (!map.slotted_attachment(vertex)) {
    map.for_each_cell(vertex, [&](Dart v) {
      Real m = 0;
      map.for_each_sub_orbit(v, vertex, corner, [&](Dart c) { m += mass_of(c); });
      vertex_mass[v] = m;
    });
    return;
  }
  const std::size_t darts = map.capacity();
  for (std::size_t i = 0; i < darts; ++i) {
    if (map.is_alive(static_cast<Dart>(i))) vertex_mass[static_cast<Dart>(i)] = 0;
  }
  std::vector<std::uint64_t> seen((darts + 63) / 64, 0);  // one bit per dart
  for (std::size_t i = 0; i < darts; ++i) {
    const auto d = static_cast<Dart>(i);
    if (!map.is_alive(d) || (seen[i / 64] >> (i % 64) & 1)) continue;
    map.for_each_in_orbit(d, corner, [&](Dart x) { seen[x / 64] |= std::uint64_t{1} << (x % 64); });
    vertex_mass[d] += mass_of(d);
  }
}

}  // namespace

ElementMasses element_masses_by_density(const GMap& map, Real density,
                                        const Embedding<Vec3>& position) {
  return with_density(measure_elements(map, position), density);
}

ElementMasses element_masses_by_total(const GMap& map, Real total_mass,
                                      const Embedding<Vec3>& position) {
  MeasuredElements elements = measure_elements(map, position);
  const Real density = density_for_total(elements, total_mass);
  return with_density(std::move(elements), density);
}

void vertex_masses_from_elements(const GMap& map, const ElementMasses& elements,
                                 Embedding<Real>& vertex_mass) {
  const int n = map.dimension();
  // Every dart of an element holds its corners' share (mass / corners), as
  // each corner's slot would: a corner lies in one element.
  std::vector<Real> share;
  grow_huge(share, map.capacity(), Real{0});
  for (std::size_t k = 0; k < elements.darts.size(); ++k) {
    const Dart e = elements.darts[k];
    if (!map.is_alive(e)) {
      throw std::logic_error("vertex_masses_from_elements: an element's dart was deleted");
    }
    const Real corner = elements.masses[k] / count_corners(map, e);
    map.for_each_in_orbit(e, element_orbit(n), [&](Dart x) { share[x] = corner; });
  }
  sum_corners_into_vertices(
      map, [&](Dart c) { return share[c]; }, vertex_mass);
  give_back(share);
}

Real assign_corner_masses_by_density(GMap& map, Real density, Embedding<Real>& corner_mass,
                                     const Embedding<Vec3>& position) {
  return share_masses(map, measure_elements(map, position), density, corner_mass);
}

Real assign_corner_masses_by_total(GMap& map, Real total_mass, Embedding<Real>& corner_mass,
                                   const Embedding<Vec3>& position) {
  const MeasuredElements elements = measure_elements(map, position);
  return share_masses(map, elements, density_for_total(elements, total_mass), corner_mass);
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
  sum_corners_into_vertices(
      map, [&](Dart c) { return corner_mass[c]; }, vertex_mass);
}

}  // namespace rift
