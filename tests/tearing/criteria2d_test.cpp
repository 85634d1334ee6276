// Every criterion of criteria2d.rules on a small strip of the standard packs:
// above its threshold the expected tear happens at the expected place, below
// it nothing tears; after tearing the G-map is valid (checked after every
// rewrite), the cell counts are those expected, and the mass is unchanged
// (separations, vertex splits) or lower by exactly the removed elements'.
//
// The strip: 6 cells along x over [0,1] x [0,0.2], 0.1 kg per cell. The
// scenes are static (no gravity, dt = 1e-7): positions are imposed after the
// rest state is recorded, and one step evaluates the criteria.
#include <gtest/gtest.h>

#include <algorithm>

#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

constexpr double kStripMass = 0.6;

std::string strip(const std::string& kind, const std::string& components) {
  return static_scene("grid:" + kind + ":6x1", "[1.0, 0.2, 1.0]", kStripMass, components);
}

const std::string kStripStretch = interaction_table("stretch", "stiffness = 60.0\ndamping = 0.0");

/// Column 3 (x in [0.5, 0.667]) stretched by 0.05 along x: strain 0.3, and a
/// stretch spring force of 60 N/m * 0.05 m = 3 N on its horizontal edges.
Vec3 pull_column_3(const Vec3& p) {
  return p.x() > 0.55 ? Vec3(p.x() + 0.05, p.y(), p.z()) : p;
}

/// Columns 2 and 3 (x in [1/3, 2/3]) stretched by 0.05 each.
Vec3 pull_columns_2_3(const Vec3& p) {
  const Real u = 0.3 * std::clamp(p.x() - 1.0 / 3.0, 0.0, 1.0 / 3.0);
  return Vec3(p.x() + u, p.y(), p.z());
}

/// Every piece of these strips stays a disk: V - E + F is the number of pieces.
void expect_disks(const Counts& c) {
  EXPECT_EQ(c.euler(), static_cast<long>(c.components));
}

/// Column 3 was removed: two pieces of the strip, 5 cells, 0.1 kg less.
void expect_column_3_removed(const Simulation& sim, std::size_t cells_per_column) {
  const Counts c = counts(sim.map());
  EXPECT_EQ(c.faces, 5 * cells_per_column);
  EXPECT_EQ(c.components, 2u);
  expect_disks(c);
  EXPECT_NEAR(sim.total_mass(), kStripMass - 0.1, 1e-12);
  for (const Vec3& centre : element_centres(sim))
    EXPECT_FALSE(centre.x() > 0.5 && centre.x() < 0.72) << centre.transpose();
}

/// The vertices at x = 0.5 and x = 0.667 (deformed: 0.717) split: column 3
/// is a piece of its own, no cell and no mass is lost.
void expect_column_3_cut_out(const Simulation& sim, std::size_t cells_per_column) {
  const Counts c = counts(sim.map());
  EXPECT_EQ(c.vertices, 14u + 4u);
  EXPECT_EQ(c.faces, 6 * cells_per_column);
  EXPECT_EQ(c.components, 3u);
  expect_disks(c);
  EXPECT_NEAR(sim.total_mass(), kStripMass, 1e-12);
  const auto split = split_positions(sim);
  EXPECT_EQ(split.size(), 4u);
  for (const Vec3& p : split)
    EXPECT_TRUE(std::abs(p.x() - 0.5) < 1e-6 || std::abs(p.x() - (4.0 / 6.0 + 0.05)) < 1e-6)
        << p.transpose();
}

void expect_untorn(const Simulation& sim, std::size_t faces) {
  EXPECT_EQ(sim.tears(), 0u);
  const Counts c = counts(sim.map());
  EXPECT_EQ(c.vertices, 14u);
  EXPECT_EQ(c.faces, faces);
  EXPECT_EQ(c.components, 1u);
  EXPECT_NEAR(sim.total_mass(), kStripMass, 1e-12);
}

TEST(Criteria2D, StretchStrainRemovesTheElementsOfTheStretchedEdges) {
  auto torn =
      step_once("strain", strip("quad", kStripStretch + criterion_table("stretch_strain", 0.2)),
                pull_column_3);
  EXPECT_GE(torn->tears(), 1u);
  expect_column_3_removed(*torn, 1);
  expect_untorn(*step_once("strain_below",
                           strip("quad", kStripStretch + criterion_table("stretch_strain", 0.35)),
                           pull_column_3),
                6);
}

