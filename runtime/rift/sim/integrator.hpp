// Time integrators over dense position/velocity arrays (indexed by vertex slot).
#pragma once

#include <cstddef>
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

  /// The same step from forces, as Simulation runs it. `f0` holds the
  /// forces at (x, v) (the loop computes them to evaluate criteria); each
  /// sweep forms the accelerations a = to_a(f) as it reads the forces, so no
  /// acceleration array exists. `f` is the stages' force buffer (the caller's,
  /// so that the loop and the integrator share one): any content and length
  /// on entry, the arrays' length and all zeros on return (the next force
  /// pass adds into it without a zeroing pass). A stage costs the force pass
  /// and one sweep over the vertices. The same bits as step(AccelerationFn)
  /// given a = w f + g.
  void step(const ForceFn& forces, const ForceToAcceleration& to_a, std::vector<Vec3>& x,
            std::vector<Vec3>& v, Real dt, const std::vector<Vec3>& f0, std::vector<Vec3>& f);

  /// Bytes of the per-vertex buffers this integrator holds (capacities):
  /// none for the first-order kinds stepped from forces, four vec3 arrays
  /// for RK4 stepped from forces (docs/performance.md, "RK4's arrays").
  std::size_t buffer_bytes() const;

 private:
  template <class StageFn, class A1, class ToA>
  void rk4(const StageFn& stage, const A1& a1, const ToA& to_a, std::vector<Vec3>& x,
           std::vector<Vec3>& v, Real dt, std::vector<Vec3>& f);

  IntegratorKind kind_;
  // RK4's stage state: positions and velocities of the next stage (xs_,
  // vs_) and the running sums dt/6 (k1 + 2 k2 + 2 k3) of x' and v'.
  std::vector<Vec3> xs_, vs_, x_sum_, v_sum_;
  // Only step(AccelerationFn): a(x, v) when the caller gives none, and the
  // stages' accelerations.
  std::vector<Vec3> a_, stage_a_;
};

}  // namespace rift
