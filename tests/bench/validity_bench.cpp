// The cost of `rift run --check` per rewrite on the paper's cloth at 100 x 100
// quads (about 80,000 darts and the embeddings of a running simulation):
//   BM_CheckValidity        GMap::check_validity, the full check as it runs;
//   BM_CheckValidityStrings the check as it was before issue 13 (a std::string
//                           built per dart per embedding), kept here only as
//                           the baseline of the ratio;
//   BM_TornStep             one step of the same cloth tearing, for scale.
// Run: build/release/tests/bench/rift_bench_validity (docs/performance.md).
#include <benchmark/benchmark.h>

#include "../physics/physics_setup.hpp"
#include "../reference/paper_cloth.hpp"

namespace {

using rift::Dart;
using rift::GMap;
using rift::Slot;

std::unique_ptr<rift::Simulation> cloth(int n, bool tearing) {
  using namespace rift::physics_test;
  const rift::MeshData mesh = rift::reference::hanging_grid(rift::GridKind::Quad, n, n);
  SimSetup setup;
  setup.settings.integrator = rift::IntegratorKind::kRK4;
  setup.settings.dt = rift::reference::kPaperDt * (10.0 / n) * (10.0 / n);
  setup.interactions = paper_cloth_springs();
  if (tearing) setup.criteria = {Use{"atomic_edge", {{"threshold", 0.002}}}};
  setup.prepare = [&](rift::Simulation& sim) {
    sim.set_total_mass(0.1);
    const rift::Vec3 left = mesh.points[rift::reference::grid_point(n, 0, n)];
    const rift::Vec3 right = mesh.points[rift::reference::grid_point(n, n, n)];
    sim.pin_where(
        [&](const rift::Vec3& x) { return (x - left).norm() < 1e-9 || (x - right).norm() < 1e-9; });
  };
  return simulate(rift::assemble_gmap(mesh), setup);
}

// The pre-issue-13 algorithm, verbatim in substance: the baseline only.
std::vector<std::string> check_with_strings(const GMap& g, std::size_t limit) {
  std::vector<std::string> problems;
  auto report = [&](std::string msg) {
    if (problems.size() < limit) problems.push_back(std::move(msg));
  };
  const std::size_t n = g.capacity();
  const int dim = g.dimension();
  for (std::size_t k = 0; k < n && problems.size() < limit; ++k) {
    const Dart d = static_cast<Dart>(k);
    if (!g.is_alive(d)) continue;
    for (int i = 0; i <= dim; ++i) {
      const Dart e = g.alpha(d, i);
      if (!g.is_alive(e)) {
        report("alpha_" + std::to_string(i) + " is not a live dart");
      } else if (g.alpha(e, i) != d) {
        report("alpha_" + std::to_string(i) + " is not an involution at dart " + std::to_string(d));
      }
    }
    for (int i = 0; i + 2 <= dim; ++i) {
      for (int j = i + 2; j <= dim; ++j) {
        if (g.alpha(g.alpha(g.alpha(g.alpha(d, i), j), i), j) != d) report("composition");
      }
    }
  }
  for (const auto& att : g.attachments()) {
    if (att->dormant()) continue;  // no slots (attachment.hpp)
    const rift::Orbit o = att->orbit();
    std::vector<std::uint32_t> count(att->slot_capacity(), 0);
    for (std::size_t k = 0; k < n && problems.size() < limit; ++k) {
      const Dart d = static_cast<Dart>(k);
      if (!g.is_alive(d)) continue;
      const Slot s = att->slot(d);
      const std::string emb = "embedding on " + o.str();
      if (s == rift::kNoSlot || s >= att->slot_capacity()) {
        report(emb + ": dart " + std::to_string(d) + " has no value");
        continue;
      }
      ++count[s];
      for (int i = 0; i <= dim; ++i) {
        if (o.contains(i) && att->slot(g.alpha(d, i)) != s) report(emb + ": different values");
      }
    }
    for (Slot s = 0; s < count.size() && problems.size() < limit; ++s) {
      if (count[s] != att->darts_in_slot(s)) report("count");
    }
  }
  for (const auto& att : g.attachments()) {
    if (att->dormant()) continue;  // no slots (attachment.hpp)
    const rift::Orbit o = att->orbit();
    std::vector<std::uint8_t> seen(att->slot_capacity(), 0);
    g.for_each_cell(o, [&](Dart d) {
      const Slot s = att->slot(d);
      if (s == rift::kNoSlot || s >= seen.size()) return;
      if (seen[s]) report("shared slot");
      seen[s] = 1;
    });
  }
  return problems;
}

void report_darts(benchmark::State& state, const GMap& g) {
  state.counters["darts"] = static_cast<double>(g.size());
  state.counters["embeddings"] = static_cast<double>(g.attachments().size());
}

void BM_CheckValidity(benchmark::State& state) {
  auto sim = cloth(static_cast<int>(state.range(0)), false);
  sim->step();
  for (auto _ : state) {
    auto problems = sim->map().check_validity(5);
    if (!problems.empty()) state.SkipWithError(problems.front().c_str());
    benchmark::DoNotOptimize(problems);
  }
  report_darts(state, sim->map());
}

void BM_CheckValidityStrings(benchmark::State& state) {
  auto sim = cloth(static_cast<int>(state.range(0)), false);
  sim->step();
  for (auto _ : state) {
    auto problems = check_with_strings(sim->map(), 5);
    if (!problems.empty()) state.SkipWithError(problems.front().c_str());
    benchmark::DoNotOptimize(problems);
  }
  report_darts(state, sim->map());
}

void BM_TornStep(benchmark::State& state) {
  auto sim = cloth(static_cast<int>(state.range(0)), true);
  for (auto _ : state) {
    sim->step();
    benchmark::DoNotOptimize(sim->position().values().data());
  }
  state.counters["tears"] = static_cast<double>(sim->tears());
  report_darts(state, sim->map());
}

}  // namespace

BENCHMARK(BM_CheckValidity)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckValidityStrings)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TornStep)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(20);

BENCHMARK_MAIN();
