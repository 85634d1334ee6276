// Integrators against the harmonic oscillator x'' = -w^2 x, whose solution
// x(t) = cos(w t) is known in closed form.
#include "rift/sim/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rift {
namespace {

struct Oscillator {
  Real omega = 2.0;
  AccelerationFn accel() const {
    return [w2 = omega * omega](const std::vector<Vec3>& x, const std::vector<Vec3>&,
                                std::vector<Vec3>& a) {
      for (std::size_t i = 0; i < x.size(); ++i)
        a[i] = -w2 * x[i];
    };
  }
  Real energy(const Vec3& x, const Vec3& v) const {
    return 0.5 * v.squaredNorm() + 0.5 * omega * omega * x.squaredNorm();
  }
};

// Error |x(T) - cos(w T)| after integrating to T with step dt.
Real error_at(IntegratorKind kind, Real dt, Real T) {
  Oscillator osc;
  Integrator integrator(kind);
  std::vector<Vec3> x{Vec3(1, 0, 0)}, v{Vec3::Zero()};
  const int steps = static_cast<int>(std::lround(T / dt));
  for (int s = 0; s < steps; ++s)
    integrator.step(osc.accel(), x, v, dt);
  return std::abs(x[0].x() - std::cos(osc.omega * steps * dt));
}

TEST(Integrators, Rk4PeriodMatchesTheAnalyticPeriod) {
  // Period from the times of upward zero crossings, linearly interpolated.
  Oscillator osc;
  const Real dt = 1e-3;
  Integrator rk4(IntegratorKind::kRK4);
  std::vector<Vec3> x{Vec3(1, 0, 0)}, v{Vec3::Zero()};
  std::vector<Real> crossings;
  Real t = 0;
  while (crossings.size() < 4) {
    const Real before = x[0].x();
    rk4.step(osc.accel(), x, v, dt);
    t += dt;
    const Real after = x[0].x();
    if (before < 0 && after >= 0) crossings.push_back(t - dt * after / (after - before));
  }
  const Real measured = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const Real analytic = 2 * std::numbers::pi / osc.omega;
  // Linear interpolation of the crossing limits the accuracy to O(dt^2 w^2);
  // a cubic Hermite interpolation would be sharper, but 1e-6 is the target.
  EXPECT_LE(std::abs(measured - analytic) / analytic, 1e-6);
}

TEST(Integrators, ConvergenceOrders) {
  const Real T = 1.0;
  auto order = [&](IntegratorKind kind, Real dt) {
    return std::log2(error_at(kind, dt, T) / error_at(kind, dt / 2, T));
  };
  EXPECT_NEAR(order(IntegratorKind::kRK4, 0.02), 4.0, 0.15);
  EXPECT_NEAR(order(IntegratorKind::kExplicitEuler, 0.001), 1.0, 0.1);
  EXPECT_NEAR(order(IntegratorKind::kSymplecticEuler, 0.001), 1.0, 0.1);
}

TEST(Integrators, SymplecticEulerKeepsEnergyBounded) {
  Oscillator osc;
  osc.omega = 1.0;
  const Real dt = 1e-3;
  Integrator integrator(IntegratorKind::kSymplecticEuler);
  std::vector<Vec3> x{Vec3(1, 0, 0)}, v{Vec3::Zero()};
  const Real e0 = osc.energy(x[0], v[0]);
  Real worst = 0;
  for (int s = 0; s < 10000; ++s) {
    integrator.step(osc.accel(), x, v, dt);
    worst = std::max(worst, std::abs(osc.energy(x[0], v[0]) - e0) / e0);
  }
  EXPECT_LT(worst, 1e-3);
  // Explicit Euler on the same problem gains energy steadily.
  Integrator euler(IntegratorKind::kExplicitEuler);
  x = {Vec3(1, 0, 0)};
  v = {Vec3::Zero()};
  for (int s = 0; s < 10000; ++s)
    euler.step(osc.accel(), x, v, dt);
  EXPECT_GT(osc.energy(x[0], v[0]), e0 * 1.005);
}

// The step from forces (what Simulation runs): a spring of stiffness k
// holding a mass m under gravity g along x, beside a pinned vertex (inverse
// mass 0). x'' = -(k/m) x + g, so x(t) = g/w² + (x0 - g/w²) cos(w t), w² = k/m.
struct HangingSpring {
  Real k = 8, m = 2, g = -3;
  std::vector<Real> inverse_mass{1 / m, 0};
  ForceFn forces() const {
    return [k = k](const std::vector<Vec3>& x, const std::vector<Vec3>&, std::vector<Vec3>& f) {
      for (std::size_t i = 0; i < x.size(); ++i)
        f[i] += -k * x[i];  // the pinned vertex feels a force too, and must not move
    };
  }
  ForceToAcceleration to_a() const { return {inverse_mass.data(), Vec3(g, 0, 0)}; }
  // The forces at x, into a zeroed array (the loop's start forces).
  std::vector<Vec3> start_forces(const std::vector<Vec3>& x) const {
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    forces()(x, x, f);
    return f;
  }
  // a(x, v) as Simulation forms it: w f + g where w > 0, else 0.
  std::vector<Vec3> accelerations(const std::vector<Vec3>& x) const {
    std::vector<Vec3> f(x.size(), Vec3::Zero()), a(x.size());
    forces()(x, x, f);
    for (std::size_t i = 0; i < x.size(); ++i)
      a[i] = inverse_mass[i] > 0 ? Vec3(f[i] * inverse_mass[i] + to_a().gravity) : Vec3::Zero();
    return a;
  }
  Real exact(Real x0, Real t) const {
    const Real w2 = k / m, rest = g / w2;
    return rest + (x0 - rest) * std::cos(std::sqrt(w2) * t);
  }
};

Real force_step_error(Real dt, Real duration) {
  const HangingSpring spring;
  Integrator rk4(IntegratorKind::kRK4);
  std::vector<Vec3> x{Vec3(1, 0, 0), Vec3(0.5, 0.25, 0)}, v(2, Vec3::Zero()), f;
  const int steps = static_cast<int>(std::lround(duration / dt));
  for (int s = 0; s < steps; ++s)
    rk4.step(spring.forces(), spring.to_a(), x, v, dt, spring.start_forces(x), f);
  // The pinned vertex never moves, whatever its force.
  EXPECT_EQ(x[1], Vec3(0.5, 0.25, 0));
  EXPECT_EQ(v[1], Vec3::Zero());
  return std::abs(x[0].x() - spring.exact(1, steps * dt));
}

TEST(Integrators, Rk4FromForcesConvergesAtFourthOrder) {
  const Real duration = 1.0;
  EXPECT_LT(force_step_error(0.01, duration), 1e-7);
  EXPECT_NEAR(std::log2(force_step_error(0.02, duration) / force_step_error(0.01, duration)), 4.0,
              0.15);
}

TEST(Integrators, Rk4FromForcesGivesTheBitsOfRk4FromAccelerations) {
  // The force path forms accelerations inside its sweeps; the same
  // arithmetic as an acceleration function that forms them itself.
  const HangingSpring spring;
  const std::vector<Vec3> x0{Vec3(1, 0.1, -0.2), Vec3(0.5, 0.25, 0)};
  const std::vector<Vec3> v0{Vec3(0.3, -0.7, 0.1), Vec3::Zero()};
  std::vector<Vec3> xf = x0, vf = v0, xa = x0, va = v0, f;
  Integrator from_forces(IntegratorKind::kRK4), from_accelerations(IntegratorKind::kRK4);
  const AccelerationFn accel = [&](const std::vector<Vec3>& x, const std::vector<Vec3>&,
                                   std::vector<Vec3>& a) { a = spring.accelerations(x); };
  for (int s = 0; s < 100; ++s) {
    from_forces.step(spring.forces(), spring.to_a(), xf, vf, 0.03, spring.start_forces(xf), f);
    from_accelerations.step(accel, xa, va, 0.03);
  }
  EXPECT_NE(xf[0], x0[0]);
  for (std::size_t i = 0; i < x0.size(); ++i) {
    EXPECT_EQ(xf[i], xa[i]) << i;
    EXPECT_EQ(vf[i], va[i]) << i;
  }
}

TEST(Integrators, Rk4FromForcesSumsTheStagesInTheClassicalOrder) {
  // The textbook step written out, stage by stage, with the summation order
  // the integrator promises: x += ((dt/6 v1 + dt/3 v2) + dt/3 v3) + dt/6 v4,
  // v likewise with the accelerations. Its sweeps defer and fuse the sums;
  // the bits must not move.
  const HangingSpring spring;
  const Real dt = 0.03, h = dt / 2, w1 = dt / 6, w2 = dt / 3;
  std::vector<Vec3> x{Vec3(1, 0.1, -0.2), Vec3(0.5, 0.25, 0)};
  std::vector<Vec3> v{Vec3(0.3, -0.7, 0.1), Vec3::Zero()};
  std::vector<Vec3> xr = x, vr = v;
  Integrator rk4(IntegratorKind::kRK4);
  std::vector<Vec3> f;
  for (int s = 0; s < 50; ++s) {
    rk4.step(spring.forces(), spring.to_a(), x, v, dt, spring.start_forces(x), f);
    for (const Vec3& fi : f)
      EXPECT_EQ(fi, Vec3::Zero());  // handed back zeroed for the next force pass
    const std::size_t n = xr.size();
    std::vector<Vec3> x2(n), v2(n), x3(n), v3(n), x4(n), v4(n);
    const std::vector<Vec3> a1 = spring.accelerations(xr);
    for (std::size_t i = 0; i < n; ++i)
      x2[i] = xr[i] + h * vr[i], v2[i] = vr[i] + h * a1[i];
    const std::vector<Vec3> a2 = spring.accelerations(x2);
    for (std::size_t i = 0; i < n; ++i)
      x3[i] = xr[i] + h * v2[i], v3[i] = vr[i] + h * a2[i];
    const std::vector<Vec3> a3 = spring.accelerations(x3);
    for (std::size_t i = 0; i < n; ++i)
      x4[i] = xr[i] + dt * v3[i], v4[i] = vr[i] + dt * a3[i];
    const std::vector<Vec3> a4 = spring.accelerations(x4);
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 sx = w1 * vr[i], sv = w1 * a1[i];
      sx += w2 * v2[i], sv += w2 * a2[i];
      sx += w2 * v3[i], sv += w2 * a3[i];
      xr[i] += sx + w1 * v4[i];
      vr[i] += sv + w1 * a4[i];
    }
  }
  EXPECT_NE(x[0], Vec3(1, 0.1, -0.2));
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i], xr[i]) << i;
    EXPECT_EQ(v[i], vr[i]) << i;
  }
}

