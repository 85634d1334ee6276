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

// The first-order kinds, which need a(x, v) only (`a(i)`): true when `kind`
// is one.
template <class A>
bool first_order_step(IntegratorKind kind, std::vector<Vec3>& x, std::vector<Vec3>& v, Real dt,
                      const A& a) {
  const std::size_t n = x.size();
  Vec3* const xp = x.data();
  Vec3* const vp = v.data();
  switch (kind) {
    case IntegratorKind::kExplicitEuler:
      parallel_sweep(n, [=](std::size_t i) {
        xp[i] += dt * vp[i];
        vp[i] += dt * a(i);
      });
      return true;
    case IntegratorKind::kSymplecticEuler:
      parallel_sweep(n, [=](std::size_t i) {
        vp[i] += dt * a(i);
        xp[i] += dt * vp[i];
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

template <class StageFn, class A1, class ToA>
void Integrator::rk4(const StageFn& stage, const A1& a1, const ToA& to_a, std::vector<Vec3>& x,
                     std::vector<Vec3>& v, Real dt, std::vector<Vec3>& f) {
  // Classical RK4 on y = (x, v), y' = (v, a(x, v)), accumulated on the fly:
  //   k1 = (v, a1)            at (x, v), a1 = a1(i)
  //   k2 = (v2, a2)           at (x + h k1x, v + h k1v), h = dt/2, v2 = v + h a1
  //   k3 = (v3, a3)           at (x + h k2x, v + h k2v)
  //   k4 = (v4, a4)           at (x + dt k3x, v + dt k3v)
  //   y += dt/6 (k1 + 2 k2 + 2 k3 + k4)
  // summed in that order, ((k1/6 + k2/3) + k3/3) + k4/6, the same bits
  // whatever the sweeps. A stage's forces arrive in f; each sweep turns them
  // into accelerations as it reads them (to_a) and zeroes f for the next
  // pass, so that between two force passes there is one pass over the
  // vertices. At 10⁶ vertices a pass is bandwidth, so the sweeps touch as
  // few arrays as they can: the first writes only the stage (xs, vs), and
  // the running sums start at the second, which forms k1's terms again from
  // what it reads anyway (v, and a1 from the start forces and the inverse
  // mass) rather than a first sweep writing them and the second reading them
  // back (48 bytes a vertex each way). Every sweep is per vertex, hence
  // parallel with the same result on any number of threads.
  // The sweeps take the arrays as raw pointers, by copy (parallel_sweep).
  const std::size_t n = x.size();
  xs_.resize(n), vs_.resize(n), x_sum_.resize(n), v_sum_.resize(n), f.resize(n);
  Vec3* const xp = x.data();
  Vec3* const vp = v.data();
  Vec3* const xs = xs_.data();
  Vec3* const vs = vs_.data();
  Vec3* const x_sum = x_sum_.data();
  Vec3* const v_sum = v_sum_.data();
  // The stage may resize f (an AccelerationFn assigns its output): its
  // address is taken again after each stage.
  Vec3* fp = f.data();
  const Real h = dt / 2;
  const Real w1 = dt / 6, w2 = dt / 3;
  parallel_sweep(n, [=](std::size_t i) {
    xs[i] = xp[i] + h * vp[i];
    vs[i] = vp[i] + h * a1(i);
    fp[i].setZero();
  });
  stage(xs_, vs_, f);  // a2 at stage 2; vs_ holds v2
  fp = f.data();
  parallel_sweep(n, [=](std::size_t i) {
    const Vec3 ai = to_a(i, fp[i]);
    fp[i].setZero();
    x_sum[i] = w1 * vp[i] + w2 * vs[i];  // running dt/6 (k1x + 2 k2x + 2 k3x + k4x)
    v_sum[i] = w1 * a1(i) + w2 * ai;
    xs[i] = xp[i] + h * vs[i];
    vs[i] = vp[i] + h * ai;
  });
  stage(xs_, vs_, f);  // a3; vs_ holds v3
  fp = f.data();
  parallel_sweep(n, [=](std::size_t i) {
    const Vec3 ai = to_a(i, fp[i]);
    fp[i].setZero();
    x_sum[i] += w2 * vs[i];
    v_sum[i] += w2 * ai;
    xs[i] = xp[i] + dt * vs[i];
    vs[i] = vp[i] + dt * ai;
  });
  stage(xs_, vs_, f);  // a4; vs_ holds v4
  fp = f.data();
  parallel_sweep(n, [=](std::size_t i) {
    const Vec3 ai = to_a(i, fp[i]);
    fp[i].setZero();
    xp[i] += x_sum[i] + w1 * vs[i];
    vp[i] += v_sum[i] + w1 * ai;
  });
}

void Integrator::step(const AccelerationFn& accel, std::vector<Vec3>& x, std::vector<Vec3>& v,
                      Real dt, const std::vector<Vec3>* a0) {
  if (!a0) a_.resize(x.size());
  const std::vector<Vec3>& a = a0 ? *a0 : a_;
  if (!a0) accel(x, v, a_);
  const auto a1 = [ap = a.data()](std::size_t i) -> const Vec3& { return ap[i]; };
  if (first_order_step(kind_, x, v, dt, a1)) return;
  // The stage function writes accelerations: they are used as they are.
  rk4(
      accel, a1, [](std::size_t, const Vec3& ai) { return ai; }, x, v, dt, stage_a_);
}

void Integrator::step(const ForceFn& forces, const ForceToAcceleration& to_a, std::vector<Vec3>& x,
                      std::vector<Vec3>& v, Real dt, const std::vector<Vec3>& f0,
                      std::vector<Vec3>& f) {
  const Real* w = to_a.inverse_mass;
  const Vec3 g = to_a.gravity;
  // a = w f + g where w > 0, else 0: the expression Simulation formed its
  // accelerations with, so the bits of step(AccelerationFn).
  const auto accel = [w, g](std::size_t i, const Vec3& fi) {
    return w[i] > 0 ? Vec3(fi * w[i] + g) : Vec3::Zero();
  };
  const auto a1 = [accel, f0p = f0.data()](std::size_t i) { return accel(i, f0p[i]); };
  if (first_order_step(kind_, x, v, dt, a1)) {
    f.assign(x.size(), Vec3::Zero());
    return;
  }
  rk4(forces, a1, accel, x, v, dt, f);
}

std::size_t Integrator::buffer_bytes() const {
  std::size_t bytes = 0;
  for (const std::vector<Vec3>* b : {&xs_, &vs_, &x_sum_, &v_sum_, &a_, &stage_a_})
    bytes += b->capacity() * sizeof(Vec3);
  return bytes;
}

}  // namespace rift
