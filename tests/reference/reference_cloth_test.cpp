// The reference cloth: spring counts in closed form and against the G-map's
// support orbits, masses, conservation laws, rest under gravity, scaling, and
// the runtime's simulation loop driven by the same springs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include "gmap_cloth_model.hpp"
#include "paper_cloth.hpp"
#include "reference_cloth.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/sim/simulation.hpp"

namespace rift::reference {
namespace {

const Vec3 kNoGravity = Vec3::Zero();

ClothParameters without_gravity(ClothParameters p = {}) {
  p.gravity = kNoGravity;
  return p;
}

// Number of quads of grid:mix:NxM that are split into two triangles.
std::size_t mix_split_count(std::size_t n, std::size_t m) {
  return (n * m + (n % 2) * (m % 2)) / 2;
}

// ---- spring counts -----------------------------------------------------------------

class GridSizes : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(GridSizes, QuadCountsMatchTheClosedForm) {
  const auto [nx, ny] = GetParam();
  const std::size_t n = nx, m = ny;
  const ReferenceCloth cloth(make_grid(GridKind::Quad, nx, ny), {});
  // 4 half-edges per quad; 2 diagonals per quad; 2 extremities per interior edge,
  // and a grid has 2NM - N - M interior edges.
  EXPECT_EQ(cloth.counts().stretch, 4 * n * m);
  EXPECT_EQ(cloth.counts().shear, 2 * n * m);
  EXPECT_EQ(cloth.counts().bend, 2 * (2 * n * m - n - m));
  EXPECT_EQ(cloth.vertex_count(), (n + 1) * (m + 1));
}

TEST_P(GridSizes, TriangleAndMixCountsMatchTheClosedForm) {
  const auto [nx, ny] = GetParam();
  const std::size_t n = nx, m = ny;
  const ReferenceCloth tri(make_grid(GridKind::Tri, nx, ny), {});
  EXPECT_EQ(tri.counts().stretch, 6 * n * m);
  EXPECT_EQ(tri.counts().shear, 0u);
  EXPECT_EQ(tri.counts().bend, 2 * (3 * n * m - n - m));  // diagonals are interior too

  const std::size_t split = mix_split_count(n, m);
  const ReferenceCloth mix(make_grid(GridKind::Mix, nx, ny), {});
  EXPECT_EQ(mix.counts().stretch, 4 * (n * m - split) + 6 * split);
  EXPECT_EQ(mix.counts().shear, 2 * (n * m - split));
  EXPECT_EQ(mix.counts().bend, 2 * (2 * n * m - n - m + split));
}

INSTANTIATE_TEST_SUITE_P(Grids, GridSizes,
                         ::testing::Values(std::pair{1, 1}, std::pair{1, 4}, std::pair{3, 2},
                                           std::pair{10, 10}, std::pair{7, 13}));

TEST(SpringCounts, PaperCloth) {
  const ReferenceCloth cloth(make_grid(GridKind::Quad, 10, 10), {});
  EXPECT_EQ(cloth.counts().stretch, 400u);
  EXPECT_EQ(cloth.counts().shear, 200u);
  EXPECT_EQ(cloth.counts().bend, 360u);
}

// One spring per vertex pair, in closed form on an n x n grid: quads 2n(n+1)
// edges + 2n^2 diagonals + 2(n+1)(n-1) bending pairs (two edges of a vertex
// place the same bending spring across it), 618 at n = 10 as the paper's §7
// counts, against 960 atomic; triangles 3n^2 + 2n edges + one bending pair
// per interior edge (both its ends place the same one), 3n^2 - 2n.
TEST(SpringCounts, CumulatedClothHasOneSpringPerVertexPair) {
  for (const auto& [kind, n, expected] :
       {std::tuple{GridKind::Quad, 10, 618}, std::tuple{GridKind::Tri, 10, 600},
        std::tuple{GridKind::Quad, 7, 2 * 7 * 8 + 2 * 49 + 2 * 8 * 6},
        std::tuple{GridKind::Tri, 7, 3 * 49 + 2 * 7 + 3 * 49 - 2 * 7}}) {
    ReferenceCloth cloth(make_grid(kind, n, n), {});
    const std::size_t atomic = cloth.springs().size();
    cloth.cumulate_springs();
    EXPECT_EQ(cloth.springs().size(), static_cast<std::size_t>(expected)) << "n = " << n;
    EXPECT_LT(cloth.springs().size(), atomic);
    EXPECT_EQ(cloth.counts().total(), atomic);  // the atomic counts are kept
  }
}

// Cumulating changes only the rounding of each vertex's force sum: the same
// hanging cloth, atomic and cumulated, stays together over a second of motion.
TEST(RuntimeLoop, CumulatedSpringsFollowTheAtomicCloth) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    ReferenceCloth atomic = paper_cloth(kind, 8, 8);
    ReferenceCloth cumulated = paper_cloth(kind, 8, 8);
    cumulated.cumulate_springs();
    ASSERT_LT(cumulated.springs().size(), atomic.springs().size());
    Real deviation = 0, travel = 0;
    const std::vector<Vec3> start = atomic.positions();
    for (int s = 0; s < 2000; ++s) {
      atomic.step_rk4(kPaperDt);
      cumulated.step_rk4(kPaperDt);
    }
    for (std::size_t i = 0; i < atomic.vertex_count(); ++i) {
      deviation = std::max(deviation, (atomic.positions()[i] - cumulated.positions()[i]).norm());
      travel = std::max(travel, (atomic.positions()[i] - start[i]).norm());
    }
    EXPECT_GT(travel, 0.005);  // the cloth did sag and swing (the paper's cloth is stiff)
    EXPECT_LT(deviation, 1e-10) << "grid kind " << static_cast<int>(kind);
  }
}

