// The vertex stress criteria (§5.2, eqs. 1-2) against a hand computation.
// vertex_stress reads each element's stress and mass where the force pass
// stored them (fem3d's corotational and fem2d's membrane `store` them per
// element: docs/language.md, "store"). Its measure must equal eqs. 1-2
// computed here from the stored forces alone: per element e around the
// vertex, its mass m_e (the sum of its corner masses), its current size V_e
// and its stress σ_e = -sym(Σ_corners f ⊗ x) / V_e (the virial), then the
// largest eigenvalue of Σ m_e σ_e / Σ m_e. The interactions add m_e σ_e and
// m_e per vertex during the force pass (`store v.E += ...`), so the
// criterion reads two sums. Checked at every vertex of a jittered mesh torn
// between collections by random vertex splits (a value stored before a tear
// and not refreshed would be wrong there), and between a tear and the next
// force pass: the vertices a rewrite touched read zero sums (they do not
// pass), the others the last pass's sums, unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "rift/core/symmetric_eigen.hpp"
#include "rift/generated/orbit_values.hpp"
#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

/// Eqs. 1-2 at the vertex of `v`, with plain walks of the map: the elements
/// are the volumes <0,1,2> (3D) or faces <0,1> (2D) around it, their corners
/// <1,2> or <1>, and the forces those of f_fem or f_membrane.
Real hand_vertex_stress(const GMap& g, Dart v) {
  const bool volumes = g.dimension() == 3;
  const Orbit vertex = volumes ? Orbit{1, 2, 3} : Orbit{1, 2};
  const Orbit element = volumes ? Orbit{0, 1, 2} : Orbit{0, 1};
  const Orbit corner = volumes ? Orbit{1, 2} : Orbit{1};
  const auto position = g.embedding<Vec3>("position");
  const auto force = g.embedding<Vec3>(volumes ? "f_fem" : "f_membrane");
  const auto corner_mass = g.embedding<Real>("corner_mass");
  Mat3 weighted = Mat3::Zero();
  Real mass = 0;
  g.for_each_sub_orbit(v, vertex, element, [&](Dart c) {
    const Vec3 e1 = position[g.alpha(c, 0)] - position[c];
    const Vec3 e2 = position[g.alpha(g.alpha(c, 1), 0)] - position[c];
    Real size = 0;
    if (volumes) {
      Mat3 edges;
      edges << e1, e2, position[g.alpha(g.alpha(g.alpha(c, 2), 1), 0)] - position[c];
      size = std::abs(edges.determinant()) / 6;
    } else {
      size = 0.5 * e1.cross(e2).norm();
    }
    const Real element_mass = generated::fold_sum(g, corner_mass, c, element, corner);
    Mat3 virial = Mat3::Zero();
    g.for_each_sub_orbit(c, element, corner,
                         [&](Dart k) { virial += force[k] * position[k].transpose(); });
    if (size > 0) weighted += element_mass / size * Mat3(-0.5 * (virial + virial.transpose()));
    mass += element_mass;
  });
  return symmetric_max_eigenvalue(mass > 0 ? Mat3(weighted / mass) : Mat3(Mat3::Zero()));
}

