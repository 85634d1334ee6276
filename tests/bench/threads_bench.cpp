// Every core (issue 12): the same step on 1 and 2 threads, side by side in one
// run, wall-clock time (the point of threads). The simulation of each size
// is built once and stepped by every thread count in turn, so the ratios
// compare the same work; the results are the same bits for any thread count
// (tests/cli: AnyThreadCountGivesByteIdenticalOutputs). See
// docs/performance.md "Every core" for the command and the figures.
//
// BM_ThreadsRk4Cloth/N/T: one RK4 step of the paper's hanging quad cloth
// (stretch, shear, bend springs) on an N×N grid with T threads.
// BM_ThreadsImplicitBeam/T: one implicit Euler step of the co-rotational
// beam block:tet:8x8x50 (CG capped at 10 iterations) with T threads.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "paper_cloth_sim.hpp"
#include "rift/core/parallel.hpp"
#include "rift/io/load_map.hpp"

namespace {

using rift::Real;
using rift::Vec3;

rift::Simulation& cloth(int n) {
  static std::map<int, std::unique_ptr<rift::Simulation>> built;
  auto& sim = built[n];
  if (sim) return *sim;
  sim = rift::bench::paper_cloth_simulation(rift::GridKind::Quad, n);
  sim->step();  // warm: every buffer at its size
  return *sim;
}

rift::Simulation& beam() {
  static std::unique_ptr<rift::Simulation> sim;
  if (sim) return *sim;
  using namespace rift::physics_test;
  rift::GMap map = rift::load_map("block:tet:8x8x50");
  for (Vec3& x : map.embedding<Vec3>("position").values())
    x = Vec3(0.16 * x.x(), 0.16 * x.y(), x.z());
  SimSetup setup;
  setup.settings.integrator = rift::IntegratorKind::kImplicitEuler;
  setup.settings.dt = 0.01;
  setup.settings.gravity = Vec3(0, -9.81, 0);
  setup.settings.implicit.cg_max_iterations = 10;
  setup.settings.implicit.cg_tolerance = 1e-30;
  setup.interactions = {{"corotational", {{"young", 1e6}, {"poisson", 0.3}}}};
  setup.prepare = [](rift::Simulation& s) {
    s.set_density(1000);
    s.pin_where([](const Vec3& x) { return x.z() < 1e-9; });
  };
  sim = simulate(std::move(map), setup);
  sim->step();
  return *sim;
}

void run_steps(benchmark::State& state, rift::Simulation& sim, int threads) {
  rift::set_thread_count(threads);
  for (auto _ : state) {
    sim.step();
    benchmark::DoNotOptimize(sim.position().values().data());
    benchmark::ClobberMemory();
  }
  rift::set_thread_count(0);
  for (const Vec3& x : sim.position().values()) {
    if (!x.allFinite()) {
      state.SkipWithError("the simulation exploded");
      break;
    }
  }
  state.counters["threads"] = threads;
  state.counters["vertices"] = static_cast<double>(sim.position().values().size());
}

void BM_ThreadsRk4Cloth(benchmark::State& state) {
  run_steps(state, cloth(static_cast<int>(state.range(0))), static_cast<int>(state.range(1)));
}

void BM_ThreadsImplicitBeam(benchmark::State& state) {
  run_steps(state, beam(), static_cast<int>(state.range(0)));
}

}  // namespace

BENCHMARK(BM_ThreadsRk4Cloth)
    ->ArgsProduct({{300, 1000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ThreadsImplicitBeam)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
