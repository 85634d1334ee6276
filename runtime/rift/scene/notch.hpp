// Notches: cuts made in the mesh before the first step, as an experimentalist
// saws a notch into a specimen. The cut goes between the elements whose
// centres lie on either side of the notch's line (2D: the segment from -> to,
// in the surface) or plane (3D: the parallelogram from, to, to + depth), over
// the segment's or patch's extent; each of those inner edges (2D) or faces
// (3D) is separated by the packs' own separation rule (separate_faces,
// separate_volumes of rules/topology*.rules), so the G-map stays valid and
// the split vertices' masses follow the rule's updates.
#pragma once

#include <cstddef>
#include <vector>

#include "rift/pack/rule.hpp"
#include "rift/scene/scene.hpp"

namespace rift {

/// The darts (one per edge in 2D, per face in 3D) that the notch separates.
std::vector<Dart> notch_cut_darts(const GMap& map, const SceneNotch& notch);

/// Separates them with `separate` (hooked at each dart); returns how many
/// separations applied and appends the touched darts.
std::size_t cut_notch(GMap& map, const SceneNotch& notch, Rule& separate,
                      std::vector<Dart>& touched);

}  // namespace rift
