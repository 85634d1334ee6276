// Rigid obstacles (ground plane, spheres, axis-aligned boxes, capsules),
// fixed or moving at a constant velocity, and the contact of the body's
// vertices with them.
//
// Contact is a projection applied after each step (not a penalty force):
// a vertex found inside an obstacle is moved to its surface, its velocity
// relative to the obstacle loses its inward normal part, and Coulomb friction
// takes up to `friction` times that normal change off the tangential part.
// It adds no stiffness, so it is stable at any dt the body itself allows, and
// it works the same after an explicit or an implicit step. Only vertices
// collide (an obstacle edge can pass between the vertices of a coarse mesh);
// the body does not collide with itself (no self-collision).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rift/gmap/gmap.hpp"

namespace rift {

struct Obstacle {
  enum class Shape { kPlane, kSphere, kBox, kCapsule };
  Shape shape = Shape::kPlane;
  /// plane: a point and the normal (toward the free side); sphere: the
  /// centre in `a`; box: corners `a` (min) and `b` (max); capsule: the ends
  /// of its axis.
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3(0, 0, 1);
  Real radius = 0;
  Vec3 velocity = Vec3::Zero();  ///< moves rigidly at this velocity
  Real friction = 0;             ///< Coulomb coefficient
  Real start = 0;                ///< s: it moves from this time (still before)

  /// The displacement of the obstacle at time t.
  Vec3 offset(Real t) const { return t > start ? Vec3(velocity * (t - start)) : Vec3::Zero(); }
  Vec3 velocity_at(Real t) const { return t > start ? velocity : Vec3::Zero(); }
  /// Signed distance from p to the surface at time t (negative inside) and
  /// the outward normal at the closest surface point.
  Real distance(const Vec3& p, Real t, Vec3& normal) const;
};

const char* to_string(Obstacle::Shape shape);

/// Contact of every free vertex with every obstacle, by projection.
class Contact {
 public:
  explicit Contact(std::vector<Obstacle> obstacles) : obstacles_(std::move(obstacles)) {}
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }

  /// Projects the slots with a positive inverse mass out of every obstacle
  /// at time t; returns how many were in contact.
  std::size_t project(const OrbitAttachment& alive, Real t, const std::vector<Real>& inverse_mass,
                      std::vector<Vec3>& x, std::vector<Vec3>& v) const;

 private:
  std::vector<Obstacle> obstacles_;
};

}  // namespace rift

namespace rift {

/// Triangles of an obstacle's surface at time t, for pictures and VTU files;
/// a plane becomes a square around the box [lo, hi] of the body (twice its
/// size). Appends to `points` and `triangles` (indices into `points`).
void tessellate(const Obstacle& obstacle, Real t, const Vec3& lo, const Vec3& hi,
                std::vector<Vec3>& points, std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace rift