// Springs as sorted (point, point, rest length) triples, comparable across solvers.
using SpringKey = std::tuple<std::int64_t, std::int64_t, Real>;

std::vector<SpringKey> keys(const std::vector<Spring>& springs,
                            const std::vector<std::int64_t>& point_of) {
  std::vector<SpringKey> out;
  for (const Spring& s : springs) {
    const std::int64_t a = point_of[s.a], b = point_of[s.b];
    out.emplace_back(std::min(a, b), std::max(a, b), std::round(s.rest * 1e9) / 1e9);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SpringCounts, SameSpringsAsTheGMapSupportOrbits) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    const MeshData mesh = make_grid(kind, 5, 3);
    GMap map = assemble_gmap(mesh);
    GMapClothModel model({});
    model.initialise(map);
    const ReferenceCloth cloth(mesh, {});
    EXPECT_EQ(model.counts().stretch, cloth.counts().stretch);
    EXPECT_EQ(model.counts().shear, cloth.counts().shear);
    EXPECT_EQ(model.counts().bend, cloth.counts().bend);
    // Same end points and rest lengths, spring by spring.
    const Embedding<std::int64_t> point = map.embedding<std::int64_t>("point_index");
    const Embedding<Vec3> position = map.embedding<Vec3>("position");
    std::vector<std::int64_t> point_of_slot(position.values().size(), -1);
    map.for_each_cell(Orbit{1, 2}, [&](Dart d) { point_of_slot[position.slot(d)] = point[d]; });
    std::vector<std::int64_t> identity(cloth.vertex_count());
    for (std::size_t i = 0; i < identity.size(); ++i)
      identity[i] = static_cast<std::int64_t>(i);
    EXPECT_EQ(keys(model.springs(), point_of_slot), keys(cloth.springs(), identity));
    // And the same force field at a random state.
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> noise(-0.02, 0.02);
    std::vector<Vec3> xs(position.values().size()), vs(xs.size(), Vec3::Zero()), fs(xs.size());
    std::vector<Vec3> xr(cloth.vertex_count()), vr(xr.size(), Vec3::Zero()), fr(xr.size());
    for (std::size_t i = 0; i < xr.size(); ++i) {
      xr[i] = mesh.points[i] + Vec3(noise(rng), noise(rng), noise(rng));
      vr[i] = Vec3(noise(rng), noise(rng), noise(rng));
    }
    for (std::size_t s = 0; s < xs.size(); ++s) {
      if (point_of_slot[s] < 0) continue;
      xs[s] = xr[point_of_slot[s]];
      vs[s] = vr[point_of_slot[s]];
    }
    for (Vec3& f : fs)
      f.setZero();
    model.add_forces({xs.data(), vs.data()}, fs.data(), false);
    cloth.internal_forces(xr.data(), vr.data(), fr.data());
    for (std::size_t s = 0; s < xs.size(); ++s) {
      if (point_of_slot[s] < 0) continue;
      EXPECT_LT((fs[s] - fr[point_of_slot[s]]).norm(), 1e-12) << "point " << point_of_slot[s];
    }
  }
}

// ---- masses -----------------------------------------------------------------------------

