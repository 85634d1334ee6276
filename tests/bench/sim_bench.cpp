// One RK4 step of the paper's cloth (Fig. 14, Table 2 "basic step") with the
// GENERATED packs of rules/ in the runtime's Simulation, beside the
// hand-written flat-array reference solver (tests/reference/) on the same
// cloth. Reported as time per step; `springs` counts the atomic springs,
// `s_per_spring` is the step time over springs x 4 force evaluations. See
// docs/physics.md §7 for the command and the figures.
#include <benchmark/benchmark.h>

#include "paper_cloth_sim.hpp"

namespace {

using rift::GridKind;
using rift::Real;
using rift::Vec3;

using rift::bench::paper_cloth_dt;

void report(benchmark::State& state, double springs, double vertices) {
  state.counters["springs"] = springs;
  state.counters["vertices"] = vertices;
  state.counters["s_per_spring"] =
      benchmark::Counter(4 * springs * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_GeneratedRk4Step(benchmark::State& state, GridKind kind, bool grouped) {
  const int n = static_cast<int>(state.range(0));
  auto sim = rift::bench::paper_cloth_simulation(kind, n, grouped);
  for (int s = 0; s < 200; ++s)
    sim->step();
  for (auto _ : state) {
    sim->step();
    benchmark::DoNotOptimize(sim->position().values().data());
    benchmark::ClobberMemory();
  }
  for (const Vec3& x : sim->position().values()) {
    if (!x.allFinite()) {
      state.SkipWithError("the cloth exploded");
      break;
    }
  }
  const auto& m = sim->force_models();
  // stretch, shear (two diagonals per matched quad), bend
  report(state,
         static_cast<double>(m[0]->active_matches() + 2 * m[1]->active_matches() +
                             m[2]->active_matches()),
         static_cast<double>(sim->map().count_cells(rift::Orbit{1, 2})));
}

// cumulated: one spring per vertex pair (ReferenceCloth::cumulate_springs),
// the fastest plain way to step this cloth; otherwise the atomic springs.
void BM_ReferenceRk4Step(benchmark::State& state, GridKind kind, bool cumulated) {
  const int n = static_cast<int>(state.range(0));
  rift::reference::ReferenceCloth cloth = rift::reference::paper_cloth(kind, n, n);
  if (cumulated) cloth.cumulate_springs();
  for (int s = 0; s < 200; ++s)
    cloth.step_rk4(paper_cloth_dt(n));
  for (auto _ : state) {
    cloth.step_rk4(paper_cloth_dt(n));
    benchmark::DoNotOptimize(cloth.positions().data());
    benchmark::ClobberMemory();
  }
  report(state, static_cast<double>(cloth.springs().size()),
         static_cast<double>(cloth.vertex_count()));
}

}  // namespace

BENCHMARK_CAPTURE(BM_GeneratedRk4Step, quads, GridKind::Quad, true)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_GeneratedRk4Step, quads_ungrouped, GridKind::Quad, false)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, quads, GridKind::Quad, false)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, quads_cumulated, GridKind::Quad, true)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_GeneratedRk4Step, triangles, GridKind::Tri, true)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_GeneratedRk4Step, triangles_ungrouped, GridKind::Tri, false)
    ->Arg(10)
    ->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, triangles, GridKind::Tri, false)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, triangles_cumulated, GridKind::Tri, true)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_GeneratedRk4Step, mixed, GridKind::Mix, true)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_GeneratedRk4Step, mixed_ungrouped, GridKind::Mix, false)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, mixed, GridKind::Mix, false)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, mixed_cumulated, GridKind::Mix, true)->Arg(10)->Arg(100);

BENCHMARK_MAIN();
