// The co-rotational tetrahedron (issue 12, row "per element evaluation"):
//  - BM_Polar: the rotation alone, Jacobi SVD (the kernels' old rotation)
//    against rift::polar_rotation, on nearly rigid deformation gradients;
//  - BM_CorotationalElement: one element's whole evaluation (F, R, strain,
//    stress, four forces gathered and scattered over flat arrays), written
//    like the generated kernel, with either rotation;
//  - BM_GeneratedCorotational: the generated fem3d pack's force pass on a
//    deformed block, per element.
// Counter s_per_element = CPU time / elements. docs/performance.md has the command.
#include <benchmark/benchmark.h>

#include <random>

#include "../physics/physics_setup.hpp"
#include "rift/core/polar.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"

namespace {

using rift::Mat3;
using rift::Real;
using rift::Vec3;

enum class PolarKind { kSvd, kQuaternion };

Mat3 rotation_of(PolarKind kind, const Mat3& f) {
  return kind == PolarKind::kSvd ? rift::polar_rotation_svd(f) : rift::polar_rotation(f);
}

/// Nearly rigid deformation gradients: a random rotation times I + 5 % noise.
std::vector<Mat3> sample_gradients(std::size_t n) {
  std::mt19937 rng(3);
  std::normal_distribution<Real> g(0, 1);
  std::uniform_real_distribution<Real> u(-0.05, 0.05);
  std::vector<Mat3> out(n);
  for (Mat3& f : out) {
    Eigen::Quaternion<Real> q(g(rng), g(rng), g(rng), g(rng));
    q.normalize();
    Mat3 e;
    for (int i = 0; i < 9; ++i)
      e(i) = u(rng);
    f = q.toRotationMatrix() * (Mat3::Identity() + e);
  }
  return out;
}

void BM_Polar(benchmark::State& state, PolarKind kind) {
  const std::vector<Mat3> fs = sample_gradients(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    Mat3 r = rotation_of(kind, fs[i++ & 1023]);
    benchmark::DoNotOptimize(r);
  }
  state.counters["s_per_element"] =
      benchmark::Counter(static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

/// Flat arrays of a random tetrahedral mesh-like set: four vertex indices,
/// B = D_m⁻¹, volume, μ and λ per element.
struct TetSet {
  std::vector<std::array<std::uint32_t, 4>> tets;
  std::vector<Mat3> b;
  std::vector<Real> volume, mu, lambda;
  std::vector<Vec3> x, v, f;
};

TetSet make_tets(std::size_t elements) {
  const rift::MeshData mesh = rift::make_block(rift::BlockKind::Tet, 10, 10, 10);
  TetSet s;
  s.x = mesh.points;
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(-0.003, 0.003);
  const Mat3 rot = Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (Vec3& p : s.x)
    p = rot * p + Vec3(u(rng), u(rng), u(rng));
  s.v.assign(s.x.size(), Vec3(0.01, 0, 0));
  s.f.assign(s.x.size(), Vec3::Zero());
  for (std::size_t e = 0; e < elements; ++e) {
    const rift::MeshElement& c = mesh.elements[e % mesh.elements.size()];
    const std::uint32_t* vs = mesh.element_vertices.data() + c.first;
    s.tets.push_back({vs[0], vs[1], vs[2], vs[3]});
    const Vec3 x0 = mesh.points[vs[0]];
    Mat3 dm;
    dm << mesh.points[vs[1]] - x0, mesh.points[vs[2]] - x0, mesh.points[vs[3]] - x0;
    s.b.push_back(dm.inverse());
    s.volume.push_back(std::abs(dm.determinant()) / 6);
    s.mu.push_back(1e5 / 2.6);
    s.lambda.push_back(1e5 * 0.3 / (1.3 * 0.4));
  }
  return s;
}

void BM_CorotationalElement(benchmark::State& state, PolarKind kind) {
  TetSet s = make_tets(6000);
  const Real damping = 0.01;
  for (auto _ : state) {
    for (std::size_t e = 0; e < s.tets.size(); ++e) {
      const auto& t = s.tets[e];
      const Vec3 x0 = s.x[t[0]], v0 = s.v[t[0]];
      Mat3 ds, dv;
      ds << s.x[t[1]] - x0, s.x[t[2]] - x0, s.x[t[3]] - x0;
      dv << s.v[t[1]] - v0, s.v[t[2]] - v0, s.v[t[3]] - v0;
      const Mat3 f = ds * s.b[e];
      const Mat3 r = rotation_of(kind, f);
      const Mat3 rf = r.transpose() * f;
      const Mat3 rv = r.transpose() * dv * s.b[e];
      const Mat3 strain = 0.5 * (rf + rf.transpose()) - Mat3::Identity();
      const Mat3 eps = strain + (0.5 * damping) * (rv + rv.transpose());
      const Mat3 stress = (s.lambda[e] * eps.trace()) * Mat3::Identity() + (2 * s.mu[e]) * eps;
      const Mat3 h = -s.volume[e] * (r * stress * s.b[e].transpose());
      s.f[t[0]] -= h.col(0) + h.col(1) + h.col(2);
      s.f[t[1]] += h.col(0);
      s.f[t[2]] += h.col(1);
      s.f[t[3]] += h.col(2);
    }
    benchmark::DoNotOptimize(s.f.data());
    benchmark::ClobberMemory();
  }
  state.counters["s_per_element"] =
      benchmark::Counter(static_cast<double>(state.iterations() * s.tets.size()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_GeneratedCorotational(benchmark::State& state) {
  using namespace rift::physics_test;
  const int n = static_cast<int>(state.range(0));
  SimSetup setup;
  setup.interactions = {{"corotational", {{"young", 1e5}, {"poisson", 0.3}, {"damping", 0.01}}}};
  auto sim = simulate(rift::assemble_gmap(rift::make_block(rift::BlockKind::Tet, n, n, n)), setup);
  const Mat3 rot = Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(-0.003, 0.003);
  move_vertices(*sim, [&](const Vec3& p) { return Vec3(rot * p + Vec3(u(rng), u(rng), u(rng))); });
  const auto& x = sim->position().values();
  const auto& v = sim->velocity().values();
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  rift::ForceModel& model = *sim->force_models()[0];
  for (auto _ : state) {
    model.add_forces({x.data(), v.data()}, f.data(), false);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  state.counters["elements"] = static_cast<double>(model.active_matches());
  state.counters["s_per_element"] =
      benchmark::Counter(static_cast<double>(state.iterations() * model.active_matches()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_CAPTURE(BM_Polar, svd, PolarKind::kSvd);
BENCHMARK_CAPTURE(BM_Polar, quaternion, PolarKind::kQuaternion);
BENCHMARK_CAPTURE(BM_CorotationalElement, svd, PolarKind::kSvd);
BENCHMARK_CAPTURE(BM_CorotationalElement, quaternion, PolarKind::kQuaternion);
BENCHMARK(BM_GeneratedCorotational)->Arg(10);

BENCHMARK_MAIN();
