// implicit_euler on the GENERATED packs, with the Jacobians riftc derives:
// a co-rotational tetrahedral cantilever stepped at dt = 0.01 s (hundreds of
// times its explicit limit) settles at the static deflection, and pinned
// vertices stay where they are.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "physics_setup.hpp"
#include "rift/io/load_map.hpp"

namespace rift::physics_test {
namespace {

// The beam of fem_test's cantilever (L = 10 m, h = 1 m, clamped at x = 0,
// 1000 kg/m^3, E = 1e9 Pa, gravity -z) with stiffness-proportional
// damping, so that it settles within a few seconds.
std::unique_ptr<Simulation> beam(IntegratorKind kind, Real dt) {
  GMap map = load_map("block:tet:20x2x2");
  for (Vec3& p : map.embedding<Vec3>("position").values())
    p = Vec3(10 * p.x(), p.y(), p.z());
  SimSetup setup;
  setup.settings.integrator = kind;
  setup.settings.dt = dt;
  setup.settings.gravity = Vec3(0, 0, -9.81);
  setup.settings.implicit.cg_tolerance = 1e-8;
  setup.settings.implicit.preconditioner = PreconditionerKind::kIncompleteCholesky;
  setup.settings.implicit.cg_max_iterations = 1000;
  setup.interactions = {{"corotational", {{"young", 1e9}, {"poisson", 0.3}, {"damping", 0.02}}}};
  setup.prepare = [](Simulation& sim) {
    sim.set_density(1000);
    sim.pin_where([](const Vec3& p) { return p.x() < 1e-9; });
  };
  return simulate(std::move(map), setup);
}

// Mean downward deflection of the free end (x = 10).
Real tip_deflection(const Simulation& sim, const std::vector<Vec3>& rest) {
  const auto& x = sim.position().values();
  Real sum = 0;
  int count = 0;
  for (std::size_t s = 0; s < x.size(); ++s) {
    if (rest[s].x() > 10 - 1e-9) {
      sum += rest[s].z() - x[s].z();
      ++count;
    }
  }
  return sum / count;
}

// The static deflection of the same beam: K u = -m g on the free vertices,
// with K = -∂f/∂x at rest from the element blocks (linear: the deflection is
// 1 % of the length).
std::vector<Vec3> static_displacement(Simulation& sim) {
  ForceModel& model = *sim.force_models()[0];
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  const std::size_t k = static_cast<std::size_t>(model.jacobian_vertices());
  const std::size_t m = model.active_matches(), n = x.size();
  std::vector<Slot> slots(m * k);
  std::vector<Mat3> jx(m * k * k), jv(m * k * k);
  model.jacobians({x.data(), v.data()}, slots.data(), jx.data(), jv.data());
  std::vector<int> index(n, -1);
  int unknowns = 0;
  for (std::size_t s = 0; s < n; ++s)
    if (x[s].x() > 1e-9) index[s] = unknowns++;
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(3 * unknowns, 3 * unknowns);
  for (std::size_t e = 0; e < m; ++e)
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = 0; j < k; ++j) {
        const int a = index[slots[e * k + i]], b = index[slots[e * k + j]];
        if (a >= 0 && b >= 0) stiffness.block<3, 3>(3 * a, 3 * b) -= jx[e * k * k + i * k + j];
      }
  Eigen::VectorXd load(3 * unknowns);
  for (std::size_t s = 0; s < n; ++s)
    if (index[s] >= 0)
      load.segment<3>(3 * index[s]) = sim.vertex_mass().values()[s] * sim.settings().gravity;
  const Eigen::VectorXd u = stiffness.ldlt().solve(load);
  EXPECT_LT((stiffness * u - load).norm(), 1e-8 * load.norm());
  std::vector<Vec3> out(n, Vec3::Zero());
  for (std::size_t s = 0; s < n; ++s)
    if (index[s] >= 0) out[s] = u.segment<3>(3 * index[s]);
  return out;
}

TEST(ImplicitCorotational, CantileverAtDtOneHundredthSettlesAtTheStaticDeflection) {
  auto sim = beam(IntegratorKind::kImplicitEuler, 0.01);
  const std::vector<Vec3> rest = sim->position().values();
  const std::vector<Vec3> u = static_displacement(*sim);
  Real expected = 0;
  int count = 0;
  for (std::size_t s = 0; s < rest.size(); ++s) {
    if (rest[s].x() > 10 - 1e-9) {
      expected -= u[s].z();
      ++count;
    }
  }
  expected /= count;
  ASSERT_GT(expected, 1e-3);
  for (int step = 0; step < 600; ++step)
    sim->step();
  const Real tip = tip_deflection(*sim, rest);
  std::printf("implicit cantilever tip %.5f m, static %.5f m (ratio %.4f)\n", tip, expected,
              tip / expected);
  EXPECT_NEAR(tip / expected, 1.0, 0.05);
  EXPECT_LT(sim->kinetic_energy(), 1e-6 * sim->total_mass());
  // The clamped end did not move.
  const auto& x = sim->position().values();
  for (std::size_t s = 0; s < x.size(); ++s) {
    if (rest[s].x() < 1e-9) {
      EXPECT_EQ(x[s], rest[s]);
    }
  }
}

TEST(ImplicitCorotational, ExplicitIntegratorsExplodeAtThatStep) {
  // The same beam at the same dt with RK4: the step is far beyond its limit
  // (so the implicit test above is not trivially stable).
  auto sim = beam(IntegratorKind::kRK4, 0.01);
  EXPECT_THROW(
      {
        for (int step = 0; step < 200; ++step)
          sim->step();
      },
      SimulationError);
}

}  // namespace
}  // namespace rift::physics_test