TEST(Integrators, FromForcesAnIntegratorHoldsOnlyTheArraysItsKindNeeds) {
  // RK4: the next stage (x, v) and the two running sums, four vec3 arrays a
  // vertex; the stage forces are the caller's buffer, the start forces and
  // accelerations no array at all. The first-order kinds: nothing. The
  // caller's buffer comes back of the state's length and zero, whatever it
  // held.
  const HangingSpring spring;
  for (IntegratorKind kind :
       {IntegratorKind::kRK4, IntegratorKind::kExplicitEuler, IntegratorKind::kSymplecticEuler}) {
    Integrator integrator(kind);
    std::vector<Vec3> x{Vec3(1, 0, 0), Vec3(0.5, 0.25, 0)}, v(2, Vec3::Zero());
    std::vector<Vec3> f(5, Vec3::Constant(7));
    integrator.step(spring.forces(), spring.to_a(), x, v, 0.01, spring.start_forces(x), f);
    EXPECT_EQ(f, std::vector<Vec3>(2, Vec3::Zero())) << to_string(kind);
    const std::size_t per_vertex = kind == IntegratorKind::kRK4 ? 4 * sizeof(Vec3) : 0;
    EXPECT_EQ(integrator.buffer_bytes(), 2 * per_vertex) << to_string(kind);
  }
}

TEST(Integrators, ParseNames) {
  EXPECT_EQ(parse_integrator("rk4"), IntegratorKind::kRK4);
  EXPECT_EQ(parse_integrator("euler"), IntegratorKind::kExplicitEuler);
  EXPECT_EQ(parse_integrator("symplectic_euler"), IntegratorKind::kSymplecticEuler);
  EXPECT_FALSE(parse_integrator("verlet").has_value());
  EXPECT_EQ(to_string(IntegratorKind::kRK4), "rk4");
}

}  // namespace
}  // namespace rift