TEST(Criteria2D, StretchForceRemovesTheElementsOfTheStretchedEdges) {
  auto torn = step_once("stretch_force",
                        strip("quad", kStripStretch + criterion_table("stretch_force", 2.0)),
                        pull_column_3);
  expect_column_3_removed(*torn, 1);
  expect_untorn(*step_once("stretch_force_below",
                           strip("quad", kStripStretch + criterion_table("stretch_force", 4.0)),
                           pull_column_3),
                6);
}

TEST(Criteria2D, SpringSplitSplitsBothExtremitiesAcrossTheSpring) {
  auto torn =
      step_once("spring_split", strip("quad", kStripStretch + criterion_table("spring_split", 2.0)),
                pull_column_3);
  expect_column_3_cut_out(*torn, 1);
  expect_untorn(*step_once("spring_split_below",
                           strip("quad", kStripStretch + criterion_table("spring_split", 4.0)),
                           pull_column_3),
                6);
}

TEST(Criteria2D, ShearForceRemovesTheShearedQuad) {
  // The diagonals of column 3 grow from 0.2603 to 0.2949: 43 N/m * 0.0345 m = 1.48 N.
  const std::string shear = interaction_table("shear", "stiffness = 43.0\ndamping = 0.0");
  auto torn =
      step_once("shear", strip("quad", shear + criterion_table("shear_force", 1.0)), pull_column_3);
  expect_column_3_removed(*torn, 1);
  expect_untorn(
      *step_once("shear_below", strip("quad", shear + criterion_table("shear_force", 2.0)),
                 pull_column_3),
      6);
}

/// The right part of the strip (x > 0.5) folded up by 60 degrees about x = 0.5:
/// the bending springs across that edge shrink from 1/3 to cos(30) / 3, a
/// force of 10 N/m * 0.0447 m = 0.447 N; the other springs keep their length.
Vec3 fold_at_half(const Vec3& p) {
  if (p.x() <= 0.5) return p;
  const Real r = p.x() - 0.5, angle = std::acos(-1.0) / 3.0;
  return Vec3(0.5 + r * std::cos(angle), p.y(), r * std::sin(angle));
}

TEST(Criteria2D, BendForceSeparatesTheFacesOfTheFoldedEdge) {
  const std::string bend = interaction_table("bend", "stiffness = 10.0\ndamping = 0.0");
  auto sim = simulate("bend", strip("quad", bend + criterion_table("bend_force", 0.3)));
  const ForceModel& model = *sim->force_models()[0];
  EXPECT_EQ(model.active_matches(), 10u);  // 5 interior edges, 2 extremities each
  deform(*sim, fold_at_half);
  sim->step();
  const Counts c = counts(sim->map());
  EXPECT_EQ(c.vertices, 16u);
  EXPECT_EQ(c.components, 2u);
  expect_disks(c);
  EXPECT_NEAR(sim->total_mass(), kStripMass, 1e-12);
  const auto split = split_positions(*sim);
  ASSERT_EQ(split.size(), 2u);
  for (const Vec3& p : split)
    EXPECT_NEAR(p.x(), 0.5, 1e-9);
  // No bending spring acts across the cut edge any more, and the forces
  // those springs stored are zero.
  EXPECT_EQ(model.active_matches(), 8u);
  const GMap& g = sim->map();
  const auto f_bend = g.embedding<Vec3>("f_bend");
  std::size_t cut_darts = 0;
  g.for_each_dart([&](Dart d) {
    const Vec3 a = sim->position()[d], b = sim->position()[g.alpha(d, 0)];
    if (!g.is_free(d, 2) || std::abs(a.x() - 0.5) > 1e-9 || std::abs(b.x() - 0.5) > 1e-9) return;
    ++cut_darts;
    EXPECT_EQ(f_bend[g.alpha(g.alpha(d, 1), 0)], Vec3::Zero());
  });
  EXPECT_EQ(cut_darts, 4u);
  expect_untorn(*step_once("bend_below", strip("quad", bend + criterion_table("bend_force", 0.6)),
                           fold_at_half),
                6);
}

