#include "rift/sim/mass_model.hpp"

#include <algorithm>
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

// Positions: an Embedding<Vec3>, or its reader in a pass over many faces
// (plain loads, where an Embedding's read checks the column's storage with
// an acquire load: a 10^6-quad cloth's areas read 8·10^6 positions).
template <class Positions>
Real polygon_area(const GMap& map, Dart face, const Positions& position) {
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

constexpr std::uint32_t kNoElement = 0xffffffffu;

// A set of indices below a bound, one bit each: darts of the map, or the
// slots of an attachment.
class IndexBits {
 public:
  explicit IndexBits(std::size_t bound) : words_((bound + 63) / 64, 0) {}
  bool test(std::uint32_t i) const { return (words_[i / 64] >> (i % 64) & 1) != 0; }
  void set(std::uint32_t i) { words_[i / 64] |= std::uint64_t{1} << (i % 64); }

 private:
  std::vector<std::uint64_t> words_;
};

// The same over the darts of one element, listed in increasing order.
class ElementDartBits {
 public:
  explicit ElementDartBits(const std::vector<Dart>& sorted)
      : sorted_(sorted), bits_(sorted.size(), 0) {}
  bool test(Dart d) const { return bits_[index(d)] != 0; }
  void set(Dart d) { bits_[index(d)] = 1; }

 private:
  std::size_t index(Dart d) const {
    return static_cast<std::size_t>(std::lower_bound(sorted_.begin(), sorted_.end(), d) -
                                    sorted_.begin());
  }
  const std::vector<Dart>& sorted_;
  std::vector<char> bits_;
};

// Calls f(x) for each dart of the corner <1> (2D) or <1,2> (3D) of d.
template <class F>
void for_each_corner_dart(const GMap& map, Dart d, F&& f) {
  if (map.dimension() == 2) {
    f(d);
    if (map.alpha(d, 1) != d) f(map.alpha(d, 1));
    return;
  }
  map.for_each_in_two_link_orbit(d, 1, 2, [&](Dart x, int) { f(x); });
}

// Adds to `measure` the fan of tetrahedra from `centre` over the polygon of
// face <0,1>(face), started at the vertex of `face`.
template <class Positions>
void add_face_fan(const GMap& map, Dart face, const Vec3& centre, const Positions& position,
                  Real& measure) {
  const Vec3 p0 = position[face] - centre;
  Vec3 prev = Vec3::Zero();
  int k = 0;
  for_each_face_vertex(map, face, [&](Dart x) {
    const Vec3 p = position[x] - centre;
    if (k >= 2) measure += std::abs(p0.dot(prev.cross(p))) / 6;
    prev = p;
    ++k;
  });
}

// Per element: its corners' count and, for a solid, the sum of its corners'
// positions, then its measure. Whether measured element by element or the
// whole map at once, each sum runs over the same darts in increasing order,
// so both give the same bits: a corner is counted at its smallest dart, and
// a solid's faces are added in the order of their smallest darts, each as a
// fan from the vertex of that dart.
struct ElementSums {
  std::vector<std::uint32_t> corners;
  std::vector<Vec3> centres;
  std::vector<Real> measures;

  explicit ElementSums(std::size_t elements)
      : corners(elements, 0), centres(elements, Vec3::Zero()), measures(elements, 0) {}
};

// for_each_dart(f) calls f with every dart of the elements measured, in
// increasing order; element_of(d) is the index of d's element; firsts[k] is
// element k's smallest dart; Bits is IndexBits or ElementDartBits.
template <class ForEachDart, class ElementOf, class Bits>
void sum_elements(const GMap& map, const std::vector<Dart>& firsts, ForEachDart&& for_each_dart,
                  ElementOf&& element_of, Bits corner_seen, Bits face_seen,
                  const Embedding<Vec3>& position, ElementSums& sums) {
  const bool solid = map.dimension() == 3;
  const EmbeddingReader<Vec3> reader = position.reader();  // polygon_area
  for_each_dart([&](Dart d) {
    if (corner_seen.test(d)) return;
    for_each_corner_dart(map, d, [&](Dart x) { corner_seen.set(x); });
    const std::uint32_t e = element_of(d);
    ++sums.corners[e];
    if (solid) sums.centres[e] += reader[d];
  });
  if (!solid) {
    for (std::size_t k = 0; k < firsts.size(); ++k)
      sums.measures[k] = polygon_area(map, firsts[k], reader);
    return;
  }
  for (std::size_t k = 0; k < firsts.size(); ++k)
    sums.centres[k] /= static_cast<Real>(sums.corners[k]);
  for_each_dart([&](Dart d) {
    if (face_seen.test(d)) return;
    map.for_each_in_two_link_orbit(d, 0, 1, [&](Dart x, int) { face_seen.set(x); });
    const std::uint32_t e = element_of(d);
    add_face_fan(map, d, sums.centres[e], reader, sums.measures[e]);
  });
}

// Calls f(x) for each dart of element <0,1>(d) (2D) or <0,1,2>(d) (3D),
// `visit` telling and recording darts already met (x itself included).
template <class Visit, class F>
void flood_element(const GMap& map, Dart d, std::vector<Dart>& stack, Visit&& visit, F&& f) {
  if (map.dimension() == 2) {
    // A face is a path or a cycle of alpha_0 and alpha_1: walked along it,
    // without the stack and its second look at each dart (a third of a
    // 10^6-vertex cloth's masses, issue 12).
    map.for_each_in_two_link_orbit(d, 0, 1, [&](Dart x, int) {
      if (visit(x)) f(x);
    });
    return;
  }
  const int links = map.dimension();  // alpha_0 .. alpha_{n-1}
  stack.clear();
  if (!visit(d)) return;
  stack.push_back(d);
  while (!stack.empty()) {
    const Dart x = stack.back();
    stack.pop_back();
    f(x);
    for (int i = 0; i < links; ++i) {
      const Dart y = map.alpha(x, i);
      if (visit(y)) stack.push_back(y);
    }
  }
}

}  // namespace

