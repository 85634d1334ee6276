// BDF2, the second-order backward differentiation formula, for
// M v' = f(x, v), x' = v with a constant step h (docs/physics.md, "The
// implicit step"):
//
//   x1 = (4 x0 - x_1) / 3 + (2h/3) v1,
//   v1 = (4 v0 - v_1) / 3 + (2h/3) M⁻¹ f(x1, v1),
//
// x_1, v_1 being the state one step back. With x̂ = (4 x0 - x_1)/3,
// v̂ = (4 v0 - v_1)/3 and ĥ = 2h/3 this is backward Euler from (x̂, v̂) with
// the step ĥ, so ImplicitEuler solves it unchanged: the same linearisation
// (once, or Newton), the same PCG and the same Dirichlet constraints.
// The first step, and the first after the vertex slots changed (a tear) or
// after a change of h, is a backward Euler step, which keeps the method
// second order overall (its local error is O(h²), made once).
#pragma once

#include <vector>

#include "rift/sim/implicit_euler.hpp"

namespace rift {

class Bdf2 {
 public:
  /// The next step starts the method again with a backward Euler step.
  void restart() { have_previous_ = false; }

  /// One step of size h, arguments as ImplicitEuler::step: target_v is the
  /// end-of-step velocity of constrained slots in backward Euler's terms
  /// (they end at x0 + h target_v, which BDF2 keeps exact); f0, when
  /// given, holds force(x, v) (used by a backward Euler step only).
  void step(ImplicitEuler& solver, const ImplicitEuler::ForceFn& force,
            const std::vector<Real>& mass, const std::vector<char>& is_free, const Vec3* target_v,
            std::vector<Vec3>& x, std::vector<Vec3>& v, Real h,
            const std::vector<Vec3>* f0 = nullptr);

  /// Whether the last step was a BDF2 step (false: backward Euler).
  bool last_was_bdf2() const { return last_was_bdf2_; }
  /// The step before, under "implicit" (MemoryReport).
  void report_memory(MemoryReport& report) const {
    report.add("implicit", "BDF2's previous state",
               (x_previous_.size() + v_previous_.size() + target_v_.size()) * sizeof(Vec3));
  }

 private:
  bool have_previous_ = false;
  bool last_was_bdf2_ = false;
  Real previous_h_ = 0;
  std::vector<Vec3> x_previous_, v_previous_, target_v_;
};

}  // namespace rift
