#include "rift/sim/integrator.hpp"

#include <stdexcept>

#include "rift/core/parallel.hpp"

namespace rift {

std::optional<IntegratorKind> parse_integrator(std::string_view name) {
  if (name == "euler" || name == "explicit_euler") return IntegratorKind::kExplicitEuler;
  if (name == "symplectic_euler" || name == "symplectic") return IntegratorKind::kSymplecticEuler;
  if (name == "rk4") return IntegratorKind::kRK4;
  if (name == "implicit_euler") return IntegratorKind::kImplicitEuler;
  if (name == "bdf2") return IntegratorKind::kBdf2;
  return std::nullopt;
}

std::string_view to_string(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::kExplicitEuler:
      return "euler";
    case IntegratorKind::kSymplecticEuler:
      return "symplectic_euler";
    case IntegratorKind::kRK4:
      return "rk4";
    case IntegratorKind::kImplicitEuler:
      return "implicit_euler";
    case IntegratorKind::kBdf2:
      return "bdf2";
  }
  return "?";
}

void Integrator::step(const AccelerationFn& accel, std::vector<Vec3>& x, std::vector<Vec3>& v,
                      Real dt, const std::vector<Vec3>* a0) {
  const std::size_t n = x.size();
  a_.resize(n);
  const std::vector<Vec3>& a = a0 ? *a0 : a_;
  if (!a0) accel(x, v, a_);

  switch (kind_) {
    case IntegratorKind::kExplicitEuler:
      parallel_for(n, [&](std::size_t i) {
        x[i] += dt * v[i];
        v[i] += dt * a[i];
      });
      return;
    case IntegratorKind::kSymplecticEuler:
      parallel_for(n, [&](std::size_t i) {
        v[i] += dt * a[i];
        x[i] += dt * v[i];
      });
      return;
    case IntegratorKind::kRK4:
      break;
    case IntegratorKind::kImplicitEuler:
    case IntegratorKind::kBdf2:
      // Needs Jacobians, not accelerations: Simulation runs ImplicitEuler.
      throw std::logic_error("Integrator::step cannot run an implicit integrator");
  }

  // Classical RK4 on y = (x, v), y' = (v, a(x, v)), accumulated on the fly
  // so that a step touches five arrays and copies none:
  //   k1 = (v, a)             at (x, v)
  //   k2 = (v2, a2)           at (x + h k1x, v + h k1v), h = dt/2, v2 = v + h a
  //   k3 = (v3, a3)           at (x + h k2x, v + h k2v)
  //   k4 = (v4, a4)           at (x + dt k3x, v + dt k3v)
  //   y += dt/6 (k1 + 2 k2 + 2 k3 + k4)
  // Every sweep is per vertex, hence parallel with the same result on any
  // number of threads.
  xs_.resize(n), vs_.resize(n), k2x_.resize(n), k2v_.resize(n), k4v_.resize(n);
  std::vector<Vec3>& x_sum = k2x_;  // running dt/6 (k1x + 2 k2x + 2 k3x + k4x)
  std::vector<Vec3>& v_sum = k2v_;
  std::vector<Vec3>& stage_a = k4v_;
  const Real h = dt / 2;
  const Real w1 = dt / 6, w2 = dt / 3;
  parallel_for(n, [&](std::size_t i) {
    x_sum[i] = w1 * v[i];
    v_sum[i] = w1 * a[i];
    xs_[i] = x[i] + h * v[i];
    vs_[i] = v[i] + h * a[i];
  });
  accel(xs_, vs_, stage_a);  // a2 at stage 2; vs_ holds v2
  parallel_for(n, [&](std::size_t i) {
    x_sum[i] += w2 * vs_[i];
    v_sum[i] += w2 * stage_a[i];
    xs_[i] = x[i] + h * vs_[i];
    vs_[i] = v[i] + h * stage_a[i];
  });
  accel(xs_, vs_, stage_a);  // a3; vs_ holds v3
  parallel_for(n, [&](std::size_t i) {
    x_sum[i] += w2 * vs_[i];
    v_sum[i] += w2 * stage_a[i];
    xs_[i] = x[i] + dt * vs_[i];
    vs_[i] = v[i] + dt * stage_a[i];
  });
  accel(xs_, vs_, stage_a);  // a4; vs_ holds v4
  parallel_for(n, [&](std::size_t i) {
    x[i] += x_sum[i] + w1 * vs_[i];
    v[i] += v_sum[i] + w1 * stage_a[i];
  });
}

}  // namespace rift