/// Every vertex is a candidate (a tiny threshold), so that collect reports
/// the measure of each one; compared with hand_vertex_stress over rounds of
/// new positions and random splits.
void expect_hand_computation_after_random_tears(const std::string& name, const std::string& toml,
                                                std::size_t min_splits) {
  constexpr Real kThreshold = 1.0e-9;
  auto sim = simulate(name, toml);
  // A fixed seed: the same positions and splits on every run.
  std::mt19937 rng(12);  // NOLINT(bugprone-random-generator-seed)
  std::uniform_real_distribution<Real> jitter(-0.03, 0.03);
  GMap& g = sim->map();
  const Orbit vertex = Orbit::cell(0, g.dimension());
  const Criterion& criterion = *sim->criteria().at(0);
  std::size_t splits = 0;
  for (int round = 0; round < 8; ++round) {
    // New positions every round: a stress stored at the last collection is wrong.
    g.for_each_cell(vertex, [&](Dart d) {
      sim->position()[d] += Vec3(jitter(rng), jitter(rng), g.dimension() == 3 ? jitter(rng) : 0);
    });
    store_forces(*sim);
    std::vector<TearCandidate> candidates;
    criterion.collect(g, candidates);
    // One candidate per vertex whose hand measure passes, each with its measure.
    std::size_t passing = 0;
    g.for_each_cell(vertex, [&](Dart v) { passing += hand_vertex_stress(g, v) > kThreshold; });
    ASSERT_EQ(candidates.size(), passing) << "round " << round;
    ASSERT_GT(passing, 10u);
    for (const TearCandidate& c : candidates) {
      const Real hand = hand_vertex_stress(g, c.at);
      // The same terms in another order (the element's corners, its sizes
      // from another corner): equal to rounding.
      EXPECT_NEAR(c.measure + kThreshold, hand, 1e-11 * std::max<Real>(1, std::abs(hand)))
          << "round " << round << ", dart " << c.at;
    }
    // The measures of this pass, by vertex slot.
    const Embedding<Vec3> position = sim->position();
    std::map<Slot, Real> before;
    for (const TearCandidate& c : candidates)
      before[position.slot(c.at)] = c.measure;
    // Tear at two random candidates (vertex splits); the next collection
    // after a force pass must see the stresses of the new elements'
    // arrangement.
    std::set<Slot> touched_vertices;
    for (int attempt = 0, done = 0; attempt < 20 && done < 2; ++attempt) {
      std::vector<TearCandidate> now;
      criterion.collect(g, now);
      std::uniform_int_distribution<std::size_t> pick(0, now.size() - 1);
      std::vector<Dart> touched;
      if (sim->criteria()[0]->apply(g, now[pick(rng)], touched)) ++done, ++splits;
      ASSERT_TRUE(g.check_validity().empty());
      sim->on_topology_changed(touched);
      for (Dart d : touched)
        if (g.is_alive(d)) touched_vertices.insert(position.slot(d));
    }
    // Before the next force pass: the touched vertices' sums are zero, the
    // others' those of the last pass.
    std::vector<TearCandidate> after;
    criterion.collect(g, after);
    std::size_t kept = 0;
    for (const auto& [slot, measure] : before)
      kept += touched_vertices.count(slot) == 0;
    EXPECT_EQ(after.size(), kept) << "round " << round;
    for (const TearCandidate& c : after) {
      const Slot slot = position.slot(c.at);
      EXPECT_EQ(touched_vertices.count(slot), 0u) << "round " << round << ", dart " << c.at;
      const auto it = before.find(slot);
      ASSERT_NE(it, before.end()) << "round " << round << ", dart " << c.at;
      EXPECT_EQ(c.measure, it->second) << "round " << round << ", dart " << c.at;
    }
  }
  EXPECT_GE(splits, min_splits);
}

TEST(VertexStress, TetrahedraEqualEquations1And2AfterRandomTears) {
  expect_hand_computation_after_random_tears(
      "vertex_stress_3d",
      static_scene("block:tet:3x2x2", "[0.75, 0.5, 0.5]", 1.0,
                   "[[interaction]]\nname = \"corotational\"\n"
                   "young = 1.0e5\npoisson = 0.3\n"
                   "[[criterion]]\nname = \"vertex_stress\"\n"
                   "threshold = 1.0e-9\n"),
      12);
}

TEST(VertexStress, TrianglesEqualEquations1And2AfterRandomTears) {
  expect_hand_computation_after_random_tears(
      "vertex_stress_2d",
      static_scene("grid:tri:6x5", "[1.0, 0.8, 1.0]", 1.0,
                   "[[interaction]]\nname = \"membrane\"\n"
                   "young = 1.0e3\npoisson = 0.3\n"
                   "[[criterion]]\nname = \"vertex_stress\"\n"
                   "threshold = 1.0e-9\n"),
      12);
}

}  // namespace
}  // namespace rift::tearing_test
