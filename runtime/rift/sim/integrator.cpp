#include "rift/sim/integrator.hpp"

namespace rift {

std::optional<IntegratorKind> parse_integrator(std::string_view name) {
  if (name == "euler" || name == "explicit_euler") return IntegratorKind::kExplicitEuler;
  if (name == "symplectic_euler" || name == "symplectic") return IntegratorKind::kSymplecticEuler;
  if (name == "rk4") return IntegratorKind::kRK4;
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
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += dt * v[i];
        v[i] += dt * a[i];
      }
      return;
    case IntegratorKind::kSymplecticEuler:
      for (std::size_t i = 0; i < n; ++i) {
        v[i] += dt * a[i];
        x[i] += dt * v[i];
      }
      return;
    case IntegratorKind::kRK4:
      break;
  }

  // Classical RK4 on y = (x, v), y' = (v, a(x, v)):
  //   k1 = (v, a(x, v))
  //   k2 = (v + dt/2 k1v, a(x + dt/2 k1x, v + dt/2 k1v)), and so on.
  k2x_.resize(n), k2v_.resize(n), k3x_.resize(n), k3v_.resize(n);
  k4x_.resize(n), k4v_.resize(n), xs_.resize(n), vs_.resize(n);
  const Real h = dt / 2;
  for (std::size_t i = 0; i < n; ++i) {
    xs_[i] = x[i] + h * v[i];
    vs_[i] = v[i] + h * a[i];
  }
  k2x_ = vs_;
  accel(xs_, vs_, k2v_);
  for (std::size_t i = 0; i < n; ++i) {
    xs_[i] = x[i] + h * k2x_[i];
    vs_[i] = v[i] + h * k2v_[i];
  }
  k3x_ = vs_;
  accel(xs_, vs_, k3v_);
  for (std::size_t i = 0; i < n; ++i) {
    xs_[i] = x[i] + dt * k3x_[i];
    vs_[i] = v[i] + dt * k3v_[i];
  }
  k4x_ = vs_;
  accel(xs_, vs_, k4v_);
  const Real s = dt / 6;
  for (std::size_t i = 0; i < n; ++i) {
    x[i] += s * (v[i] + 2 * k2x_[i] + 2 * k3x_[i] + k4x_[i]);
    v[i] += s * (a[i] + 2 * k2v_[i] + 2 * k3v_[i] + k4v_[i]);
  }
}

}  // namespace rift