const std::string kMembrane =
    interaction_table("membrane", "young = 1000.0\npoisson = 0.3\ndamping = 0.0");

TEST(Criteria2D, ElementStressRemovesTheStretchedTriangles) {
  // Strain 0.3 along x: a principal stress of about E / (1 - nu^2) * 0.3 = 330 N/m.
  auto torn =
      step_once("element_stress",
                strip("tri", kMembrane + criterion_table("element_stress", 100.0)), pull_column_3);
  expect_column_3_removed(*torn, 2);
  expect_untorn(*step_once("element_stress_below",
                           strip("tri", kMembrane + criterion_table("element_stress", 1000.0)),
                           pull_column_3),
                12);
}

TEST(Criteria2D, InteractionForceSplitsTheVerticesOfTheStretchedColumn) {
  auto torn = step_once("interaction_force",
                        strip("quad", kStripStretch + criterion_table("interaction_force", 2.0)),
                        pull_column_3);
  expect_column_3_cut_out(*torn, 1);
  expect_untorn(*step_once("interaction_force_below",
                           strip("quad", kStripStretch + criterion_table("interaction_force", 4.0)),
                           pull_column_3),
                6);
}

TEST(Criteria2D, VertexStressSplitsTheVerticesOfTheStretchedColumn) {
  auto torn =
      step_once("vertex_stress", strip("tri", kMembrane + criterion_table("vertex_stress", 100.0)),
                pull_column_3);
  expect_column_3_cut_out(*torn, 2);
  expect_untorn(
      *step_once("vertex_stress_below",
                 strip("tri", kMembrane + criterion_table("vertex_stress", 1000.0)), pull_column_3),
      12);
}

TEST(Criteria2D, VertexSumSplitsTheVerticesOfTheStretchedColumn) {
  // The ends of column 3 are pulled by 3 N each, every other vertex by none.
  auto torn =
      step_once("vertex_sum", strip("quad", kStripStretch + criterion_table("vertex_sum", 2.0)),
                pull_column_3);
  expect_column_3_cut_out(*torn, 1);
  expect_untorn(
      *step_once("vertex_sum_below",
                 strip("quad", kStripStretch + criterion_table("vertex_sum", 4.0)), pull_column_3),
      6);
}

TEST(Criteria2D, GlobalEdgeSeparatesTheEdgesOfTheStretchedColumn) {
  // |(fA + fB).n| = 3 N + 3 N on the edges x = 0.5 and x = 0.667, 0 elsewhere.
  auto torn =
      step_once("global_edge", strip("quad", kStripStretch + criterion_table("global_edge", 5.0)),
                pull_column_3);
  expect_column_3_cut_out(*torn, 1);
  EXPECT_EQ(torn->tears(), 2u);
  expect_untorn(
      *step_once("global_edge_below",
                 strip("quad", kStripStretch + criterion_table("global_edge", 7.0)), pull_column_3),
      6);
}

TEST(Criteria2D, AtomicEdgeSeparatesTheEdgeBothFacesContract) {
  // At x = 0.5 both faces pull the edge into themselves (f1 = -6 N, f2 = +6 N
  // along x): |(f1 - f2).n| = 12 N. At x = 1/3 and 2/3 one face does not pull.
  auto torn =
      step_once("atomic_edge", strip("quad", kStripStretch + criterion_table("atomic_edge", 10.0)),
                pull_columns_2_3);
  EXPECT_EQ(torn->tears(), 1u);
  const Counts c = counts(torn->map());
  EXPECT_EQ(c.vertices, 16u);
  EXPECT_EQ(c.components, 2u);
  expect_disks(c);
  EXPECT_NEAR(torn->total_mass(), kStripMass, 1e-12);
  for (const Vec3& p : split_positions(*torn))
    EXPECT_NEAR(p.x(), 0.55, 1e-9);
  expect_untorn(*step_once("atomic_edge_below",
                           strip("quad", kStripStretch + criterion_table("atomic_edge", 14.0)),
                           pull_columns_2_3),
                6);
}

}  // namespace
}  // namespace rift::tearing_test