namespace rift::physics_test {
namespace {

// The Newton line search on the incremental potential of backward Euler,
// E(v1) = ½ |v1 - v0|²_M + Φ(x0 + h v1), Φ = elastic energy - Σ m g·x: a
// hanging cloth of undamped springs stepped from rest at 50 ms, far past its
// explicit limit (springs stretch and compress: a stiff, nonlinear step).
struct NewtonStep {
  Real energy = 0;  // E(v1), computed here from the end state
  ImplicitStats stats;
};

NewtonStep newton_step(LineSearch search, int iterations, Real damping = 0) {
  SimSetup setup;
  setup.settings.integrator = IntegratorKind::kImplicitEuler;
  setup.settings.dt = 0.05;
  setup.settings.gravity = Vec3(0, -9.81, 0);
  setup.settings.implicit.newton_iterations = iterations;
  setup.settings.implicit.newton_tolerance = 1e-12;
  setup.settings.implicit.cg_tolerance = 1e-12;
  setup.settings.implicit.cg_max_iterations = 2000;
  setup.settings.implicit.line_search = search;
  setup.interactions = {{"stretch", {{"stiffness", 600.0}, {"damping", damping}}},
                        {"shear", {{"stiffness", 430.0}, {"damping", damping}}},
                        {"bend", {{"stiffness", 10.0}, {"damping", damping}}}};
  setup.prepare = [](Simulation& sim) {
    sim.set_total_mass(0.1);
    sim.pin_where([](const Vec3& p) { return p.y() > 0.999 && (p.x() < 1e-3 || p.x() > 0.999); });
  };
  auto sim = simulate(load_map("grid:quad:12x12"), setup);
  sim->step();  // from rest: v0 = 0
  NewtonStep out;
  out.stats = sim->implicit()->last();
  const auto& x = sim->position().values();
  const auto& v = sim->velocity().values();
  const auto& mass = sim->vertex_mass().values();
  const auto& w = sim->inverse_masses();
  out.energy = elastic_energy(*sim);
  for (std::size_t s = 0; s < x.size(); ++s) {
    if (w[s] > 0)
      out.energy += 0.5 * mass[s] * v[s].squaredNorm() - mass[s] * Vec3(0, -9.81, 0).dot(x[s]);
  }
  return out;
}

TEST(ImplicitNewton, EnergyLineSearchDecreasesTheIncrementalPotentialMonotonically) {
  Real previous = newton_step(LineSearch::kEnergy, 1).energy;
  for (int k = 2; k <= 10; ++k) {
    const NewtonStep s = newton_step(LineSearch::kEnergy, k);
    EXPECT_TRUE(s.stats.energy_search);
    EXPECT_LE(s.energy, previous + 1e-12 * std::abs(previous)) << "after " << k << " iterations";
    previous = s.energy;
  }
}

TEST(ImplicitNewton, EnergyLineSearchConvergesAtLeastAsWellAsTheResidualSearch) {
  const NewtonStep energy = newton_step(LineSearch::kEnergy, 40);
  const NewtonStep residual = newton_step(LineSearch::kResidual, 40);
  EXPECT_TRUE(energy.stats.energy_search);
  EXPECT_FALSE(residual.stats.energy_search);
  // Converged: stopped by newton_tolerance, before the iteration limit.
  EXPECT_LT(energy.stats.newton_iterations, 40);
  EXPECT_GT(energy.stats.newton_iterations, 2);
  EXPECT_LE(energy.stats.newton_iterations, residual.stats.newton_iterations);
  EXPECT_LE(energy.energy, residual.energy + 1e-12 * std::abs(residual.energy));
}

TEST(ImplicitNewton, DampedForcesFallBackToTheResidualSearch) {
  // Damping forces have no potential: E's minimum is not the step.
  EXPECT_FALSE(newton_step(LineSearch::kEnergy, 3, 0.1).stats.energy_search);
}

}  // namespace
}  // namespace rift::physics_test
