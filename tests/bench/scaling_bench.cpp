// Time per vertex of one RK4 step against mesh size, 10^2 ... 10^6 vertices
// (issue 12, deliverable 7; the plot of docs/performance.md "Scaling").
//
//   cloth, quads and triangles: the paper's hanging cloth (stretch, shear,
//     bend) with the generated packs of rules/, beside the hand-written
//     flat-array reference of tests/reference in its two variants: atomic
//     springs as the paper writes them, and springs cumulated per vertex pair
//     (the fastest plain way to step that cloth);
//   solids: hexahedra with the paper's 3D mass-spring model (stretch, shear,
//     volume shear) and tetrahedra with co-rotational FEM, both generated (no
//     hand-written 3D reference exists; BM_CorotationalElement in
//     rift_bench_corotational is the per-element one).
//
// Each benchmark reports `vertices` and `s_per_vertex` (seconds per vertex
// per step; the plot shows it in ns). scripts/plot-scaling.py turns the
// --benchmark_format=json output into docs/images/performance-scaling.png.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "paper_cloth_sim.hpp"
#include "rift/core/parallel.hpp"

namespace {

using rift::GridKind;
using rift::Real;
using rift::Vec3;

using rift::bench::paper_cloth_dt;

void report(benchmark::State& state, double vertices) {
  state.counters["vertices"] = vertices;
  state.counters["s_per_vertex"] =
      benchmark::Counter(vertices * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Steps on one thread (the plot compares the work per vertex; threads:
// rift_bench_threads). False, with the benchmark skipped, when the
// simulation diverged.
template <typename Step>
bool run_steps(benchmark::State& state, Step&& step, const Vec3* watched) {
  rift::set_thread_count(1);
  try {
    for (int s = 0; s < 3; ++s)  // warm: first-touch pages, lazy columns, caches
      step();
    for (auto _ : state) {
      step();
      benchmark::DoNotOptimize(watched);
      benchmark::ClobberMemory();
    }
  } catch (const rift::SimulationError& e) {
    state.SkipWithError(e.what());
    return false;
  }
  return true;
}

void BM_ScalingClothRift(benchmark::State& state, GridKind kind, bool grouped) {
  auto sim = rift::bench::paper_cloth_simulation(kind, static_cast<int>(state.range(0)), grouped);
  if (!run_steps(
          state, [&] { sim->step(); }, sim->position().values().data()))
    return;
  report(state, static_cast<double>(sim->map().count_cells_of_dimension(0)));
}

bool all_finite(const std::vector<Vec3>& x) {
  for (const Vec3& p : x) {
    if (!p.allFinite()) return false;
  }
  return true;
}

void BM_ScalingClothReference(benchmark::State& state, GridKind kind, bool cumulated) {
  const int n = static_cast<int>(state.range(0));
  rift::reference::ReferenceCloth cloth = rift::reference::paper_cloth(kind, n, n);
  if (cumulated) cloth.cumulate_springs();
  run_steps(
      state, [&] { cloth.step_rk4(paper_cloth_dt(n)); }, cloth.positions().data());
  if (!all_finite(cloth.positions())) state.SkipWithError("the cloth exploded");
  state.counters["springs"] = static_cast<double>(cloth.springs().size());
  report(state, static_cast<double>(cloth.vertex_count()));
}

void BM_ScalingSolid(benchmark::State& state, rift::BlockKind kind, bool grouped) {
  using namespace rift::physics_test;
  const int n = static_cast<int>(state.range(0));
  SimSetup setup;
  setup.settings.integrator = rift::IntegratorKind::kRK4;
  // The time per step does not depend on dt; a tiny one keeps the finest
  // block, stiffest at its smallest elements, within its stability limit.
  setup.settings.dt = 1e-7;
  setup.settings.group_interactions = grouped;
  if (kind == rift::BlockKind::Hex) {
    setup.interactions = {{"stretch", {}}, {"shear", {}}, {"volume_shear", {}}};
  } else {
    setup.interactions = {{"corotational", {{"young", 1e5}, {"poisson", 0.3}, {"damping", 0.0}}}};
  }
  const rift::MeshData mesh = rift::make_block(kind, n, n, n);
  auto sim = simulate(rift::assemble_gmap(mesh), setup);
  if (!run_steps(
          state, [&] { sim->step(); }, sim->position().values().data()))
    return;
  report(state, static_cast<double>(mesh.points.size()));
}

// Cloth n x n: (n + 1)^2 vertices, 121 ... 1 002 001.
void cloth_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10, 31, 99, 315, 999})
    b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

// Block n^3: (n + 1)^3 vertices, 125 ... 1 000 000.
void solid_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {4, 10, 21, 46, 99})
    b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK_CAPTURE(BM_ScalingClothRift, quads, GridKind::Quad, true)->Apply(cloth_sizes);
// Every atomic spring evaluated (identical ones not grouped), to compare.
BENCHMARK_CAPTURE(BM_ScalingClothRift, quads_ungrouped, GridKind::Quad, false)->Apply(cloth_sizes);
BENCHMARK_CAPTURE(BM_ScalingClothReference, quads_atomic, GridKind::Quad, false)
    ->Apply(cloth_sizes);
BENCHMARK_CAPTURE(BM_ScalingClothReference, quads_cumulated, GridKind::Quad, true)
    ->Apply(cloth_sizes);
BENCHMARK_CAPTURE(BM_ScalingClothRift, triangles, GridKind::Tri, true)->Apply(cloth_sizes);
BENCHMARK_CAPTURE(BM_ScalingClothRift, triangles_ungrouped, GridKind::Tri, false)
    ->Apply(cloth_sizes);
BENCHMARK_CAPTURE(BM_ScalingClothReference, triangles_atomic, GridKind::Tri, false)
    ->Apply(cloth_sizes);
BENCHMARK_CAPTURE(BM_ScalingClothReference, triangles_cumulated, GridKind::Tri, true)
    ->Apply(cloth_sizes);
BENCHMARK_CAPTURE(BM_ScalingSolid, hexahedra, rift::BlockKind::Hex, true)->Apply(solid_sizes);
BENCHMARK_CAPTURE(BM_ScalingSolid, hexahedra_ungrouped, rift::BlockKind::Hex, false)
    ->Apply(solid_sizes);
BENCHMARK_CAPTURE(BM_ScalingSolid, tetrahedra, rift::BlockKind::Tet, true)->Apply(solid_sizes);

BENCHMARK_MAIN();
