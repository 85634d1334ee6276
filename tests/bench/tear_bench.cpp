// One tear as the loop pays it (issue 12, row "one tear at 1000x1000 vs
// 10x10"): the criterion's rewrite (a spring split, both extremities), then
// Simulation::on_topology_changed (masses of the touched vertices, inverse
// masses, re-match of every interaction around them). The first tears on a
// big map also pay the doubling of its dart arrays (amortised growth). Candidates are
// collected once at set-up on a stretched cloth; each iteration applies the
// next one. The time is the thread's CPU time of those two calls only
// (manual time), so set-up and rebuilds when the candidates run out do not
// count. A tear should cost what it touches: the same at 10x10 and 1000x1000.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>

#include "../physics/physics_setup.hpp"
#include "../reference/paper_cloth.hpp"
#include "rift/gmap/cell_list.hpp"

namespace {

using rift::Real;
using rift::Vec3;

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Minor page faults of this thread so far: memory a tear touches for the
// first time (new darts, slots and matches growing into reserved pages).
long thread_minor_faults() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return u.ru_minflt;
}

struct TearingCloth {
  std::unique_ptr<rift::Simulation> sim;
  std::vector<rift::TearCandidate> candidates;
  std::size_t next = 0;
};

TearingCloth stretched_cloth(rift::GridKind kind, int n) {
  using namespace rift::physics_test;
  SimSetup setup;
  setup.interactions = paper_cloth_springs();
  setup.criteria = {{"spring_split", {{"threshold", 1e-9}}}};
  // As a scene's set-up (and rift run) makes them: only the forces a
  // criterion reads are stored, here the stretch springs' (spring_split
  // reads f_stretch). With every interaction storing, each tear also reset
  // the bending and shear springs' stored forces, which no loop pays.
  setup.lean_forces = true;
  TearingCloth c;
  c.sim = simulate(rift::assemble_gmap(rift::reference::hanging_grid(kind, n, n)), setup);
  move_vertices(*c.sim, [](const Vec3& p) { return Vec3(1.1 * p.x(), 1.05 * p.y(), p.z()); });
  const auto& x = c.sim->position().values();
  const auto& v = c.sim->velocity().values();
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  for (const auto& m : c.sim->force_models())
    m->add_forces({x.data(), v.data()}, f.data(), true);
  c.sim->criteria()[0]->collect(c.sim->map(), c.candidates);
  // Spread the tears over the cloth rather than along the dart order.
  std::vector<rift::TearCandidate> spread;
  for (std::size_t k = 0; k < c.candidates.size(); ++k)
    spread.push_back(c.candidates[(k * 7919) % c.candidates.size()]);
  c.candidates = std::move(spread);
  return c;
}

// Whether every face around the vertex of d has a neighbour across each of
// its edges at that vertex: an inner vertex of an untorn cloth.
bool inner_vertex(const rift::GMap& g, rift::Dart d) {
  bool inner = true;
  g.for_each_in_orbit(d, rift::Orbit{1, 2},
                      [&](rift::Dart x) { inner = inner && !g.is_free(x, 2); });
  return inner;
}

// Marks the vertex slots within `rings` rings of faces around the vertex of d.
void mark_rings(const rift::GMap& g, const rift::Embedding<Vec3>& position, rift::Dart d, int rings,
                std::vector<char>& marked) {
  std::vector<rift::Dart> frontier{d}, next;
  for (int r = 0; r < rings; ++r) {
    next.clear();
    for (rift::Dart v : frontier) {
      g.for_each_in_orbit(v, rift::Orbit{1, 2}, [&](rift::Dart x) {
        g.for_each_in_orbit(x, rift::Orbit{0, 1}, [&](rift::Dart y) {
          char& m = marked[position.slot(y)];
          if (!m) next.push_back(y);
          m = 1;
        });
      });
    }
    frontier.swap(next);
  }
}

// The candidates of an untorn stretched cloth that split a spring between
// two inner vertices, each two rings of faces away from every other one
// kept: each such tear rewrites the same neighbourhood (the same darts, the
// same matches around them) whatever the cloth's size.
TearingCloth inner_tears(rift::GridKind kind, int n) {
  TearingCloth c = stretched_cloth(kind, n);
  const rift::GMap& g = c.sim->map();
  const auto& position = c.sim->position();
  std::vector<char> taken(g.capacity(), 0);
  std::vector<rift::TearCandidate> kept;
  for (const rift::TearCandidate& cand : c.candidates) {
    const rift::Dart a = cand.at, b = g.alpha(cand.at, 0);
    if (taken[position.slot(a)] || taken[position.slot(b)]) continue;
    if (!inner_vertex(g, a) || !inner_vertex(g, b)) continue;
    mark_rings(g, position, a, 3, taken);
    mark_rings(g, position, b, 3, taken);
    kept.push_back(cand);
  }
  c.candidates = std::move(kept);
  return c;
}

