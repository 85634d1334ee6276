// One implicit Euler (or BDF2) step of a co-rotational tetrahedral beam of about
// 19 000 tetrahedra (block:tet:8x8x50, issue 10; SOFA reports ~42 ms per
// step for 18 954 tetrahedra with EulerImplicitSolver + CG, 10 iterations).
// CG runs exactly 10 iterations (its tolerance is out of reach). Counters:
// tetrahedra, and the fractions of the step spent assembling the element
// Jacobians (with the block-Jacobi update), in A·p products, and in the
// preconditioner. Each case runs on 1 and on 2 threads (the last argument),
// side by side in one run, timed on the wall clock (the point of threads).
// See docs/physics.md "The implicit step" for the figures.
#include <benchmark/benchmark.h>

#include "../physics/physics_setup.hpp"
#include "rift/core/parallel.hpp"
#include "rift/io/load_map.hpp"
#include "rift/sim/element_matrix.hpp"
#include "rift/sim/preconditioner.hpp"

namespace {

using rift::Real;
using rift::Vec3;

void BM_ImplicitCorotationalBeam(
    benchmark::State& state, rift::PreconditionerKind p, bool project_definite,
    rift::IntegratorKind integrator = rift::IntegratorKind::kImplicitEuler) {
  using namespace rift::physics_test;
  rift::GMap map = rift::load_map("block:tet:8x8x50");
  // 0.16 m x 0.16 m x 1 m, clamped at z = 0, sagging along -y.
  for (Vec3& x : map.embedding<Vec3>("position").values())
    x = Vec3(0.16 * x.x(), 0.16 * x.y(), x.z());
  SimSetup setup;
  setup.settings.integrator = integrator;
  setup.settings.dt = 0.01;
  setup.settings.gravity = Vec3(0, -9.81, 0);
  setup.settings.implicit.cg_max_iterations = 10;
  setup.settings.implicit.cg_tolerance = 1e-30;
  setup.settings.implicit.preconditioner = p;
  setup.settings.implicit.project_definite = project_definite;
  setup.interactions = {{"corotational", {{"young", 1e6}, {"poisson", 0.3}}}};
  setup.prepare = [](rift::Simulation& sim) {
    sim.set_density(1000);
    sim.pin_where([](const Vec3& x) { return x.z() < 1e-9; });
  };
  auto sim = simulate(std::move(map), setup);
  for (int s = 0; s < 5; ++s)
    sim->step();  // BDF2's first step is backward Euler: the timed ones are BDF2
  rift::ImplicitEuler& implicit = *sim->implicit();
  implicit.reset_times();
  rift::set_thread_count(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sim->step();
    benchmark::DoNotOptimize(sim->position().values().data());
    benchmark::ClobberMemory();
  }
  rift::set_thread_count(0);
  for (const Vec3& x : sim->position().values()) {
    if (!x.allFinite()) {
      state.SkipWithError("the beam exploded");
      break;
    }
  }
  const rift::ImplicitTimes& t = implicit.times();
  state.counters["threads"] = static_cast<double>(state.range(0));
  state.counters["tets"] = static_cast<double>(sim->force_models()[0]->active_matches());
  state.counters["cg_iterations"] = implicit.last().cg_iterations;
  state.counters["assembly"] = t.assembly / t.total;
  state.counters["products"] = t.products / t.total;
  state.counters["preconditioner"] = t.preconditioner / t.total;
}

BENCHMARK_CAPTURE(BM_ImplicitCorotationalBeam, jacobi, rift::PreconditionerKind::kJacobi, true)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// The price of the semidefinite test (element_matrix.hpp) beside the above.
BENCHMARK_CAPTURE(BM_ImplicitCorotationalBeam, jacobi_unprojected,
                  rift::PreconditionerKind::kJacobi, false)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ImplicitCorotationalBeam, incomplete_cholesky,
                  rift::PreconditionerKind::kIncompleteCholesky, true)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// BDF2 is backward Euler from an extrapolated state (bdf2.hpp): the same
// solve, plus two vector combinations per step. Beside implicit Euler's
// jacobi case above, in the same run.
BENCHMARK_CAPTURE(BM_ImplicitCorotationalBeam, bdf2_jacobi, rift::PreconditionerKind::kJacobi, true,
                  rift::IntegratorKind::kBdf2)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// What a tear costs the incomplete-Cholesky preconditioner (issue 10): its
// update on the beam's element blocks with the global pattern rebuilt
// (arg 1: the symbolic part, as after a tear) and without (arg 0: the
// numeric factorisation every step redoes). Compare with the step above.
void BM_IncompleteCholeskyUpdate(benchmark::State& state) {
  using namespace rift::physics_test;
  rift::GMap map = rift::load_map("block:tet:8x8x50");
  for (Vec3& x : map.embedding<Vec3>("position").values())
    x = Vec3(0.16 * x.x(), 0.16 * x.y(), x.z());
  SimSetup setup;
  setup.settings.dt = 0.01;
  setup.interactions = {{"corotational", {{"young", 1e6}, {"poisson", 0.3}}}};
  setup.prepare = [](rift::Simulation& sim) {
    sim.set_density(1000);
    sim.pin_where([](const Vec3& x) { return x.z() < 1e-9; });
  };
  auto sim = simulate(std::move(map), setup);
  // A bent state, so the blocks are those of a deformed beam.
  std::vector<Vec3> x = sim->position().values();
  for (Vec3& p : x)
    p.y() -= 0.05 * p.z() * p.z();
  const std::vector<Vec3> v(x.size(), Vec3::Zero());
  std::vector<rift::ForceModel*> models;
  for (const auto& m : sim->force_models())
    models.push_back(m.get());
  rift::ElementMatrix blocks;
  blocks.set_models(models);
  std::vector<Vec3> kxv;
  blocks.assemble(rift::ForceInput{x.data(), v.data()}, 0.01, x.size(), kxv);
  const std::vector<Real>& mass = sim->vertex_mass().values();
  std::vector<char> is_free(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    is_free[i] = sim->position().attachment().slot_alive(static_cast<rift::Slot>(i)) &&
                 sim->inverse_masses()[i] > 0;
  rift::Preconditioner ic(rift::PreconditionerKind::kIncompleteCholesky);
  ic.update(&blocks, mass, is_free, true);
  const bool rebuild = state.range(0) != 0;
  for (auto _ : state)
    ic.update(&blocks, mass, is_free, rebuild);
  state.counters["pattern_rebuilt"] = static_cast<double>(rebuild);
}

BENCHMARK(BM_IncompleteCholeskyUpdate)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
