// The mass model of §3.3: each element's mass is split among its corners
// (corner_mass on <1> in 2D, <1,2> in 3D); a vertex's mass is the sum of the
// corner masses of its vertex orbit and is recomputed only where a rewrite
// touched the map.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rift/gmap/gmap.hpp"

namespace rift {

/// <1> in 2D, <1,2> in 3D: the corner of one element at one vertex.
inline Orbit corner_orbit(int dimension) {
  return Orbit::all(dimension - 1).without(0);
}
/// <0,1> in 2D, <0,1,2> in 3D.
inline Orbit element_orbit(int dimension) {
  return Orbit::all(dimension - 1);
}

/// Area of a polygon (2D map) or volume of a solid (3D map) of the element
/// containing dart `element`, from the vertex positions. Solids are measured
/// as a fan of tetrahedra from the mean of their corners (exact for
/// star-shaped elements with planar faces): each face a fan from the vertex
/// of its smallest dart, the faces added in the order of their smallest
/// darts, so that the whole map's measures (one pass over its darts) and
/// this function's give the same bits.
Real element_measure(const GMap& map, Dart element, const Embedding<Vec3>& position);

/// Sets corner_mass so that each element gets `density * measure`, split
/// equally among its corners. Returns the total mass.
Real assign_corner_masses_by_density(GMap& map, Real density, Embedding<Real>& corner_mass,
                                     const Embedding<Vec3>& position);

/// Same, with the density chosen so that the whole map weighs `total_mass`.
Real assign_corner_masses_by_total(GMap& map, Real total_mass, Embedding<Real>& corner_mass,
                                   const Embedding<Vec3>& position);

/// One dart of each element, in for_each_cell's order, the element's mass
/// (density times its measure) and its corners' count: what the corner
/// masses are shared from.
struct ElementMasses {
  std::vector<Dart> darts;
  std::vector<Real> masses;
  std::vector<std::uint32_t> corners;
};

/// The elements' masses that assign_corner_masses_by_density shares (the
/// same numbers, bit for bit), without corner masses.
ElementMasses element_masses_by_density(const GMap& map, Real density,
                                        const Embedding<Vec3>& position);
/// The same for assign_corner_masses_by_total.
ElementMasses element_masses_by_total(const GMap& map, Real total_mass,
                                      const Embedding<Vec3>& position);

/// The vertex masses update_all_vertex_masses would sum from the corner
/// masses that these elements' shares give (every term and its order the
/// same, so the same bits), without a corner-mass column: for a map never
/// rewritten, whose corner masses nothing else reads (issue 12, lean
/// memory). Each element's share goes to a per-dart scratch array, given
/// back on return. Throws std::logic_error when an element's dart is dead.
void vertex_masses_from_elements(const GMap& map, const ElementMasses& elements,
                                 Embedding<Real>& vertex_mass);

/// vertex_mass(v) = sum of corner_mass over the distinct corners of v.
void update_vertex_mass(const GMap& map, Dart vertex, const Embedding<Real>& corner_mass,
                        Embedding<Real>& vertex_mass);
/// The same sum from the vertex's darts as for_each_in_orbit lists them from
/// darts[0] (a caller that walked the vertex already): each corner is told
/// by its slot of corner_mass and added at its first dart in that order,
/// the walk's order, so the same bits. No second walk, and no marks.
void update_vertex_mass(const GMap& map, std::span<const Dart> darts,
                        const Embedding<Real>& corner_mass, Embedding<Real>& vertex_mass);
void update_all_vertex_masses(const GMap& map, const Embedding<Real>& corner_mass,
                              Embedding<Real>& vertex_mass);

}  // namespace rift
