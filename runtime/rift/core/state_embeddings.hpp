// The simulator's state embeddings, declared once for the runtime and for
// riftc. The runtime (mesh assembly, Simulation) creates its columns from
// this table, and riftc declares the same embeddings in every pack it
// compiles, so a rule that merges two vertices merges their velocities with
// the policy the simulator expects, and no pack can declare them otherwise.
// The table is plain data on purpose: riftc includes this header and nothing
// else of the runtime.
#pragma once

#include <string_view>

namespace rift::state {

/// The orbit a state embedding lives on, in a map of dimension n.
enum class Where {
  kVertex,   ///< the vertex orbit <1,...,n>
  kCorner,   ///< a face corner <1,...,n-1> (the mass contributions, §3.3)
  kElement,  ///< the element <0,...,n-1>
};

enum class Kind { kReal, kVec3, kBool, kInt };

/// What a rewrite does with the values of two orbits it merges. For bool,
/// `kSum` is the logical or.
enum class Merge { kKeep, kSum, kMean };

struct Declaration {
  std::string_view name;
  Kind kind;
  Where where;
  Merge merge;
  double fill;  ///< every component of a new orbit's value (bool: true when non-zero)
  std::string_view role;
};

inline constexpr std::string_view kPosition = "position";
inline constexpr std::string_view kVelocity = "velocity";
inline constexpr std::string_view kCornerMass = "corner_mass";
inline constexpr std::string_view kVertexMass = "vertex_mass";
inline constexpr std::string_view kPinned = "pinned";
inline constexpr std::string_view kVertexForce = "vertex_force";
inline constexpr std::string_view kPointIndex = "point_index";
inline constexpr std::string_view kElementIndex = "element_index";

inline constexpr Declaration kDeclarations[] = {
    {kPosition, Kind::kVec3, Where::kVertex, Merge::kMean, 0.0, "read from the mesh"},
    {kVelocity, Kind::kVec3, Where::kVertex, Merge::kMean, 0.0, "integrated by the simulator"},
    {kCornerMass, Kind::kReal, Where::kCorner, Merge::kKeep, 0.0,
     "set from the scene's [mass] by area or volume"},
    {kVertexMass, Kind::kReal, Where::kVertex, Merge::kSum, 0.0,
     "the sum of the vertex's corner masses, recomputed by the simulator after every rewrite"},
    {kPinned, Kind::kBool, Where::kVertex, Merge::kSum, 0.0,
     "set from the scene's pins and handles"},
    {kVertexForce, Kind::kVec3, Where::kVertex, Merge::kKeep, 0.0,
     "the total internal force on the vertex at the start of the step; filled by the simulator "
     "only when a pack reads it"},
    {kPointIndex, Kind::kInt, Where::kVertex, Merge::kKeep, -1.0,
     "the vertex's index in the mesh file, -1 for vertices created later"},
    {kElementIndex, Kind::kInt, Where::kElement, Merge::kKeep, -1.0,
     "the element's index in the mesh file, -1 for elements created later"},
};

/// The declaration of `name`, or nullptr when it is not a state embedding.
constexpr const Declaration* find(std::string_view name) {
  for (const Declaration& d : kDeclarations) {
    if (d.name == name) return &d;
  }
  return nullptr;
}

}  // namespace rift::state
