// What one frame of output shows, extracted once from a G-map and shared by
// every writer: points (one per vertex orbit, so a split vertex is two points
// and tears open visibly), elements as VTK cells, the boundary surface for
// OBJ and PNG, which elements are torn, and per-point / per-element arrays
// gathered from embeddings.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rift/core/types.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift {

/// VTK cell type codes the writers emit.
enum class VtkCell : std::uint8_t {
  kTriangle = 5,
  kPolygon = 7,
  kQuad = 9,
  kTetra = 10,
  kHexahedron = 12,
  kWedge = 13,
  kPyramid = 14,
  kPolyhedron = 42,
};

/// A per-point or per-element array gathered from an embedding.
struct FrameArray {
  std::string name;
  int components = 1;     ///< 1 (real, int) or 3 (vec3)
  bool integral = false;  ///< values in `ints` (Int64) rather than `reals` (Float64)
  std::vector<Real> reals;
  std::vector<std::int64_t> ints;
};

/// How an edge of a boundary face is drawn.
enum class EdgeKind : std::uint8_t {
  kInner,     ///< an element edge inside the surface
  kBoundary,  ///< on the mesh boundary since the start (or the map is open there)
  kTear,      ///< made by tearing: a torn free edge (2D), the rim of a crack (3D)
};

struct FrameMesh {
  static constexpr std::uint32_t kNoElement = ~0u;

  int dimension = 0;

  /// One point per vertex orbit, in the order of the position embedding's slots.
  std::vector<Vec3> points;
  std::vector<Dart> point_dart;  ///< one dart of each point's vertex orbit

  /// Elements (2D faces, 3D volumes) as VTK cells: `offsets[c]` is the end of
  /// cell c in `connectivity` (VTK's convention).
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  std::vector<VtkCell> cell_types;
  std::vector<Dart> element_dart;  ///< one dart of each element
  std::vector<std::int64_t> element_ids;
  /// 1 when the element has an edge (2D) or face (3D) that tearing made free.
  std::vector<std::uint8_t> torn;
  /// VTK "faces" / "faceoffsets" streams; empty unless a cell is a polyhedron.
  /// polyhedron_face_offsets[c] is the end of cell c's stream, -1 for others.
  std::vector<std::int64_t> polyhedron_faces;
  std::vector<std::int64_t> polyhedron_face_offsets;
  /// Elements not written: open cells (a free alpha_0 or alpha_1), cells with
  /// a dart that has no position, and in 3D unrecognised volumes when
  /// polyhedra are turned off.
  std::size_t skipped_elements = 0;

  /// The surface to render: 2D every face, 3D every face with a 3-free dart.
  /// Face f has the points face_vertices[face_offsets[f] .. face_offsets[f+1]).
  std::vector<std::uint32_t> face_vertices;
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_element;  ///< element index, or kNoElement if skipped
  /// 2D: the face's element is torn; 3D: the face was exposed by tearing.
  std::vector<std::uint8_t> face_torn;
  /// Edge from face_vertices[k] to the next vertex of the same face.
  std::vector<EdgeKind> face_edge_kind;

  std::vector<FrameArray> point_data;
  std::vector<FrameArray> cell_data;
  /// Requested arrays that exist but could not be written (orbit or type).
  std::vector<std::string> unsupported_arrays;

  std::size_t point_count() const { return points.size(); }
  std::size_t element_count() const { return cell_types.size(); }
  std::size_t face_count() const { return face_offsets.size() - 1; }
  std::size_t torn_count() const;
  /// Smallest box holding every point; false when there is no point.
  bool bounding_box(Vec3& lo, Vec3& hi) const;
};

struct FrameOptions {
  /// Vec3 embedding on the vertex orbit giving the points.
  std::string position = "position";
  /// Embeddings on the vertex orbit (real, int, bool or vec3) written as point
  /// data when they exist; missing names are skipped silently.
  std::vector<std::string> point_arrays = {"velocity", "force", "point_index"};
  /// Embeddings on the element orbit written as cell data when they exist.
  std::vector<std::string> cell_arrays;
  /// Int embedding giving element ids; when empty or missing, the cell index.
  std::string element_id = "element_id";
  /// Per dart, 1 where the dart was free (2-free in 2D, 3-free in 3D) in the
  /// original mesh: record_boundary_darts() at set-up. A free dart that is not
  /// flagged (or lies past the end) was made free by tearing.
  std::span<const std::uint8_t> original_boundary;
  /// Per dart, 1 where the caller knows a tear freed the dart; takes
  /// precedence over original_boundary. With neither, every free dart counts
  /// as torn (has_free_link()).
  std::span<const std::uint8_t> torn_darts;
  /// Int or bool embedding on the element orbit, non-zero for a torn element:
  /// per-element flags kept by the rules themselves. When it exists it decides
  /// FrameMesh::torn (the darts above still decide the edges and crack faces).
  std::string torn_element;
  /// 3D volumes that are no tetra, hexahedron, wedge or pyramid: written as
  /// VTK polyhedra (true) or skipped and counted.
  bool polyhedra = true;
};

/// Per dart, 1 where the dart is free in the map's top dimension (2-free in
/// 2D, 3-free in 3D). Record it on the initial map and pass it as
/// FrameOptions::original_boundary; after GMap::compact(), remap it.
std::vector<std::uint8_t> record_boundary_darts(const GMap& map);

/// Flags indexed by old dart renumbered after GMap::compact() (new_index[old]).
std::vector<std::uint8_t> remap_dart_flags(std::span<const std::uint8_t> flags,
                                           const std::vector<Dart>& new_index);

/// True when the element (2D face, 3D volume) of `d` has a free edge (2D) or
/// face (3D): the default "torn" test when the original boundary is unknown.
bool has_free_link(const GMap& map, Dart d);

/// Extracts frames, reusing its buffers from one frame to the next.
class FrameExtractor {
 public:
  FrameExtractor() = default;
  explicit FrameExtractor(FrameOptions options) : options_(std::move(options)) {}

  FrameOptions& options() { return options_; }
  const FrameOptions& options() const { return options_; }

  /// Fills and returns the frame of `map`, valid until the next call.
  /// Throws std::invalid_argument when the position embedding is missing or
  /// is not a vec3 on the vertex orbit, or the element id is not an int.
  const FrameMesh& extract(const GMap& map);
  const FrameMesh& frame() const { return frame_; }

 private:
  void number_points(const GMap& map);
  void extract_faces_2d(const GMap& map);
  void extract_volumes_3d(const GMap& map);
  void gather_arrays(const GMap& map);
  bool is_tear_dart(const GMap& map, Dart d) const;
  /// The point of a dart, or ~0u for a dart without a position (a dart a
  /// rewrite created and has not embedded yet).
  std::uint32_t point_of(Dart d) const {
    const Slot s = position_attachment_->slot(d);
    return s < slot_point_.size() ? slot_point_[s] : ~0u;
  }

  FrameOptions options_;
  FrameMesh frame_;
  const OrbitAttachment* position_attachment_ = nullptr;
  std::vector<std::uint32_t> slot_point_;  // position slot -> point index
  std::vector<Dart> volume_darts_;         // scratch for one volume
  std::vector<std::uint32_t> local_points_;
  std::vector<Dart> local_darts_;
  std::vector<std::uint32_t> local_offsets_;
};

/// One-shot extraction.
FrameMesh extract_frame_mesh(const GMap& map, const FrameOptions& options = {});

}  // namespace rift