// Profiling the tears alone (docs/performance.md, "Profiling one tear"):
// with RIFT_PERF_CTL naming the control FIFO of `perf record -D -1
// --control=fifo:...`, sampling is on only while the loop below tears, not
// while cloths are built (a 10^6-vertex build takes seconds, 4000 tears a
// fifth of one).
void profile_tears(bool on) {
  static FILE* const kControl = [] {
    const char* path = std::getenv("RIFT_PERF_CTL");
    return path ? std::fopen(path, "w") : nullptr;
  }();
  if (!kControl) return;
  std::fputs(on ? "enable\n" : "disable\n", kControl);
  std::fflush(kControl);
}

void BM_OneTear(benchmark::State& state, rift::GridKind kind, bool inner) {
  const int n = static_cast<int>(state.range(0));
  const auto make = [&] { return inner ? inner_tears(kind, n) : stretched_cloth(kind, n); };
  // Google Benchmark calls this several times; a 10^6-vertex set-up is
  // built once per size and kind of tear, and reused (later calls tear
  // further candidates).
  static std::map<std::pair<int, bool>, TearingCloth> cloths;
  const std::pair<int, bool> key{n, inner};
  if (!cloths.count(key)) cloths.emplace(key, make());
  TearingCloth& c = cloths.at(key);
  std::vector<rift::Dart> touched;
  std::size_t tears = 0;
  std::size_t touched_darts = 0;
  double total_spent = 0;
  long faults = 0;
  double faulting_spent = 0;
  std::size_t faulting_tears = 0;
  profile_tears(true);
  for (auto _ : state) {
    double spent = 0;
    for (;;) {
      if (c.next == c.candidates.size()) {
        profile_tears(false);
        c = make();
        profile_tears(true);
      }
      const rift::TearCandidate& cand = c.candidates[c.next++];
      if (!c.sim->map().is_alive(cand.at)) continue;
      touched.clear();
      const long f0 = thread_minor_faults();
      const double t0 = thread_seconds();
      const bool applied = c.sim->criteria()[0]->apply(c.sim->map(), cand, touched);
      if (applied) c.sim->on_topology_changed(touched);
      const double dt = thread_seconds() - t0;
      const long df = thread_minor_faults() - f0;
      spent += dt;
      faults += df;
      if (df > 0) {
        faulting_spent += dt;
        ++faulting_tears;
      }
      if (applied) touched_darts += touched.size();
      if (applied) break;
    }
    ++tears;
    total_spent += spent;
    state.SetIterationTime(spent);
  }
  profile_tears(false);
  state.counters["vertices"] = static_cast<double>(c.sim->map().count_cells(rift::Orbit{1, 2}));
  // How many darts a tear rewrites, on average: its work, which should not
  // depend on the cloth's size (46 at 10x10, 42 at 1000x1000 in one run), so
  // that what differs between sizes is where that work lands in memory.
  state.counters["touched_darts"] =
      static_cast<double>(touched_darts) / static_cast<double>(std::max<std::size_t>(tears, 1));
  // Minor page faults per tear, the share of tears that took any and the
  // share of the time those tears took: whether a big map's tear pays for
  // memory touched the first time (0.05-0.09 faults a tear at 1000x1000,
  // 4-6 % of the time, in the runs of docs/performance.md) or for misses.
  state.counters["faults_per_tear"] =
      static_cast<double>(faults) / static_cast<double>(std::max<std::size_t>(tears, 1));
  state.counters["faulting_tears_share"] =
      static_cast<double>(faulting_tears) / static_cast<double>(std::max<std::size_t>(tears, 1));
  state.counters["faulting_time_share"] = faulting_spent / std::max(total_spent, 1e-300);
  // The big cloth's tears are drawn from one cloth torn further and further
  // (its later tears touch 40 to 70 darts, against 46 on the small cloths,
  // rebuilt when their candidates run out): the time per touched dart
  // compares the sizes at equal work.
  state.counters["ns_per_touched_dart"] =
      1e9 * total_spent / static_cast<double>(std::max<std::size_t>(touched_darts, 1));
}

}  // namespace

