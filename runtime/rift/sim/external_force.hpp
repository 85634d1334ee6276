// Forces from outside the body (loads, acceleration fields, air drag): added
// to the per-vertex forces at every stage of every integrator, after the
// internal forces were stored for the criteria (so criteria see internal
// forces only). The implicit integrator adds them to its right-hand side and
// neglects their Jacobians (they are constant or, for drag, dissipative).
#pragma once

#include <string>

#include "rift/sim/force_model.hpp"

namespace rift {

struct ExternalInput {
  Real time;          ///< simulation time of the stage (start of the step)
  const Vec3* x;      ///< positions by vertex slot
  const Vec3* v;      ///< velocities by vertex slot
  const Real* mass;   ///< vertex masses by slot (0 for free slots)
  std::size_t slots;  ///< number of slots
};

class ExternalForce {
 public:
  virtual ~ExternalForce() = default;
  virtual const std::string& name() const = 0;
  /// Adds this force to f (indexed by vertex slot).
  virtual void add_forces(const GMap& map, const ExternalInput& in, Vec3* f) = 0;
};

}  // namespace rift