Real element_measure(const GMap& map, Dart element, const Embedding<Vec3>& position) {
  const int n = map.dimension();
  if (n == 2) return polygon_area(map, element, position);
  if (n != 3) throw std::invalid_argument("element_measure: map dimension must be 2 or 3");
  std::vector<Dart> darts;
  map.for_each_in_orbit(element, element_orbit(3), [&](Dart x) { darts.push_back(x); });
  std::sort(darts.begin(), darts.end());
  ElementSums sums(1);
  sum_elements(
      map, {darts.front()},
      [&](auto&& f) {
        for (Dart d : darts)
          f(d);
      },
      [](Dart) { return std::uint32_t{0}; }, ElementDartBits(darts), ElementDartBits(darts),
      position, sums);
  return sums.measures[0];
}

namespace {

// One dart of each element (its smallest), in for_each_cell's order, its
// measure and its corners' count. Both mass set-ups measure the elements
// once, in flat passes over the darts: labelling each dart with its element,
// then summing corners, then faces. Walking each element's corners and faces
// with marks (48 darts a hexahedron, each sub-orbit walked separately) took
// 1.8 s of the set-up of 10^6 hexahedra (issue 12). A surface's corners are
// counted on the labelling walk instead, and its faces measured by
// polygon_area. The labels (4 bytes a dart) are given back on return, unless
// kept for the corner masses.
struct MeasuredElements {
  std::vector<Dart> darts;
  std::vector<Real> measures;
  std::vector<std::uint32_t> corners;
  std::vector<std::uint32_t> element_of;  // by dart; kNoElement for dead darts
};

MeasuredElements measure_elements(const GMap& map, const Embedding<Vec3>& position) {
  const std::size_t n = map.capacity();
  MeasuredElements out;
  grow_huge(out.element_of, n, kNoElement);
  // A surface's corners <1> are counted on the walk that labels its darts:
  // pairs {x, alpha_1 x}, and darts whose alpha_1 is free alone. That saves
  // the corner pass's look at every dart and its bits (a fifth of a
  // 10^6-vertex cloth's masses, issue 12); the counts are the same.
  const bool surface = map.dimension() == 2;
  const OrbitAttachment* elements =
      surface ? nullptr : map.slotted_attachment(element_orbit(map.dimension()));
  if (elements) {
    // A solid whose elements have slots (an assembled mesh's element_index):
    // the labels come from one sweep over the darts, each element labelled
    // when its smallest dart is met, as the walk below labels them. At 10^6
    // hexahedra the walk looked at each of 4.7·10^7 darts and its three
    // links. (A surface's walk along each face costs about what the sweep
    // does, and counts the corners on the way.)
    const Slot* slot = elements->slot_data();
    std::vector<std::uint32_t> label(elements->slot_capacity(), kNoElement);
    out.darts.reserve(elements->live_slots());
    for (std::size_t i = 0; i < n; ++i) {
      if (!map.is_alive(static_cast<Dart>(i))) continue;
      std::uint32_t& k = label[slot[i]];
      if (k == kNoElement) {
        k = static_cast<std::uint32_t>(out.darts.size());
        out.darts.push_back(static_cast<Dart>(i));
      }
      out.element_of[i] = k;
    }
  } else {
    std::vector<Dart> stack;
    for (std::size_t i = 0; i < n; ++i) {
      const auto d = static_cast<Dart>(i);
      if (!map.is_alive(d) || out.element_of[i] != kNoElement) continue;
      const auto k = static_cast<std::uint32_t>(out.darts.size());
      out.darts.push_back(d);
      std::uint32_t darts = 0, alone = 0;
      flood_element(
          map, d, stack,
          [&](Dart x) {
            if (out.element_of[x] != kNoElement) return false;
            out.element_of[x] = k;
            return true;
          },
          [&](Dart x) {
            if (!surface) return;  // a solid's corners are counted by sum_elements
            ++darts;
            alone += map.is_free(x, 1);
          });
      if (surface) out.corners.push_back((darts + alone) / 2);
    }
  }
  if (surface) {
    out.measures.resize(out.darts.size());
    const EmbeddingReader<Vec3> reader = position.reader();
    for (std::size_t k = 0; k < out.darts.size(); ++k)
      out.measures[k] = polygon_area(map, out.darts[k], reader);
    return out;
  }
  ElementSums sums(out.darts.size());
  const std::vector<std::uint32_t>& element_of = out.element_of;
  sum_elements(
      map, out.darts,
      [&](auto&& f) {
        for (std::size_t i = 0; i < n; ++i) {
          if (element_of[i] != kNoElement) f(static_cast<Dart>(i));
        }
      },
      [&](Dart d) { return element_of[d]; }, IndexBits(n), IndexBits(n), position, sums);
  out.measures = std::move(sums.measures);
  out.corners = std::move(sums.corners);
  return out;
}

// Each element gets density * measure, shared equally by its corners; the
// total is summed in element order, as each element's mass is set.
Real share_masses(const GMap& map, MeasuredElements elements, Real density,
                  Embedding<Real>& corner_mass) {
  Real total = 0;
  std::vector<Real> share(elements.darts.size());
  for (std::size_t k = 0; k < elements.darts.size(); ++k) {
    const Real mass = density * elements.measures[k];
    share[k] = mass / static_cast<Real>(elements.corners[k]);
    total += mass;
  }
  give_back(elements.measures);
  const std::size_t n = map.capacity();
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t e = elements.element_of[i];
    if (e != kNoElement) corner_mass[static_cast<Dart>(i)] = share[e];
  }
  return total;
}

