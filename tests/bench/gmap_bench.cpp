// Building a quad grid as a 2D G-map and sweeping every vertex orbit, in rift
// and in CGAL's Generalized_map<2>, side by side. See docs/performance.md for
// the command and the figures.
//
// Every benchmark takes the grid's side n (n x n quads, 8 n^2 darts). Counters:
//   darts          darts in the map
//   map_MB         heap bytes the finished map holds (mesh lists freed)
//   build_heap_MB  heap bytes held right after building, mesh lists included
//   bytes_per_dart map_MB / darts
//   peak_rss_MB    the process's peak resident set so far (run one benchmark
//                  per process, with --benchmark_filter, for a clean figure)
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <sys/resource.h>

#include <CGAL/Cell_attribute.h>
#include <CGAL/Generalized_map.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"

namespace {

// ---- memory probes --------------------------------------------------------------

std::size_t heap_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

constexpr double kMB = 1024.0 * 1024.0;

rift::MeshData quad_grid(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  return rift::make_grid(rift::GridKind::Quad, n, n);
}

/// Builds once outside the timed loop to measure what the map holds.
template <class Build, class Size>
void report_memory(benchmark::State& state, Build&& build, Size&& size) {
  const std::size_t before = heap_in_use();
  std::size_t with_mesh = 0;
  auto map = [&] {
    rift::MeshData mesh = quad_grid(state);
    auto built = build(mesh);
    with_mesh = heap_in_use();
    return built;
  }();
  const std::size_t held = heap_in_use() - before;
  const double darts = static_cast<double>(size(*map));
  state.counters["darts"] = darts;
  state.counters["map_MB"] = static_cast<double>(held) / kMB;
  state.counters["build_heap_MB"] = static_cast<double>(with_mesh - before) / kMB;
  state.counters["bytes_per_dart"] = static_cast<double>(held) / darts;
}

// ---- rift -----------------------------------------------------------------------

std::unique_ptr<rift::GMap> rift_build(const rift::MeshData& mesh) {
  return std::make_unique<rift::GMap>(rift::assemble_gmap(mesh));
}

double rift_sweep(const rift::GMap& map) {
  const rift::Embedding<rift::Vec3> position = map.embedding<rift::Vec3>("position");
  double sum = 0;
  map.for_each_cell(rift::vertex_orbit(2), [&](rift::Dart d) { sum += position[d].x(); });
  return sum;
}

std::size_t rift_size(const rift::GMap& map) {
  return map.size();
}

// ---- CGAL -----------------------------------------------------------------------

// Topology only; each dart keeps its vertex id (what rift's point_index holds).
struct BareItems {
  template <class Map>
  struct Dart_wrapper {
    using Dart_info = std::uint32_t;
    using Attributes = std::tuple<>;
  };
};

// Vertex attributes holding the position: the counterpart of rift's
// "position" embedding on <1,2>.
struct PositionItems {
  template <class Map>
  struct Dart_wrapper {
    using Dart_info = std::uint32_t;
    using Vertex_attribute = CGAL::Cell_attribute<Map, std::array<double, 3>>;
    using Attributes = std::tuple<Vertex_attribute>;
  };
};

using BareMap = CGAL::Generalized_map<2, BareItems>;
using PositionMap = CGAL::Generalized_map<2, PositionItems>;

/// Builds the 2D G-map of polygon lists the way assemble_gmap does, with
/// CGAL's dart container: darts per polygon, 0- and 1-links, then edges matched
/// on their vertex ids (bucketed by smaller vertex) and 2-linked.
template <class Map>
std::unique_ptr<Map> cgal_build(const rift::MeshData& mesh) {
  using Dart = typename Map::Dart_handle;
  auto map = std::make_unique<Map>();
  Map& m = *map;
  std::size_t dart_count = 0;
  for (const rift::MeshElement& e : mesh.elements)
    dart_count += 2 * e.count;
  m.darts().reserve(dart_count);

  std::vector<Dart> darts;  // darts[2k] and darts[2k+1]: the two darts of edge k
  darts.reserve(dart_count);
  for (const rift::MeshElement& e : mesh.elements) {
    const std::uint32_t* v = mesh.vertices_of(e);
    const std::size_t first = darts.size();
    for (std::uint32_t i = 0; i < e.count; ++i) {
      const Dart d0 = m.create_dart();
      const Dart d1 = m.create_dart();
      m.info(d0) = v[i];
      m.info(d1) = v[(i + 1) % e.count];
      m.template basic_link_alpha<0>(d0, d1);
      darts.push_back(d0);
      darts.push_back(d1);
    }
    for (std::uint32_t i = 0; i < e.count; ++i) {
      m.template basic_link_alpha<1>(darts[first + 2 * i + 1],
                                     darts[first + 2 * ((i + 1) % e.count)]);
    }
  }

  // Counting sort of edges by their smaller vertex, then pairs within a bucket.
  const std::size_t edges = darts.size() / 2;
  auto low = [&](std::size_t k) {
    return std::min(m.info(darts[2 * k]), m.info(darts[2 * k + 1]));
  };
  auto high = [&](std::size_t k) {
    return std::max(m.info(darts[2 * k]), m.info(darts[2 * k + 1]));
  };
  std::vector<std::uint32_t> start(mesh.points.size() + 1, 0);
  for (std::size_t k = 0; k < edges; ++k)
    ++start[low(k) + 1];
  for (std::size_t p = 0; p < mesh.points.size(); ++p)
    start[p + 1] += start[p];
  std::vector<std::uint32_t> order(edges);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < edges; ++k)
      order[fill[low(k)]++] = static_cast<std::uint32_t>(k);
  }
  for (std::size_t p = 0; p < mesh.points.size(); ++p) {
    for (std::uint32_t a = start[p]; a < start[p + 1]; ++a) {
      const std::size_t ea = order[a];
      if (!m.template is_free<2>(darts[2 * ea])) continue;
      for (std::uint32_t b = a + 1; b < start[p + 1]; ++b) {
        const std::size_t eb = order[b];
        if (high(eb) != high(ea) || !m.template is_free<2>(darts[2 * eb])) continue;
        const bool same = m.info(darts[2 * ea]) == m.info(darts[2 * eb]);
        m.template basic_link_alpha<2>(darts[2 * ea], darts[2 * eb + (same ? 0 : 1)]);
        m.template basic_link_alpha<2>(darts[2 * ea + 1], darts[2 * eb + (same ? 1 : 0)]);
        break;
      }
    }
  }

  if constexpr (std::is_same_v<Map, PositionMap>) {
    for (auto it = m.template one_dart_per_cell<0>().begin(),
              end = m.template one_dart_per_cell<0>().end();
         it != end; ++it) {
      const rift::Vec3& p = mesh.points[m.info(it)];
      m.template set_attribute<0>(
          it, m.template create_attribute<0>(std::array<double, 3>{p.x(), p.y(), p.z()}));
    }
  }
  return map;
}

