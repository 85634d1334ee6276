// Explosions caught at the first bad step. An explicit integrator past its
// stability limit multiplies the energy by a large factor every step (a beam
// at 100 times its stable dt reaches 1e34 J in five steps), so the check only
// needs a bound that no legitimate motion of the scene reaches, derived from
// the scene's own energy and length scales (docs/simulation.md, "Divergence"):
//
//   energy   KE(t) > S * E(t), where E(t) = KE(0) + U_elastic(0)
//                                        + M |g| (L + v0 t + |g| t^2 / 2)
//                                        + W_constrained(t) + M v_c^2 / 2
//            (energy of the initial state, plus the work gravity can do on a
//            body that falls freely over the time elapsed, plus the work done
//            so far by prescribed vertices moving against internal forces);
//   speed    |v_i| dt > L + (v0 + |g| t + v_c) dt: a vertex travels farther
//            than the whole body in one step;
//   finite   every position and velocity is finite.
//
// M is the free mass, L the diagonal of the initial bounding box, v0 the
// largest initial speed, v_c the largest speed of a prescribed vertex so far
// and S the safety factor (SimulationSettings::divergence_factor, 100 by
// default; 0 turns the energy and speed checks off, the finite check stays).
#pragma once

#include <cstddef>
#include <vector>

#include "rift/core/types.hpp"

namespace rift {

class Simulation;

class DivergenceMonitor {
 public:
  /// Records the scales from the state about to be stepped first.
  void start(const Simulation& sim);
  bool started() const { return started_; }

  /// After a step: throws SimulationError naming the step, time, vertex,
  /// element and the suggested fix when the state diverged.
  void check(const Simulation& sim);

  /// The current energy bound S * E(t) in joules (0 when it is off).
  Real energy_bound(const Simulation& sim) const;
  Real initial_energy() const { return initial_energy_; }
  Real length_scale() const { return length_; }

 private:
  /// One block's share of check(): kept here so that a warm check
  /// allocates nothing.
  struct Partial {
    Real kinetic = 0, top_energy = -1, top_speed2 = 0, work = 0, constrained_speed = 0;
    Slot most_energetic = kNoSlot, fastest = kNoSlot, bad = kNoSlot;
  };

  bool started_ = false;
  Real free_mass_ = 0, length_ = 0, initial_speed_ = 0, initial_energy_ = 0;
  Real constrained_work_ = 0, constrained_speed_ = 0;
  std::vector<Partial> partials_;
};

}  // namespace rift
