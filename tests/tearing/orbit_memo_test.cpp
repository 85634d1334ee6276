// The orbit memos of generated criteria (compiler/lower/orbit_memo.hpp):
// criteria3d's vertex_stress computes each tetrahedron's mass and Σ f ⊗ x
// once per collection and reads them back for the tetrahedron's other
// vertices. Its measures must equal a fresh evaluation of the rules' formula
// at every vertex, on a map torn between collections by random vertex splits
// (a value remembered from an earlier collection would be stale there).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "rift/core/symmetric_eigen.hpp"
#include "rift/generated/orbit_values.hpp"
#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

/// criteria3d.rules' vertex_stress at the vertex of `v`, written out with
/// plain walks of the map: Σ over its tetrahedra of (m_e / V_e) Σ f ⊗ x,
/// over Σ m_e, symmetrised.
Real fresh_vertex_stress(const GMap& g, Dart v) {
  const auto position = g.embedding<Vec3>("position");
  const auto f_fem = g.embedding<Vec3>("f_fem");
  const auto corner_mass = g.embedding<Real>("corner_mass");
  Mat3 weighted = Mat3::Zero();
  Real mass = 0;
  g.for_each_sub_orbit(v, Orbit{1, 2, 3}, Orbit{0, 1, 2}, [&](Dart c) {
    Mat3 edges;
    edges << position[g.alpha(c, 0)] - position[c],
        position[g.alpha(g.alpha(c, 1), 0)] - position[c],
        position[g.alpha(g.alpha(g.alpha(c, 2), 1), 0)] - position[c];
    const Real six_volume = std::abs(edges.determinant());
    const Real element_mass = generated::fold_sum(g, corner_mass, c, Orbit{0, 1, 2}, Orbit{1, 2});
    Mat3 virial = Mat3::Zero();
    g.for_each_sub_orbit(c, Orbit{0, 1, 2}, Orbit{1, 2},
                         [&](Dart k) { virial += f_fem[k] * position[k].transpose(); });
    if (six_volume > 0) weighted += element_mass * 6.0 / six_volume * virial;
    mass += element_mass;
  });
  if (!(mass > 0)) return symmetric_max_eigenvalue(Mat3::Zero());
  return symmetric_max_eigenvalue(Mat3(-0.5 * (weighted + weighted.transpose()) / mass));
}

TEST(OrbitMemo, VertexStressEqualsAFreshEvaluationAfterRandomTears) {
  // Every vertex is a candidate (a tiny threshold), so that collect reports
  // the measure of each one.
  constexpr Real kThreshold = 1.0e-9;
  auto sim = simulate("orbit_memo", static_scene("block:tet:3x2x2", "[0.75, 0.5, 0.5]", 1.0,
                                                 "[[interaction]]\nname = \"corotational\"\n"
                                                 "young = 1.0e5\npoisson = 0.3\n"
                                                 "[[criterion]]\nname = \"vertex_stress\"\n"
                                                 "threshold = 1.0e-9\n"));
  std::mt19937 rng(12);
  std::uniform_real_distribution<Real> jitter(-0.03, 0.03);
  GMap& g = sim->map();
  const Criterion& criterion = *sim->criteria().at(0);
  std::size_t splits = 0;
  for (int round = 0; round < 8; ++round) {
    // New positions every round: a value remembered from the last collection is wrong.
    g.for_each_cell(Orbit::cell(0, 3), [&](Dart d) {
      sim->position()[d] += Vec3(jitter(rng), jitter(rng), jitter(rng));
    });
    store_forces(*sim);
    std::vector<TearCandidate> candidates;
    criterion.collect(g, candidates);
    // One candidate per vertex whose fresh measure passes, each with its measure.
    std::size_t passing = 0;
    g.for_each_cell(Orbit::cell(0, 3),
                    [&](Dart v) { passing += fresh_vertex_stress(g, v) > kThreshold; });
    ASSERT_EQ(candidates.size(), passing) << "round " << round;
    ASSERT_GT(passing, 10u);
    for (const TearCandidate& c : candidates) {
      const Real fresh = fresh_vertex_stress(g, c.at);
      // The memo walks a tetrahedron from the first vertex that meets it:
      // its sums may add the same terms in another order (last bits).
      EXPECT_NEAR(c.measure + kThreshold, fresh, 1e-12 * std::max<Real>(1, std::abs(fresh)))
          << "round " << round << ", dart " << c.at;
    }
    // Tear at two random candidates (vertex splits); the memo of the next
    // collection must not see the orbits as they were.
    for (int attempt = 0, done = 0; attempt < 20 && done < 2; ++attempt) {
      std::vector<TearCandidate> now;
      criterion.collect(g, now);
      std::uniform_int_distribution<std::size_t> pick(0, now.size() - 1);
      std::vector<Dart> touched;
      if (sim->criteria()[0]->apply(g, now[pick(rng)], touched)) ++done, ++splits;
      ASSERT_TRUE(g.check_validity().empty());
      sim->on_topology_changed(touched);
    }
  }
  EXPECT_GE(splits, 12u);
}

}  // namespace
}  // namespace rift::tearing_test
