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

namespace {

// The first-order kinds, which need a(x, v) only: true when `kind` is one.
bool first_order_step(IntegratorKind kind, std::vector<Vec3>& x, std::vector<Vec3>& v, Real dt,
                      const std::vector<Vec3>& a) {
  const std::size_t n = x.size();
  switch (kind) {
    case IntegratorKind::kExplicitEuler:
      parallel_for(n, [&](std::size_t i) {
        x[i] += dt * v[i];
        v[i] += dt * a[i];
      });
      return true;
    case IntegratorKind::kSymplecticEuler:
      parallel_for(n, [&](std::size_t i) {
        v[i] += dt * a[i];
        x[i] += dt * v[i];
      });
      return true;
    case IntegratorKind::kRK4:
      return false;
    case IntegratorKind::kImplicitEuler:
    case IntegratorKind::kBdf2:
      // Needs Jacobians, not accelerations: Simulation runs ImplicitEuler.
      throw std::logic_error("Integrator::step cannot run an implicit integrator");
  }
  return false;
}

}  // namespace

template <class StageFn, class ToA>
void Integrator::rk4(const StageFn& stage, const ToA& to_a, std::vector<Vec3>& x,
                     std::vector<Vec3>& v, Real dt, const std::vector<Vec3>& a) {
  // Classical RK4 on y = (x, v), y' = (v, a(x, v)), accumulated on the fly
  // so that a step touches six arrays and copies none:
  //   k1 = (v, a)             at (x, v)
  //   k2 = (v2, a2)           at (x + h k1x, v + h k1v), h = dt/2, v2 = v + h a
  //   k3 = (v3, a3)           at (x + h k2x, v + h k2v)
  //   k4 = (v4, a4)           at (x + dt k3x, v + dt k3v)
  //   y += dt/6 (k1 + 2 k2 + 2 k3 + k4)
  // A stage's forces arrive in f; each sweep turns them into accelerations
  // as it reads them (to_a) and zeroes f for the next stage, so that between
  // two force passes there is one pass over the vertices (at 10⁶ vertices
  // a pass is bandwidth: the separate zeroing and conversion passes cost as
  // much as the update). Every sweep is per vertex, hence parallel with the
  // same result on any number of threads.
  const std::size_t n = x.size();
  xs_.resize(n), vs_.resize(n), x_sum_.resize(n), v_sum_.resize(n), stage_f_.resize(n);
  std::vector<Vec3>& f = stage_f_;
  const Real h = dt / 2;
  const Real w1 = dt / 6, w2 = dt / 3;
  parallel_for(n, [&](std::size_t i) {
    x_sum_[i] = w1 * v[i];  // running dt/6 (k1x + 2 k2x + 2 k3x + k4x)
    v_sum_[i] = w1 * a[i];
    xs_[i] = x[i] + h * v[i];
    vs_[i] = v[i] + h * a[i];
    f[i].setZero();
  });
  stage(xs_, vs_, f);  // a2 at stage 2; vs_ holds v2
  parallel_for(n, [&](std::size_t i) {
    const Vec3 ai = to_a(i, f[i]);
    f[i].setZero();
    x_sum_[i] += w2 * vs_[i];
    v_sum_[i] += w2 * ai;
    xs_[i] = x[i] + h * vs_[i];
    vs_[i] = v[i] + h * ai;
  });
  stage(xs_, vs_, f);  // a3; vs_ holds v3
  parallel_for(n, [&](std::size_t i) {
    const Vec3 ai = to_a(i, f[i]);
    f[i].setZero();
    x_sum_[i] += w2 * vs_[i];
    v_sum_[i] += w2 * ai;
    xs_[i] = x[i] + dt * vs_[i];
    vs_[i] = v[i] + dt * ai;
  });
  stage(xs_, vs_, f);  // a4; vs_ holds v4
  parallel_for(n, [&](std::size_t i) {
    const Vec3 ai = to_a(i, f[i]);
    x[i] += x_sum_[i] + w1 * vs_[i];
    v[i] += v_sum_[i] + w1 * ai;
  });
}

void Integrator::step(const AccelerationFn& accel, std::vector<Vec3>& x, std::vector<Vec3>& v,
                      Real dt, const std::vector<Vec3>* a0) {
  a_.resize(x.size());
  const std::vector<Vec3>& a = a0 ? *a0 : a_;
  if (!a0) accel(x, v, a_);
  if (first_order_step(kind_, x, v, dt, a)) return;
  // The stage function writes accelerations: they are used as they are.
  rk4(
      accel, [](std::size_t, const Vec3& ai) { return ai; }, x, v, dt, a);
}

void Integrator::step(const ForceFn& forces, const ForceToAcceleration& to_a, std::vector<Vec3>& x,
                      std::vector<Vec3>& v, Real dt, const std::vector<Vec3>& a0) {
  if (first_order_step(kind_, x, v, dt, a0)) return;
  const Real* w = to_a.inverse_mass;
  const Vec3 g = to_a.gravity;
  rk4(
      forces,
      [w, g](std::size_t i, const Vec3& f) { return w[i] > 0 ? Vec3(f * w[i] + g) : Vec3::Zero(); },
      x, v, dt, a0);
}

}  // namespace rift
