// One generated stretch spring (rules/mass_spring2d.rules) on a minimal map:
// two darts a -0- b, i.e. two particles joined by one half-edge, the first
// one pinned. Checked against the harmonic oscillator: RK4's period at
// dt = 1e-3, the convergence orders of RK4 and explicit Euler, and the energy
// of symplectic Euler over 10^4 steps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics_setup.hpp"

namespace rift::physics_test {
namespace {

constexpr Real kStiffness = 60;  // N/m, the paper's stretch stiffness
constexpr Real kMass = 0.1;      // kg, the paper's whole cloth on one spring
constexpr Real kRest = 0.1;      // m
const Real kOmega = std::sqrt(kStiffness / kMass);

struct OneSpring {
  std::unique_ptr<Simulation> sim;
  Dart fixed = kNoDart, moving = kNoDart;

  // Elongation l - l0 and its rate.
  std::pair<Real, Real> state() const {
    const Vec3 d = sim->position()[moving] - sim->position()[fixed];
    return {d.norm() - kRest,
            (sim->velocity()[moving] - sim->velocity()[fixed]).dot(d.normalized())};
  }
  Real energy() const { return sim->kinetic_energy() + elastic_energy(*sim); }
};

// The spring at rest along x (its rest length comes from this initial map),
// then released from l = (1 + stretch) l0.
OneSpring one_spring(IntegratorKind integrator, Real dt, Real stretch = 0.2,
                     Real divergence_factor = 100) {
  GMap g(2);
  const Dart a = g.create_dart();
  const Dart b = g.create_dart();
  g.link(a, b, 0);
  auto position = g.add_embedding<Vec3>("position", Orbit{1, 2}, MergePolicy::kMean, Vec3::Zero());
  position[a] = Vec3(0, 0, 0);
  position[b] = Vec3(kRest, 0, 0);
  SimSetup setup;
  setup.settings.integrator = integrator;
  setup.settings.dt = dt;
  setup.settings.gravity = Vec3::Zero();
  setup.settings.divergence_factor = divergence_factor;
  setup.interactions = {{"stretch", {{"stiffness", kStiffness}, {"damping", 0.0}}}};
  setup.prepare = [&](Simulation& sim) {
    // The map has no area: masses are given corner by corner.
    sim.corner_mass()[a] = 1.0;
    sim.corner_mass()[b] = kMass;
    EXPECT_EQ(sim.pin_where([](const Vec3& p) { return p.norm() < 1e-12; }), 1u);
  };
  OneSpring s{simulate(std::move(g), setup), a, b};
  EXPECT_EQ(s.sim->force_models()[0]->active_matches(), 1u);
  s.sim->position()[b] = Vec3(kRest * (1 + stretch), 0, 0);
  return s;
}

// Root in [0, 1] of the cubic Hermite interpolant with p(0) = p0 < 0 <= p(1) = p1
// and slopes m0, m1 per unit s.
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

TEST(OneSpring, Rk4PeriodAtDt1e3MatchesTheHarmonicOscillator) {
  const Real dt = 1e-3;
  OneSpring s = one_spring(IntegratorKind::kRK4, dt);
  std::vector<Real> crossings;
  auto [p0, v0] = s.state();
  const int periods = 10;
  while (crossings.size() < periods + 1 && s.sim->time() < 100) {
    const Real t0 = s.sim->time();
    s.sim->step();
    const auto [p1, v1] = s.state();
    if (p0 < 0 && p1 >= 0) crossings.push_back(t0 + dt * hermite_root(p0, p1, v0 * dt, v1 * dt));
    p0 = p1;
    v0 = v1;
  }
  ASSERT_EQ(crossings.size(), periods + 1u);
  const Real measured = (crossings.back() - crossings.front()) / periods;
  const Real analytic = 2 * std::numbers::pi / kOmega;
  EXPECT_LE(std::abs(measured - analytic) / analytic, 1e-6) << measured << " vs " << analytic;
}

// Error at t = 0.5 s (about two periods) against x(t) = l0 (1 + 0.2 cos wt).
Real error_at_half_second(IntegratorKind integrator, Real dt) {
  OneSpring s = one_spring(integrator, dt);
  const int steps = static_cast<int>(std::lround(0.5 / dt));
  for (int i = 0; i < steps; ++i)
    s.sim->step();
  const Real exact = 0.2 * kRest * std::cos(kOmega * steps * dt);
  return std::abs(s.state().first - exact);
}

Real measured_order(IntegratorKind integrator, Real dt) {
  const Real e1 = error_at_half_second(integrator, dt);
  const Real e2 = error_at_half_second(integrator, dt / 2);
  const Real e3 = error_at_half_second(integrator, dt / 4);
  // Both halvings must show the same order.
  const Real first = std::log2(e1 / e2);
  const Real second = std::log2(e2 / e3);
  EXPECT_NEAR(first, second, 0.15) << e1 << " " << e2 << " " << e3;
  return second;
}

TEST(OneSpring, Rk4ConvergesAtOrderFour) {
  EXPECT_NEAR(measured_order(IntegratorKind::kRK4, 5e-3), 4.0, 0.15);
}

TEST(OneSpring, ExplicitEulerConvergesAtOrderOne) {
  EXPECT_NEAR(measured_order(IntegratorKind::kExplicitEuler, 1e-4), 1.0, 0.1);
}

// Mean energy over one period starting at the current step.
Real mean_energy_over_a_period(OneSpring& s) {
  const int steps =
      static_cast<int>(std::lround(2 * std::numbers::pi / kOmega / s.sim->settings().dt));
  Real sum = 0;
  for (int i = 0; i < steps; ++i) {
    sum += s.energy();
    s.sim->step();
  }
  return sum / steps;
}

TEST(OneSpring, SymplecticEulerKeepsTheEnergyOver1e4Steps) {
  const Real dt = 1e-3;
  OneSpring s = one_spring(IntegratorKind::kSymplecticEuler, dt);
  const Real e0 = s.energy();
  const Real first = mean_energy_over_a_period(s);
  Real lowest = e0, highest = e0;
  while (s.sim->steps_done() < 10000) {
    s.sim->step();
    lowest = std::min(lowest, s.energy());
    highest = std::max(highest, s.energy());
  }
  const Real last = mean_energy_over_a_period(s);
  EXPECT_LT(std::abs(last - first) / first, 1e-3) << first << " -> " << last;
  // Bounded: the energy oscillates by about w dt / 2 either side of the
  // conserved modified energy, and does not grow.
  EXPECT_LT((highest - lowest) / e0, 1.2 * kOmega * dt);
}

TEST(OneSpring, ExplicitEulerGainsEnergyWhereSymplecticEulerDoesNot) {
  // The same measure fails for explicit Euler: (1 + (w dt)^2) per step. The
  // growth is the point here: the divergence check (which would stop the run
  // once the energy is 100 times the start's) is off.
  OneSpring s = one_spring(IntegratorKind::kExplicitEuler, 1e-3, 0.2, 0);
  const Real first = mean_energy_over_a_period(s);
  while (s.sim->steps_done() < 10000)
    s.sim->step();
  const Real last = mean_energy_over_a_period(s);
  EXPECT_GT(last / first, 10.0);
}

}  // namespace
}  // namespace rift::physics_test
