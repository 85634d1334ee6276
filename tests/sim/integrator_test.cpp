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

TEST(Integrators, ParseNames) {
  EXPECT_EQ(parse_integrator("rk4"), IntegratorKind::kRK4);
  EXPECT_EQ(parse_integrator("euler"), IntegratorKind::kExplicitEuler);
  EXPECT_EQ(parse_integrator("symplectic_euler"), IntegratorKind::kSymplecticEuler);
  EXPECT_FALSE(parse_integrator("verlet").has_value());
  EXPECT_EQ(to_string(IntegratorKind::kRK4), "rk4");
}

}  // namespace
}  // namespace rift
