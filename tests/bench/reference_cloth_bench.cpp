// One RK4 step of the hand-written flat-array reference cloth
// (tests/reference/reference_cloth.hpp), the speed baseline of the physics
// issue: the paper's Table 2 meshes (10 x 10 patches) and the same cloth at
// 100 x 100. Reported as time per step (ns); the counter `springs` is the
// number of atomic springs, `s_per_spring` the step time over springs x 4
// force evaluations. See docs/physics.md for the command and the figures.
#include <benchmark/benchmark.h>

#include "../reference/paper_cloth.hpp"

namespace {

using rift::GridKind;
using rift::reference::kPaperDt;
using rift::reference::paper_cloth;
using rift::reference::ReferenceCloth;

void BM_ReferenceRk4Step(benchmark::State& state, GridKind kind) {
  const int n = static_cast<int>(state.range(0));
  ReferenceCloth cloth = paper_cloth(kind, n, n);
  // The same 100 g cloth on a finer grid has lighter vertices: the damping
  // limit of RK4 (docs/physics.md) scales as h^2, so dt does too. An exploded
  // state would skip the work of every spring and time nothing useful.
  const double dt = kPaperDt * (10.0 / n) * (10.0 / n);
  // Start from a moving, deformed cloth rather than the rest shape.
  for (int s = 0; s < 200; ++s)
    cloth.step_rk4(dt);
  for (auto _ : state) {
    cloth.step_rk4(dt);
    benchmark::DoNotOptimize(cloth.positions().data());
    benchmark::ClobberMemory();
  }
  for (const auto& x : cloth.positions()) {
    if (!x.allFinite()) {
      state.SkipWithError("the cloth exploded");
      break;
    }
  }
  const double springs = static_cast<double>(cloth.counts().total());
  state.counters["springs"] = springs;
  state.counters["vertices"] = static_cast<double>(cloth.vertex_count());
  // Seconds per spring evaluation (printed with an SI prefix: "1.5n" is 1.5 ns).
  state.counters["s_per_spring"] =
      benchmark::Counter(4 * springs * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_CAPTURE(BM_ReferenceRk4Step, quads, GridKind::Quad)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, triangles, GridKind::Tri)->Arg(10)->Arg(100);
BENCHMARK_CAPTURE(BM_ReferenceRk4Step, mixed, GridKind::Mix)->Arg(10)->Arg(100);

BENCHMARK_MAIN();
