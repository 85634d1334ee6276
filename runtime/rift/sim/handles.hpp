// Handles: vertices whose motion is prescribed (pins, grippers, clamps that
// move). A vertex held by an active handle has inverse mass 0 in the loop;
// the handles give its target position and velocity at any time, and the
// loop sets them after each step (explicit integrators) or treats them as
// Dirichlet degrees of freedom (implicit). See docs/scenes.md, [[handle]].
//
// Membership lives in an embedding on the vertex orbit ("handle", -1 for
// none) with the rest position of each held vertex ("handle_rest"), so that
// a vertex split by a tear keeps both halves on the handle.
//
// A fixed handle (a pin: no keyframe, no velocity) holds its vertices where
// they are, so its target is the vertex's own position and it needs no rest
// position: "handle_rest" is declared only once a handle moves or a vertex is
// held away from where it is (23 MB that a pinned 10^6-vertex cloth no
// longer fills at set-up and keeps, issue 12).
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "rift/gmap/gmap.hpp"

namespace rift {

/// A rigid motion over time: translation and rotation (a rotation vector in
/// degrees, about `pivot`) keyframed and linearly interpolated, plus a
/// constant velocity. No keyframe and zero velocity: a fixed handle.
struct HandleMotion {
  struct Keyframe {
    Real time = 0;
    Vec3 translate = Vec3::Zero();
    Vec3 rotate_degrees = Vec3::Zero();  ///< axis times angle
  };
  std::string name = "handle";
  Vec3 velocity = Vec3::Zero();
  std::vector<Keyframe> keyframes;                       ///< sorted by time; clamped outside
  Vec3 pivot = Vec3::Zero();                             ///< rotation centre, at rest
  Real release = std::numeric_limits<Real>::infinity();  ///< lets go at this time

  /// Where a point at rest position `rest` is at time t.
  Vec3 place(const Vec3& rest, Real t) const;
  /// True when the motion holds every point where it is at all times (no
  /// keyframe, no velocity), whatever its pivot and release.
  bool fixed() const { return keyframes.empty() && velocity == Vec3::Zero(); }
};

class Handles {
 public:
  /// Declares the membership embedding on `map`'s vertex orbit (the rest
  /// positions only when needed, see the file comment).
  explicit Handles(GMap& map);

  /// Adds a handle; returns its index.
  int add(HandleMotion motion);
  /// Puts the vertex of `d` on handle `index`, at its current position.
  /// Returns false when the vertex is already on another handle.
  bool hold(Dart d, int index, const Vec3& rest);
  /// The handle of a vertex, or -1.
  int handle_of(Dart d) const { return handle_[d]; }

  std::size_t count() const { return motions_.size(); }
  const HandleMotion& motion(int index) const { return motions_[index]; }

  /// True when slot s is held at time t (its handle is not yet released).
  bool holds(Slot s, Real t) const {
    const std::int64_t h = handle_.values()[s];
    return h >= 0 && t < motions_[static_cast<std::size_t>(h)].release;
  }
  /// True when some handle lets go in (t0, t1].
  bool releases_between(Real t0, Real t1) const;

  /// Whether the rest positions are kept (some handle moves, or a vertex was
  /// held away from its position).
  bool keeps_rest() const { return static_cast<bool>(rest_); }

  /// Target position of a held slot at time t, and the velocity that
  /// carries it to its target at t + dt. Without rest positions every
  /// handle is fixed and the target is the slot's position.
  Vec3 target(Slot s, Real t) const;
  Vec3 target_velocity(Slot s, Real t, Real dt) const;

  /// The slots alive in `alive` whose vertex is on a handle (released or
  /// not), ascending: what the per-step passes below visit, so that a scene
  /// pinning two corners of a 10⁶-vertex cloth pays for two vertices, not
  /// for a sweep of every slot. Kept between calls; rebuilt (one sweep of
  /// every slot) after hold() and topology_changed(), followed after
  /// topology_changed(map, region).
  const std::vector<Slot>& held_slots(const OrbitAttachment& alive) const;
  /// After values written in place: slots may have been given a handle.
  void topology_changed() { held_stale_ = true; }
  /// After rewrites whose touched vertices are the vertex orbits of the live
  /// darts of `region` (Simulation::on_topology_changed's region): a slot
  /// that appeared or took a handle is one of theirs, and a slot freed is
  /// dropped, so the held slots follow without a sweep of every slot (a tear
  /// costs what it touches, issue 12).
  void topology_changed(const GMap& map, std::span<const Dart> region);
  /// How many times held_slots() swept every slot (tests).
  std::uint64_t held_sweeps() const { return held_sweeps_; }

  /// Sets every held slot alive in `alive` to its target at t (position)
  /// and the velocity toward its target at t + dt.
  void impose(const OrbitAttachment& alive, Real t, Real dt, std::vector<Vec3>& x,
              std::vector<Vec3>& v) const;

  /// The force each handle exerts on the body: for every held vertex, what
  /// cancels the other forces on it, -(f + m g) (its acceleration is
  /// neglected: handles move at piecewise constant velocity).
  void reactions(const OrbitAttachment& alive, Real t, const std::vector<Vec3>& forces,
                 const std::vector<Real>& mass, const Vec3& gravity,
                 std::vector<Vec3>& per_handle) const;

 private:
  /// Declares "handle_rest", each slot's rest its current position.
  void keep_rest();

  GMap& map_;
  Embedding<std::int64_t> handle_;
  Embedding<Vec3> position_;
  Embedding<Vec3> rest_;  ///< unbound until keep_rest()
  std::vector<HandleMotion> motions_;
  mutable std::vector<Slot> held_;  // held_slots(), valid unless held_stale_
  std::vector<Slot> merged_;        // topology_changed's scratch
  mutable bool held_stale_ = true;
  mutable std::uint64_t held_sweeps_ = 0;
};

}  // namespace rift
