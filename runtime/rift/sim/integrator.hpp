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

/// Adds forces f(x, v) into f, which arrives zeroed and of the arrays' length.
using ForceFn = std::function<void(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                   std::vector<Vec3>& f)>;

/// How a vertex's acceleration follows from its force: a = w f + g where its
/// inverse mass w > 0, else 0 (pinned, held and dead vertices do not move).
struct ForceToAcceleration {
  const Real* inverse_mass;  ///< by vertex slot, as long as the state
  Vec3 gravity;
};

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

  /// The same step from forces: the stages' accelerations are formed inside
  /// the integrator's own sweeps (`to_a`), and the force buffer is zeroed
  /// there too, so a stage costs the force pass and one sweep over the
  /// vertices instead of three (zero, forces to accelerations, update).
  /// The same bits as step(AccelerationFn) given a = w f + g.
  /// `a0` holds a(x, v) (see above).
  void step(const ForceFn& forces, const ForceToAcceleration& to_a, std::vector<Vec3>& x,
            std::vector<Vec3>& v, Real dt, const std::vector<Vec3>& a0);

 private:
  template <class StageFn, class ToA>
  void rk4(const StageFn& stage, const ToA& to_a, std::vector<Vec3>& x, std::vector<Vec3>& v,
           Real dt, const std::vector<Vec3>& a);

  IntegratorKind kind_;
  std::vector<Vec3> a_, x_sum_, v_sum_, stage_f_, xs_, vs_;
};

}  // namespace rift
