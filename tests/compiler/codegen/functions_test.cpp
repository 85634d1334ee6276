// Functions (`def`) in generated code: golden/ok_functions/case.rules
// compiled by riftc. A spring written with functions gives the forces of the
// same spring written out, its Jacobian (derived through the inlined calls)
// matches central differences of its forces, and the calls of rules,
// scripts, inits and criteria compute what their functions say.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "functions.hpp"
#include "rift/io/load_map.hpp"
#include "rift/sim/simulation.hpp"

namespace {

namespace fp = rift::packs::functions;
using rift::ComponentUse;
using rift::Dart;
using rift::GMap;
using rift::Real;
using rift::SceneParam;
using rift::Simulation;
using rift::Slot;
using rift::Value;
using rift::Vec3;

ComponentUse use(const char* name) {
  ComponentUse u;
  u.name = name;
  u.params["stiffness"] = SceneParam{Value(60.0), 0};
  u.params["damping"] = SceneParam{Value(0.3), 0};
  return u;
}

/// A grid deformed and set moving at random after its rest lengths are taken.
std::unique_ptr<Simulation> spring_grid(const char* interaction) {
  GMap g = rift::load_map("grid:mix:3x3");
  const fp::Pack pack;
  pack.initialise(g);
  auto sim = std::make_unique<Simulation>(std::move(g), rift::SimulationSettings{});
  sim->set_total_mass(1.0);
  sim->add_force_model(pack.make_interaction(use(interaction)));
  sim->initialise();
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (Vec3& x : sim->position().values())
    x += 0.1 * Vec3(u(rng), u(rng), u(rng));
  for (Vec3& v : sim->velocity().values())
    v = 0.5 * Vec3(u(rng), u(rng), u(rng));
  return sim;
}

std::vector<Vec3> forces(Simulation& sim) {
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  sim.force_models()[0]->add_forces({x.data(), v.data()}, f.data(), false);
  return f;
}

/// The position and velocity Jacobians of every match summed into dense matrices.
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> jacobians(Simulation& sim) {
  rift::ForceModel& model = *sim.force_models()[0];
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  const auto k = static_cast<std::size_t>(model.jacobian_vertices());
  const std::size_t m = model.active_matches();
  std::vector<Slot> slots(m * k);
  std::vector<rift::Mat3> jx(m * k * k), jv(m * k * k);
  model.jacobians({x.data(), v.data()}, slots.data(), jx.data(), jv.data());
  const auto dofs = static_cast<Eigen::Index>(3 * x.size());
  Eigen::MatrixXd kx = Eigen::MatrixXd::Zero(dofs, dofs), kv = kx;
  for (std::size_t e = 0; e < m; ++e) {
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = 0; j < k; ++j) {
        const Slot a = slots[e * k + i], b = slots[e * k + j];
        kx.block<3, 3>(3 * a, 3 * b) += jx[e * k * k + i * k + j];
        kv.block<3, 3>(3 * a, 3 * b) += jv[e * k * k + i * k + j];
      }
    }
  }
  return {kx, kv};
}

/// Largest |central difference - Jacobian entry|, relative to the largest entry.
Real finite_difference_error(Simulation& sim, const Eigen::MatrixXd& k, bool wrt_x) {
  auto& state = wrt_x ? sim.position().values() : sim.velocity().values();
  const Real h = 1e-6;
  Real worst = 0;
  for (std::size_t s = 0; s < state.size(); ++s) {
    for (int c = 0; c < 3; ++c) {
      const Real keep = state[s][c];
      state[s][c] = keep + h;
      const std::vector<Vec3> plus = forces(sim);
      state[s][c] = keep - h;
      const std::vector<Vec3> minus = forces(sim);
      state[s][c] = keep;
      for (std::size_t r = 0; r < plus.size(); ++r) {
        for (int a = 0; a < 3; ++a) {
          const Real fd = (plus[r][a] - minus[r][a]) / (2 * h);
          const auto row = static_cast<Eigen::Index>(3 * r + static_cast<std::size_t>(a));
          const auto col = static_cast<Eigen::Index>(3 * s + static_cast<std::size_t>(c));
          worst = std::max(worst, std::abs(fd - k(row, col)));
        }
      }
    }
  }
  return worst / k.cwiseAbs().maxCoeff();
}

