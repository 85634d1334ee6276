// Recognises a G-map volume as a VTK tetra, pyramid, wedge or hexahedron from
// the faces it is made of, with VTK's vertex ordering and orientation.
// Internal to the frame extraction.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "rift/embed/attachment.hpp"
#include "rift/gmap/gmap.hpp"
#include "rift/output/frame_mesh.hpp"

namespace rift {

/// Maps a dart to its output point through the position slots.
struct PointLookup {
  const OrbitAttachment* attachment;
  const std::uint32_t* slot_point;
  std::size_t slots;
  std::uint32_t operator()(Dart d) const {
    const Slot s = attachment->slot(d);
    return s < slots ? slot_point[s] : ~0u;
  }
};

/// The faces of one volume: face f has points[offsets[f] .. offsets[f+1]),
/// and darts[k] is the dart at points[k] on the edge to the face's next point.
struct VolumeFaces {
  std::span<const std::uint32_t> points;
  std::span<const Dart> darts;
  std::span<const std::uint32_t> offsets;
  std::size_t face_count() const { return offsets.size() - 1; }
};

struct VolumeCell {
  VtkCell type = VtkCell::kPolyhedron;
  int count = 0;
  std::array<std::uint32_t, 8> v{};
};

/// Fills `cell` and returns true when the volume is a tetra, pyramid, wedge or
/// hexahedron (face counts, distinct points and the links between faces all
/// agree); false otherwise. Orientation follows VTK using the positions.
bool recognise_volume(const GMap& map, const VolumeFaces& faces, PointLookup point_of,
                      std::span<const Vec3> positions, VolumeCell& cell);

}  // namespace rift