TEST(Masses, CornerMassesByArea) {
  const int n = 10;
  const ReferenceCloth cloth(hanging_grid(GridKind::Quad, n, n), {});
  const Real face = 0.1 / (n * n);  // equal squares
  EXPECT_NEAR(cloth.total_mass(), 0.1, 1e-15);
  const Real tol = 1e-12 * face;
  EXPECT_NEAR(cloth.masses()[grid_point(n, 0, 0)], face / 4, tol);  // 1 corner
  EXPECT_NEAR(cloth.masses()[grid_point(n, 3, 0)], face / 2, tol);  // 2 corners
  EXPECT_NEAR(cloth.masses()[grid_point(n, 4, 5)], face, tol);      // 4 corners
  // Triangles: a corner weighs a sixth of a square's mass.
  const ReferenceCloth tri(make_grid(GridKind::Tri, n, n), {});
  EXPECT_NEAR(tri.total_mass(), 0.1, 1e-15);
  EXPECT_NEAR(tri.masses()[grid_point(n, 0, 0)], 2 * face / 6, tol);  // both triangles
  EXPECT_NEAR(tri.masses()[grid_point(n, n, 0)], face / 6, tol);
  EXPECT_NEAR(tri.masses()[grid_point(n, 4, 5)], 6 * face / 6, tol);
}

TEST(Masses, SameAsTheRuntimeMassModel) {
  const MeshData mesh = hanging_grid(GridKind::Mix, 6, 4);
  Simulation sim(assemble_gmap(mesh), {});
  sim.set_total_mass(0.1);
  sim.initialise();
  const ReferenceCloth cloth(mesh, {});
  const Embedding<std::int64_t> point = sim.map().embedding<std::int64_t>("point_index");
  sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
    EXPECT_NEAR(sim.vertex_mass()[d], cloth.masses()[point[d]], 1e-17) << "point " << point[d];
  });
}

// ---- conservation laws ---------------------------------------------------------------

TEST(Conservation, MomentumWithoutGravityAndPins) {
  ReferenceCloth cloth(make_grid(GridKind::Quad, 10, 10), without_gravity());
  std::mt19937 rng(11);
  std::normal_distribution<Real> noise(0.0, 0.2);
  for (Vec3& v : cloth.velocities())
    v = Vec3(noise(rng), noise(rng), noise(rng));
  const Vec3 p0 = cloth.momentum();
  for (int s = 0; s < 2000; ++s)
    cloth.step_rk4(kPaperDt);
  EXPECT_LT((cloth.momentum() - p0).norm(), 1e-13 * (1 + p0.norm()));
  EXPECT_GT(cloth.elastic_energy(), 0);  // the cloth did deform
}

TEST(Conservation, InternalForcesHaveNoNetForceOrTorque) {
  // Central forces only (damping along the spring too): sum f = 0 and
  // sum x × f = 0 at any state, so angular momentum is conserved by the flow.
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    ReferenceCloth cloth(make_grid(kind, 6, 5), {});
    std::mt19937 rng(5);
    std::normal_distribution<Real> noise(0.0, 0.05);
    for (std::size_t i = 0; i < cloth.vertex_count(); ++i) {
      cloth.positions()[i] += Vec3(noise(rng), noise(rng), noise(rng)) + Vec3(2, -1, 3);
      cloth.velocities()[i] = Vec3(noise(rng), noise(rng), noise(rng)) * 10;
    }
    const std::vector<Vec3> f = cloth.current_internal_forces();
    Vec3 net = Vec3::Zero(), torque = Vec3::Zero();
    Real scale = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      net += f[i];
      torque += cloth.positions()[i].cross(f[i]);
      scale += f[i].norm() * (1 + cloth.positions()[i].norm());
    }
    ASSERT_GT(scale, 1e-3);
    EXPECT_LT(net.norm(), 1e-14 * scale);
    EXPECT_LT(torque.norm(), 1e-14 * scale);
  }
}

// Worst energy loss of RK4 per step on an undamped mode of frequency w:
// |R(i w dt)|^2 = 1 - (w dt)^6 / 72 + (w dt)^8 / 576.
Real rk4_energy_loss_bound(Real omega_max, Real dt, int steps) {
  const Real y = omega_max * dt;
  return steps * (std::pow(y, 6) / 72);
}

// Gershgorin bound of docs/physics.md on the highest frequency of the paper's
// quad cloth at rest: w_max^2 <= 2 * 366 N/m / 1 g.
const Real kOmegaMaxBound = std::sqrt(2 * 366.0 / 0.001);