TEST(Functions, SpringThroughFunctionsGivesTheForcesOfTheSpringWrittenOut) {
  auto with_def = spring_grid("spring_def");
  auto written_out = spring_grid("spring_inline");
  const std::vector<Vec3> a = forces(*with_def), b = forces(*written_out);
  ASSERT_EQ(a.size(), b.size());
  Real largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, a[i].norm());
    EXPECT_LT((a[i] - b[i]).norm(), 1e-12 * (1 + b[i].norm())) << "vertex " << i;
  }
  EXPECT_GT(largest, 0.1);  // deformed and moving: the springs pull
}

TEST(Functions, JacobianThroughFunctionsMatchesCentralDifferences) {
  auto sim = spring_grid("spring_def");
  ASSERT_GT(sim->force_models()[0]->jacobian_vertices(), 0)
      << sim->force_models()[0]->jacobian_unavailable_reason();
  const auto [kx, kv] = jacobians(*sim);
  ASSERT_GT(kx.cwiseAbs().maxCoeff(), 0.0);
  ASSERT_GT(kv.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LT(finite_difference_error(*sim, kx, true), 1e-6);
  EXPECT_LT(finite_difference_error(*sim, kv, false), 1e-6);
  // ... and the same blocks as the spring written out.
  auto written_out = spring_grid("spring_inline");
  const auto [kx2, kv2] = jacobians(*written_out);
  EXPECT_LT((kx - kx2).cwiseAbs().maxCoeff(), 1e-10 * kx.cwiseAbs().maxCoeff());
  EXPECT_LT((kv - kv2).cwiseAbs().maxCoeff(), 1e-10 * kv.cwiseAbs().maxCoeff());
}

TEST(Functions, InitRuleAndScriptComputeWhatTheirFunctionsSay) {
  GMap g = rift::load_map("grid:quad:2x1");
  fp::declare_embeddings(g);
  fp::run_initialisers(g);
  const auto position = g.embedding<Vec3>("position");
  const auto half = g.embedding<Real>("half");
  const auto mark = g.embedding<Real>("mark");
  const Dart d = 0;
  // init half(e) = 0.5 * length(difference(e.position, e@0.position))
  EXPECT_NEAR(half[d], 0.5 * (position[g.alpha(d, 0)] - position[d]).norm(), 1e-15);
  EXPECT_GT(half[d], 0.0);
  // rule nudge: a.mark = twice(by) + 1
  fp::nudge_args args;
  args.by = 0.25;
  ASSERT_TRUE(fp::apply_nudge(g, std::span<const Dart>(&d, 1), args));
  EXPECT_DOUBLE_EQ(mark[d], 1.5);
  // script nudge_twice: applies nudge with by = twice(by)
  fp::nudge_twice_args twice;
  twice.by = 0.25;
  ASSERT_TRUE(fp::apply_nudge_twice(g, std::span<const Dart>(&d, 1), twice));
  EXPECT_DOUBLE_EQ(mark[d], 2.0);
}

TEST(Functions, CriterionMeasuresThroughItsFunctions) {
  GMap g = rift::load_map("grid:quad:2x1");
  const fp::Pack pack;
  pack.initialise(g);
  ComponentUse u;
  u.name = "long_edge";
  u.params["ratio"] = SceneParam{Value(1.5), 0};
  auto criterion = pack.make_criterion(u);
  criterion->initialise(g);
  std::vector<rift::TearCandidate> found;
  criterion->collect(g, found);
  EXPECT_TRUE(found.empty());  // at rest every edge has ratio 1
  // Stretch the edges at dart 0's vertex: length(difference(...)) / (2 half) passes 1.5.
  auto position = g.embedding<Vec3>("position");
  position[Dart{0}] += Vec3(-2.0, -2.0, 0.0);  // one slot per vertex
  criterion->collect(g, found);
  ASSERT_FALSE(found.empty());
  for (const rift::TearCandidate& c : found)
    EXPECT_GT(c.measure, 0.0);
}

}  // namespace