template <class Map>
double cgal_sweep(const Map& m) {
  double sum = 0;
  for (auto it = m.template one_dart_per_cell<0>().begin(),
            end = m.template one_dart_per_cell<0>().end();
       it != end; ++it) {
    if constexpr (std::is_same_v<Map, PositionMap>) {
      sum += m.template info<0>(it)[0];
    } else {
      sum += m.info(it);
    }
  }
  return sum;
}

template <class Map>
std::size_t cgal_size(const Map& m) {
  return m.number_of_darts();
}

// ---- benchmarks -----------------------------------------------------------------

template <class Build, class Sweep, class Size>
void build_and_sweep(benchmark::State& state, Build build, Sweep sweep, Size size) {
  report_memory(state, build, size);
  for (auto _ : state) {
    const rift::MeshData mesh = quad_grid(state);
    auto map = build(mesh);
    benchmark::DoNotOptimize(sweep(*map));
  }
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

template <class Build, class Size>
void build_only(benchmark::State& state, Build build, Size size) {
  report_memory(state, build, size);
  for (auto _ : state) {
    const rift::MeshData mesh = quad_grid(state);
    auto map = build(mesh);
    benchmark::DoNotOptimize(map.get());
  }
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

template <class Build, class Sweep>
void sweep_only(benchmark::State& state, Build build, Sweep sweep) {
  auto map = build(quad_grid(state));
  for (auto _ : state)
    benchmark::DoNotOptimize(sweep(*map));
  state.counters["vertices_per_s"] =
      benchmark::Counter(static_cast<double>((state.range(0) + 1) * (state.range(0) + 1)),
                         benchmark::Counter::kIsIterationInvariantRate);
}

void BM_MakeGridOnly(benchmark::State& state) {
  for (auto _ : state) {
    const rift::MeshData mesh = quad_grid(state);
    benchmark::DoNotOptimize(mesh.elements.data());
  }
}

void BM_Rift_Build(benchmark::State& state) {
  build_only(state, rift_build, [](const rift::GMap& m) { return rift_size(m); });
}
void BM_Rift_BuildSweep(benchmark::State& state) {
  build_and_sweep(state, rift_build, rift_sweep, [](const rift::GMap& m) { return rift_size(m); });
}
void BM_Rift_Sweep(benchmark::State& state) {
  sweep_only(state, rift_build, rift_sweep);
}

void BM_CgalBare_Build(benchmark::State& state) {
  build_only(state, cgal_build<BareMap>, cgal_size<BareMap>);
}
void BM_CgalBare_BuildSweep(benchmark::State& state) {
  build_and_sweep(state, cgal_build<BareMap>, cgal_sweep<BareMap>, cgal_size<BareMap>);
}
void BM_CgalBare_Sweep(benchmark::State& state) {
  sweep_only(state, cgal_build<BareMap>, cgal_sweep<BareMap>);
}

void BM_CgalPosition_Build(benchmark::State& state) {
  build_only(state, cgal_build<PositionMap>, cgal_size<PositionMap>);
}
void BM_CgalPosition_BuildSweep(benchmark::State& state) {
  build_and_sweep(state, cgal_build<PositionMap>, cgal_sweep<PositionMap>, cgal_size<PositionMap>);
}
void BM_CgalPosition_Sweep(benchmark::State& state) {
  sweep_only(state, cgal_build<PositionMap>, cgal_sweep<PositionMap>);
}

#define RIFT_GRID_BENCHMARK(fn) \
  BENCHMARK(fn)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime()

RIFT_GRID_BENCHMARK(BM_MakeGridOnly);
RIFT_GRID_BENCHMARK(BM_Rift_Build);
RIFT_GRID_BENCHMARK(BM_CgalBare_Build);
RIFT_GRID_BENCHMARK(BM_CgalPosition_Build);
RIFT_GRID_BENCHMARK(BM_Rift_BuildSweep);
RIFT_GRID_BENCHMARK(BM_CgalBare_BuildSweep);
RIFT_GRID_BENCHMARK(BM_CgalPosition_BuildSweep);
RIFT_GRID_BENCHMARK(BM_Rift_Sweep);
RIFT_GRID_BENCHMARK(BM_CgalBare_Sweep);
RIFT_GRID_BENCHMARK(BM_CgalPosition_Sweep);

// One polygon of N vertices: assembly must cost the same per dart as a grid
// (it was quadratic in the polygon's size: 12 s for `rift info` at 300,000).
// Compare the "time_per_dart" counter across sizes and with BM_Rift_Build.
void BM_Rift_BuildOnePolygon(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  rift::MeshData mesh;
  std::vector<std::uint32_t> ids(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    const double a = 2 * 3.141592653589793 * k / n;
    mesh.points.emplace_back(std::cos(a), std::sin(a), 0);
    ids[k] = k;
  }
  mesh.add_element(rift::ElementType::Polygon, ids.begin(), ids.end());
  for (auto _ : state)
    benchmark::DoNotOptimize(rift_build(mesh));
  state.counters["time_per_dart"] = benchmark::Counter(
      2.0 * n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Rift_BuildOnePolygon)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(300'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A block of n^3 hexahedra (48 darts each; its vertices are three-link
// orbits): the solids' share of the set-up of a 10^6-vertex block
// (`block:hex:99x99x99`, 4.7·10^7 darts). The mesh is made outside the timing.
void BM_Rift_BuildHexBlock(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const rift::MeshData mesh = rift::make_block(rift::BlockKind::Hex, n, n, n);
  for (auto _ : state)
    benchmark::DoNotOptimize(rift_build(mesh));
  state.counters["time_per_dart"] =
      benchmark::Counter(48.0 * n * n * n, benchmark::Counter::kIsIterationInvariantRate |
                                               benchmark::Counter::kInvert);
}
BENCHMARK(BM_Rift_BuildHexBlock)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
