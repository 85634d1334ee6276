// One spring of the reference solver against the harmonic oscillator: the
// period of RK4 at dt = 1e-3 against 2 pi sqrt(m / k), crossings timed with a
// cubic Hermite interpolation of positions and velocities.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "reference_cloth.hpp"

namespace rift::reference {
namespace {

constexpr Real kStiffness = 60;  // N/m, the paper's stretch stiffness
constexpr Real kMass = 0.1;      // kg, the paper's whole cloth on one spring
constexpr Real kRest = 0.1;      // m

// Root in [0, 1] of the cubic Hermite interpolant of p with p(0) = p0,
// p(1) = p1, p'(0) = m0, p'(1) = m1 (slopes per unit s), p0 < 0 <= p1.
Real hermite_root(Real p0, Real p1, Real m0, Real m1) {
  auto p = [&](Real s) {
    const Real s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 +
           (s3 - s2) * m1;
  };
  Real lo = 0, hi = 1;
  for (int it = 0; it < 100; ++it) {
    const Real mid = (lo + hi) / 2;
    (p(mid) < 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// Mean period of the spring's length oscillation over `periods` periods:
// upward crossings of l - rest through zero.
Real measured_period(ReferenceCloth& cloth, Real dt, int periods) {
  auto state = [&] {
    const Vec3 d = cloth.positions()[1] - cloth.positions()[0];
    const Vec3 u = d.normalized();
    return std::pair<Real, Real>(d.norm() - kRest,
                                 (cloth.velocities()[1] - cloth.velocities()[0]).dot(u));
  };
  std::vector<Real> crossings;
  auto [p0, v0] = state();
  while (crossings.size() < static_cast<std::size_t>(periods + 1)) {
    const Real t0 = cloth.time();
    cloth.step_rk4(dt);
    const auto [p1, v1] = state();
    if (p0 < 0 && p1 >= 0) crossings.push_back(t0 + dt * hermite_root(p0, p1, v0 * dt, v1 * dt));
    p0 = p1;
    v0 = v1;
  }
  return (crossings.back() - crossings.front()) / periods;
}

// RK4 maps a harmonic oscillator's phase by arg R(i w dt) per step.
Real rk4_period(Real omega, Real dt) {
  const std::complex<Real> z(0, omega * dt);
  const std::complex<Real> r = 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
  return 2 * std::numbers::pi * dt / std::arg(r);
}

TEST(SpringPeriod, MassOnAPinnedSpringAtDt1e3) {
  ReferenceCloth cloth({Vec3(0, 0, 0), Vec3(kRest * 1.2, 0, 0)}, {1.0, kMass},
                       {{0, 1, kRest, kStiffness, 0}}, Vec3::Zero());
  cloth.pin(0);
  const Real dt = 1e-3;
  const Real omega = std::sqrt(kStiffness / kMass);
  const Real analytic = 2 * std::numbers::pi / omega;
  const Real measured = measured_period(cloth, dt, 10);
  EXPECT_LE(std::abs(measured - analytic) / analytic, 1e-6);
  // Sharper: the crossings resolve RK4's own phase error, (w dt)^4 / 120 of the period.
  EXPECT_LE(std::abs(measured - rk4_period(omega, dt)) / analytic, 1e-10);
  EXPECT_GT(std::abs(measured - analytic), std::abs(measured - rk4_period(omega, dt)));
}

TEST(SpringPeriod, TwoFreeMassesUseTheReducedMass) {
  const Real m1 = 0.03, m2 = 0.07;
  ReferenceCloth cloth({Vec3(0, 0, 0), Vec3(0, kRest * 0.9, 0)}, {m1, m2},
                       {{0, 1, kRest, kStiffness, 0}}, Vec3::Zero());
  const Real dt = 1e-3;
  const Real omega = std::sqrt(kStiffness * (m1 + m2) / (m1 * m2));
  const Real analytic = 2 * std::numbers::pi / omega;
  const Real measured = measured_period(cloth, dt, 10);
  EXPECT_LE(std::abs(measured - analytic) / analytic, 1e-6);
  EXPECT_LE(std::abs(measured - rk4_period(omega, dt)) / analytic, 1e-10);
  // The centre of mass does not move.
  EXPECT_LT(cloth.momentum().norm(), 1e-15);
}

TEST(SpringPeriod, DampingDecaysAtTheAnalyticRate) {
  // m x'' = -k x - c x': the amplitude decays as exp(-c t / (2 m)).
  const Real c = 0.2;
  ReferenceCloth cloth({Vec3(0, 0, 0), Vec3(kRest * 1.1, 0, 0)}, {1.0, kMass},
                       {{0, 1, kRest, kStiffness, c}}, Vec3::Zero());
  cloth.pin(0);
  const Real dt = 1e-4;
  const Real omega_d = std::sqrt(kStiffness / kMass - std::pow(c / (2 * kMass), 2));
  const Real period = 2 * std::numbers::pi / omega_d;
  // Energy-like invariant of the damped oscillator, sampled one period apart.
  auto amplitude2 = [&] {
    const Real x = cloth.positions()[1].x() - kRest;
    const Real v = cloth.velocities()[1].x();
    const Real gamma = c / (2 * kMass);
    return std::pow(x, 2) + std::pow((v + gamma * x) / omega_d, 2);
  };
  const Real a0 = amplitude2();
  const int steps = static_cast<int>(std::lround(5 * period / dt));
  for (int s = 0; s < steps; ++s)
    cloth.step_rk4(dt);
  const Real expected = a0 * std::exp(-c / kMass * steps * dt);
  EXPECT_NEAR(amplitude2() / expected, 1.0, 1e-8);
}

}  // namespace
}  // namespace rift::reference