TEST(Conservation, EnergyWithoutDampingFreeCloth) {
  ClothParameters p = without_gravity();
  p.stretch_c = p.shear_c = p.bend_c = 0;
  ReferenceCloth cloth(make_grid(GridKind::Quad, 10, 10), p);
  std::mt19937 rng(2);
  std::normal_distribution<Real> noise(0.0, 0.05);
  for (Vec3& v : cloth.velocities())
    v = Vec3(noise(rng), noise(rng), noise(rng));
  const Real e0 = cloth.total_energy();
  const Real dt = 1e-4;
  const int steps = 5000;
  Real worst = 0;
  for (int s = 0; s < steps; ++s) {
    cloth.step_rk4(dt);
    worst = std::max(worst, std::abs(cloth.total_energy() - e0));
  }
  EXPECT_LE(worst, rk4_energy_loss_bound(kOmegaMaxBound, dt, steps) * e0);
  EXPECT_GT(cloth.elastic_energy(), 1e-3 * e0);  // energy did move between the two forms
}

TEST(Conservation, EnergyWithoutDampingHangingCloth) {
  ClothParameters p;
  p.stretch_c = p.shear_c = p.bend_c = 0;
  ReferenceCloth cloth = paper_cloth(GridKind::Quad, 10, 10, p);
  jiggle(cloth, 1e-3, 4);
  const Real e0 = cloth.total_energy();
  const Real dt = 1e-4;
  const int steps = 5000;
  Real worst = 0, oscillating = 0;
  for (int s = 0; s < steps; ++s) {
    cloth.step_rk4(dt);
    worst = std::max(worst, std::abs(cloth.total_energy() - e0));
    oscillating = std::max(oscillating, cloth.kinetic_energy() + cloth.elastic_energy());
  }
  EXPECT_LE(worst, rk4_energy_loss_bound(kOmegaMaxBound, dt, steps) * oscillating);
  EXPECT_GT(cloth.kinetic_energy(), 0);
}

// ---- rest under gravity -----------------------------------------------------------------

TEST(HangingCloth, ComesToRestAndThePinsCarryTheWeight) {
  const int n = 10;
  ReferenceCloth cloth = paper_cloth(GridKind::Quad, n, n);
  const std::uint32_t left = grid_point(n, 0, n), right = grid_point(n, n, n);
  // 20 s of simulated time; the kinetic energy is checked over the last
  // second, not at one instant (a single mode has no kinetic energy twice a period).
  Real peak = 0, last_second = 0;
  const int steps = static_cast<int>(std::lround(20 / kPaperDt));
  for (int s = 0; s < steps; ++s) {
    cloth.step_rk4(kPaperDt);
    peak = std::max(peak, cloth.kinetic_energy());
    if (s >= steps - static_cast<int>(std::lround(1 / kPaperDt)))
      last_second = std::max(last_second, cloth.kinetic_energy());
  }
  ASSERT_GT(peak, 0);
  EXPECT_LE(last_second, 1e-14 * peak);

  // The springs pull the pins down by the weight of the free vertices; the
  // supports add the pins' own weight: the total reaction is -M g.
  const std::vector<Vec3> f = cloth.current_internal_forces();
  const Vec3 g = cloth.gravity();
  const Real pinned_mass = cloth.masses()[left] + cloth.masses()[right];
  const Vec3 free_weight = (cloth.total_mass() - pinned_mass) * g;
  const Vec3 on_pins = f[left] + f[right];
  EXPECT_LT((on_pins - free_weight).norm(), 1e-6 * free_weight.norm());
  const Vec3 reaction = -(on_pins + pinned_mass * g);
  EXPECT_LT((reaction + cloth.total_mass() * g).norm(), 1e-6 * cloth.total_mass() * g.norm());
  // By symmetry each pin carries half, and they are pulled towards each other.
  EXPECT_NEAR(f[left].z(), f[right].z(), 1e-6 * free_weight.norm());
  EXPECT_NEAR(f[left].x(), -f[right].x(), 1e-6 * free_weight.norm());
  EXPECT_GT(f[left].x(), 0);
  // It sags: the lower corners moved down, symmetrically.
  const Vec3 lower_left = cloth.positions()[grid_point(n, 0, 0)];
  const Vec3 lower_right = cloth.positions()[grid_point(n, n, 0)];
  EXPECT_LT(lower_left.z(), 0);
  EXPECT_NEAR(lower_left.z(), lower_right.z(), 1e-9);
  EXPECT_NEAR(lower_left.x(), 1 - lower_right.x(), 1e-9);
}