// density * measure of each element, as share_masses computes it.
ElementMasses with_density(MeasuredElements elements, Real density) {
  ElementMasses out;
  out.darts = std::move(elements.darts);
  out.masses = std::move(elements.measures);
  out.corners = std::move(elements.corners);
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
  // Every vertex slot starts at zero (free slots too: a slot taken again
  // gets its value then), without a write per dart through its slot.
  std::vector<Real>& vm = vertex_mass.values();
  std::fill(vm.begin(), vm.end(), Real(0));
  const Slot* vertex_slot = vertex_mass.attachment().slot_data();
  // A corner's first dart is its smallest. How it is told, fastest first:
  if (corner.size() == 1) {
    // <1> (2D): the smaller of a dart and its 1-neighbour.
    const int i = corner.first();
    for (std::size_t k = 0; k < darts; ++k) {
      const auto d = static_cast<Dart>(k);
      if (map.is_alive(d) && d <= map.alpha(d, i)) vm[vertex_slot[d]] += mass_of(d);
    }
  } else if (const OrbitAttachment* corners = map.slotted_attachment(corner)) {
    // Corners hold slots: the first dart met of each slot, one bit per slot
    // (a sixth of the darts' bits in 3D) and no walk.
    const Slot* corner_slot = corners->slot_data();
    IndexBits seen(corners->slot_capacity());
    for (std::size_t k = 0; k < darts; ++k) {
      const auto d = static_cast<Dart>(k);
      if (!map.is_alive(d) || seen.test(corner_slot[d])) continue;
      seen.set(corner_slot[d]);
      vm[vertex_slot[d]] += mass_of(d);
    }
  } else {
    IndexBits seen(darts);
    for (std::size_t k = 0; k < darts; ++k) {
      const auto d = static_cast<Dart>(k);
      if (!map.is_alive(d) || seen.test(d)) continue;
      map.for_each_in_orbit(d, corner, [&](Dart x) { seen.set(x); });
      vm[vertex_slot[d]] += mass_of(d);
    }
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
  // Every dart of an element holds its corners' share (mass / corners), as
  // each corner's slot would: a corner lies in one element.
  std::vector<Real> share;
  grow_huge(share, map.capacity(), Real{0});
  IndexBits met(map.capacity());
  std::vector<Dart> stack;
  for (std::size_t k = 0; k < elements.darts.size(); ++k) {
    const Dart e = elements.darts[k];
    if (!map.is_alive(e)) {
      throw std::logic_error("vertex_masses_from_elements: an element's dart was deleted");
    }
    const Real corner = elements.masses[k] / static_cast<Real>(elements.corners[k]);
    flood_element(
        map, e, stack,
        [&](Dart x) {
          if (met.test(x)) return false;
          met.set(x);
          return true;
        },
        [&](Dart x) { share[x] = corner; });
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
  MeasuredElements elements = measure_elements(map, position);
  const Real density = density_for_total(elements, total_mass);
  return share_masses(map, std::move(elements), density, corner_mass);
}

void update_vertex_mass(const GMap& map, Dart vertex, const Embedding<Real>& corner_mass,
                        Embedding<Real>& vertex_mass) {
  const int n = map.dimension();
  Real m = 0;
  map.for_each_sub_orbit(vertex, Orbit::cell(0, n), corner_orbit(n),
                         [&](Dart c) { m += corner_mass[c]; });
  vertex_mass[vertex] = m;
}

void update_vertex_mass(const GMap& map, std::span<const Dart> darts,
                        const Embedding<Real>& corner_mass, Embedding<Real>& vertex_mass) {
  // Each corner holds one slot of corner_mass and no two share one (a valid
  // map), so the first dart of each slot met in the walk's order is where
  // for_each_sub_orbit would add that corner. A tear's vertex has a handful
  // of corners (8 around an inner hexahedral vertex); a vertex with more
  // than kCorners (a fan of many elements) is walked instead.
  constexpr std::size_t kCorners = 32;
  if (darts.empty()) return;
  Slot seen[kCorners];
  std::size_t corners = 0;
  Real m = 0;
  for (const Dart x : darts) {
    const Slot s = corner_mass.slot(x);
    if (std::find(seen, seen + corners, s) != seen + corners) continue;
    if (corners == kCorners) {
      update_vertex_mass(map, darts.front(), corner_mass, vertex_mass);
      return;
    }
    seen[corners++] = s;
    m += corner_mass[x];
  }
  vertex_mass[darts.front()] = m;
}

void update_all_vertex_masses(const GMap& map, const Embedding<Real>& corner_mass,
                              Embedding<Real>& vertex_mass) {
  sum_corners_into_vertices(
      map, [&](Dart c) { return corner_mass[c]; }, vertex_mass);
}

}  // namespace rift
