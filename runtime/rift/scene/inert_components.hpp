// Components of a scene that cannot act on its mesh, found at set-up so that
// a user learns it before a long run that never tears: an interaction whose
// pattern matches no element (`corotational`, a tetrahedron, on hexahedra),
// and a criterion whose measure reads only forces that no interaction of the
// scene stores on this mesh (`vertex_stress` reads the co-rotational
// tetrahedron's f_fem: it cannot fire on hexahedra, nor with mass-springs).
#pragma once

#include <string>
#include <vector>

#include "rift/pack/pack.hpp"
#include "rift/scene/scene.hpp"
#include "rift/sim/simulation.hpp"

namespace rift {

/// One warning per inert component of `scene`, naming it and why. `sim` is
/// the initialised simulation of the scene (its interactions matched).
std::vector<std::string> inert_component_warnings(const Scene& scene, const PackRegistry& packs,
                                                  const Simulation& sim);

}  // namespace rift
