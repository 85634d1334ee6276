// Time integrators over dense position/velocity arrays (indexed by vertex slot).
#pragma once

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "rift/core/types.hpp"

namespace rift {

enum class IntegratorKind {
  kExplicitEuler,    ///< x += dt v(t); v += dt a(t). First order; gains energy.
  kSymplecticEuler,  ///< v += dt a(t); x += dt v(t+dt). First order; bounded energy.
  kRK4,              ///< classical Runge-Kutta on (x, v). Fourth order (the paper's choice).
  kImplicitEuler,    ///< backward Euler with Jacobians (ImplicitEuler, not this class).
  kBdf2,             ///< second-order BDF with Jacobians (Bdf2 over ImplicitEuler). Second order.
};

/// The integrators that solve a linear system with the interactions'
/// Jacobians (Simulation runs them with ImplicitEuler, not Integrator).
inline bool is_implicit(IntegratorKind kind) {
  return kind == IntegratorKind::kImplicitEuler || kind == IntegratorKind::kBdf2;
}

/// "euler", "symplectic_euler" (or "symplectic"), "rk4", "implicit_euler", "bdf2".
std::optional<IntegratorKind> parse_integrator(std::string_view name);
std::string_view to_string(IntegratorKind kind);

/// Computes accelerations a(x, v), all arrays of the same length.
using AccelerationFn = std::function<void(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                          std::vector<Vec3>& a)>;

/// Advances (x, v) by dt. Keeps its stage buffers between steps, so a step
/// allocates nothing unless the number of vertices grew.
class Integrator {
 public:
  explicit Integrator(IntegratorKind kind) : kind_(kind) {}
  IntegratorKind kind() const { return kind_; }

  /// When `a0` is given it must hold a(x, v) already (the loop computes it
  /// to evaluate criteria), saving one evaluation.
  void step(const AccelerationFn& accel, std::vector<Vec3>& x, std::vector<Vec3>& v, Real dt,
            const std::vector<Vec3>* a0 = nullptr);

  /// Number of acceleration evaluations one step makes.
  int evaluations_per_step() const { return kind_ == IntegratorKind::kRK4 ? 4 : 1; }

 private:
  IntegratorKind kind_;
  std::vector<Vec3> a_, k2x_, k2v_, k4v_, xs_, vs_;
};

}  // namespace rift