// ---- scaling --------------------------------------------------------------------------

TEST(Scaling, LengthsMassesAndStiffnessesScaleTheMotion) {
  // Lengths x s, masses x mu, time x tau: k x mu / tau^2, c x mu / tau,
  // g x s / tau^2. With g fixed, tau = sqrt(s). RK4 with dt x tau then gives
  // the same discrete motion: x'(tau t) = s x(t).
  const Real s = 2.0, mu = s * s * s, tau = std::sqrt(s);
  ClothParameters p;
  ClothParameters q = p;
  q.total_mass *= mu;
  for (Real* k : {&q.stretch_k, &q.shear_k, &q.bend_k})
    *k *= mu / (tau * tau);
  for (Real* c : {&q.stretch_c, &q.shear_c, &q.bend_c})
    *c *= mu / tau;
  q.gravity = p.gravity * s / (tau * tau);
  MeshData small = hanging_grid(GridKind::Mix, 6, 6);
  MeshData large = small;
  for (Vec3& x : large.points)
    x *= s;
  ReferenceCloth a(small, p), b(large, q);
  for (std::uint32_t pin : {grid_point(6, 0, 6), grid_point(6, 6, 6)}) {
    a.pin(pin);
    b.pin(pin);
  }
  jiggle(a, 0.01, 9);
  for (std::size_t i = 0; i < a.vertex_count(); ++i)
    b.positions()[i] = s * a.positions()[i];
  for (int step = 0; step < 1000; ++step) {
    a.step_rk4(kPaperDt);
    b.step_rk4(kPaperDt * tau);
  }
  Real worst = 0;
  for (std::size_t i = 0; i < a.vertex_count(); ++i) {
    worst = std::max(worst, (b.positions()[i] - s * a.positions()[i]).norm());
    worst = std::max(worst, (b.velocities()[i] - s / tau * a.velocities()[i]).norm());
  }
  EXPECT_LT(worst, 1e-10 * s);
  EXPECT_NEAR(b.time(), tau * a.time(), 1e-12);
  // Energies scale by mu s^2 / tau^2.
  EXPECT_NEAR(b.elastic_energy() / (a.elastic_energy() * mu * s * s / (tau * tau)), 1.0, 1e-9);
}

// ---- the runtime's loop with the same springs ----------------------------------------

TEST(RuntimeLoop, SimulationWithGMapSpringsFollowsTheReference) {
  for (GridKind kind : {GridKind::Quad, GridKind::Mix}) {
    const int n = 6;
    const MeshData mesh = hanging_grid(kind, n, n);
    const ClothParameters params;
    Simulation sim(assemble_gmap(mesh), {IntegratorKind::kRK4, kPaperDt, params.gravity});
    sim.set_total_mass(params.total_mass);
    sim.add_force_model(std::make_unique<GMapClothModel>(params));
    const Vec3 top_left = mesh.points[grid_point(n, 0, n)];
    const Vec3 top_right = mesh.points[grid_point(n, n, n)];
    const std::size_t pins = sim.pin_where([&](const Vec3& x) {
      return (x - top_left).norm() < 1e-9 || (x - top_right).norm() < 1e-9;
    });
    ASSERT_EQ(pins, 2u);
    sim.initialise();
    ReferenceCloth cloth = paper_cloth(kind, n, n, params);
    for (int s = 0; s < 400; ++s) {
      sim.step();
      cloth.step_rk4(kPaperDt);
    }
    const Embedding<std::int64_t> point = sim.map().embedding<std::int64_t>("point_index");
    Real worst = 0;
    sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
      worst = std::max(worst, (sim.position()[d] - cloth.positions()[point[d]]).norm());
      worst = std::max(worst, (sim.velocity()[d] - cloth.velocities()[point[d]]).norm());
    });
    EXPECT_LT(worst, 1e-11);
    EXPECT_NEAR(sim.kinetic_energy(), cloth.kinetic_energy(), 1e-12);
    EXPECT_NEAR(sim.momentum().z(), cloth.momentum().z(), 1e-13);
    // The runtime's potential energy: gravity plus the model's springs.
    EXPECT_NEAR(sim.potential_energy(), cloth.elastic_energy() + cloth.gravity_energy(), 1e-12);
    EXPECT_GT(cloth.kinetic_energy(), 0);
  }
}

}  // namespace
}  // namespace rift::reference