// A fixed number of tears per run: the big cloth is torn further run after
// run (its later tears touch more darts, 45 to 72 a tear in runs of 0.5 s
// whose tear counts followed the machine's speed), so with a count of its
// own each binary and each run of a binary tears the same candidates, in the
// same order, and two binaries compare at equal work.
// RIFT_TEAR_ITERS sets another count (a profile wants more tears: 20000 inner
// tears fit in one 10^6-vertex cloth).
static void tear_runs(benchmark::internal::Benchmark* b) {
  const char* count = std::getenv("RIFT_TEAR_ITERS");
  char* end = nullptr;
  long tears = count ? std::strtol(count, &end, 10) : 4000;
  if (count && (*end != '\0' || tears <= 0)) {
    std::fprintf(stderr, "RIFT_TEAR_ITERS=%s is not a positive count: 4000 tears\n", count);
    tears = 4000;
  }
  b->Arg(10)->Arg(100)->Arg(1000)->Iterations(tears)->UseManualTime()->Unit(
      benchmark::kMicrosecond);
}
BENCHMARK_CAPTURE(BM_OneTear, quads, rift::GridKind::Quad, false)->Apply(tear_runs);
// The same tear at every size: a spring between two inner vertices of an
// untorn part of the cloth (inner_tears). The tears above draw any spring, and
// the small cloth's are mostly at its border or next to earlier tears (46
// darts a tear at 10x10 against 72 at 1000x1000): this one compares the
// sizes at equal work, tear for tear.
BENCHMARK_CAPTURE(BM_OneTear, quads_inner, rift::GridKind::Quad, true)->Apply(tear_runs);

BENCHMARK_MAIN();

// What a criterion's cells cost after a tear (issue 12, "a tear costs what it
// touches"): the cells of one orbit type as CellList keeps them, brought up
// to date after each tear of the cloth, either by following the touched darts
// (note_changed, what Simulation::on_topology_changed now does) or by
// listing them anew from the whole map (what every tearing step did before).
// <0> has a slotted attachment (for_each_cell's fast path); <0,2> (the edge
// criteria's orbit) and <1,2> (the vertices') are walked with marks.
void BM_CellsAfterTear(benchmark::State& state, rift::Orbit orbit, bool follow) {
  const int n = static_cast<int>(state.range(0));
  static std::map<int, TearingCloth> cloths;
  if (!cloths.count(n)) cloths.emplace(n, inner_tears(rift::GridKind::Quad, n));
  TearingCloth& c = cloths.at(n);
  rift::CellList cells;
  cells.of(c.sim->map(), orbit);
  std::vector<rift::Dart> touched;
  std::uint64_t from = 0;
  for (auto _ : state) {
    for (;;) {
      if (c.next == c.candidates.size()) {
        c = inner_tears(rift::GridKind::Quad, n);
        cells.of(c.sim->map(), orbit);
      }
      const rift::TearCandidate& cand = c.candidates[c.next++];
      if (!c.sim->map().is_alive(cand.at)) continue;
      touched.clear();
      from = c.sim->map().topology_version();
      if (!c.sim->criteria()[0]->apply(c.sim->map(), cand, touched)) continue;
      c.sim->on_topology_changed(touched);
      break;
    }
    const double t0 = thread_seconds();
    if (follow) cells.note_changed(c.sim->map(), touched, from);
    benchmark::DoNotOptimize(cells.of(c.sim->map(), orbit).size());
    state.SetIterationTime(thread_seconds() - t0);
  }
  state.counters["cells"] = static_cast<double>(cells.of(c.sim->map(), orbit).size());
  state.counters["rebuilds"] = static_cast<double>(cells.rebuilds());
}

static void cells_runs(benchmark::internal::Benchmark* b) {
  b->Arg(100)->Arg(1000)->Iterations(400)->UseManualTime()->Unit(benchmark::kMicrosecond);
}
BENCHMARK_CAPTURE(BM_CellsAfterTear, edges_followed, rift::Orbit{0}, true)->Apply(cells_runs);
BENCHMARK_CAPTURE(BM_CellsAfterTear, edges_rebuilt, rift::Orbit{0}, false)->Apply(cells_runs);
BENCHMARK_CAPTURE(BM_CellsAfterTear, edge_pairs_followed, rift::Orbit{0, 2}, true)
    ->Apply(cells_runs);
BENCHMARK_CAPTURE(BM_CellsAfterTear, edge_pairs_rebuilt, rift::Orbit{0, 2}, false)
    ->Apply(cells_runs);
BENCHMARK_CAPTURE(BM_CellsAfterTear, vertices_followed, rift::Orbit{1, 2}, true)->Apply(cells_runs);
BENCHMARK_CAPTURE(BM_CellsAfterTear, vertices_rebuilt, rift::Orbit{1, 2}, false)->Apply(cells_runs);
