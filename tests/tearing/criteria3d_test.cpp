// Every criterion of criteria3d.rules on a small bar of the standard packs:
// above its threshold the expected fracture happens at the expected place,
// below it nothing breaks; the G-map stays valid after every rewrite, the
// cell counts are those expected and the mass is unchanged by separations
// and vertex splits, lower by exactly the removed volumes' by removals.
//
// The bar: 4 cubes along x over [0,1] x [0,0.25]^2 (hexahedra, or the six
// tetrahedra of each cube), 0.1 kg per cube. Static scenes as in 2D.
#include <gtest/gtest.h>

#include <algorithm>

#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

constexpr double kBarMass = 0.4;

std::string bar(const std::string& kind, const std::string& components) {
  return static_scene("block:" + kind + ":4x1x1", "[1.0, 0.25, 0.25]", kBarMass, components);
}

const std::string kBarStretch = interaction_table("stretch", "stiffness = 60.0\ndamping = 0.0");
const std::string kFem =
    interaction_table("corotational", "young = 1.0e5\npoisson = 0.3\ndamping = 0.0");

/// Cube 2 (x in [0.5, 0.75]) stretched by 0.05 along x (strain 0.2): its
/// springs along x pull with 60 N/m * 0.05 m = 3 N.
Vec3 pull_cube_2(const Vec3& p) {
  return p.x() > 0.6 ? Vec3(p.x() + 0.05, p.y(), p.z()) : p;
}

/// Cubes 1 and 2 (x in [0.25, 0.75]) stretched by 0.05 each.
Vec3 pull_cubes_1_2(const Vec3& p) {
  return Vec3(p.x() + 0.2 * std::clamp(p.x() - 0.25, 0.0, 0.5), p.y(), p.z());
}

/// Every piece stays a ball: V - E + F - C is the number of pieces.
void expect_balls(const Counts& c) {
  EXPECT_EQ(c.euler(), static_cast<long>(c.components));
}

void expect_cube_2_removed(const Simulation& sim, std::size_t cells_per_cube) {
  const Counts c = counts(sim.map());
  EXPECT_EQ(c.volumes, 3 * cells_per_cube);
  EXPECT_EQ(c.components, 2u);
  expect_balls(c);
  EXPECT_NEAR(sim.total_mass(), kBarMass - 0.1, 1e-12);
  for (const Vec3& centre : element_centres(sim))
    EXPECT_FALSE(centre.x() > 0.5 && centre.x() < 0.8) << centre.transpose();
}

/// The faces x = 0.5 and x = 0.75 (deformed: 0.8) separated: cube 2 is a
/// piece of its own; 8 vertices split.
void expect_cube_2_cut_out(const Simulation& sim, std::size_t cells_per_cube) {
  const Counts c = counts(sim.map());
  EXPECT_EQ(c.vertices, 20u + 8u);
  EXPECT_EQ(c.volumes, 4 * cells_per_cube);
  EXPECT_EQ(c.components, 3u);
  expect_balls(c);
  EXPECT_NEAR(sim.total_mass(), kBarMass, 1e-12);
  const auto split = split_positions(sim);
  EXPECT_EQ(split.size(), 8u);
  for (const Vec3& p : split)
    EXPECT_TRUE(std::abs(p.x() - 0.5) < 1e-6 || std::abs(p.x() - 0.8) < 1e-6) << p.transpose();
}

void expect_unbroken(const Simulation& sim, std::size_t volumes) {
  EXPECT_EQ(sim.tears(), 0u);
  const Counts c = counts(sim.map());
  EXPECT_EQ(c.vertices, 20u);
  EXPECT_EQ(c.volumes, volumes);
  EXPECT_EQ(c.components, 1u);
  EXPECT_NEAR(sim.total_mass(), kBarMass, 1e-12);
}

TEST(Criteria3D, StretchForceRemovesTheVolumesAroundTheStretchedEdges) {
  expect_cube_2_removed(
      *step_once("s3_stretch", bar("hex", kBarStretch + criterion_table("stretch_force", 2.0)),
                 pull_cube_2),
      1);
  expect_unbroken(
      *step_once("s3_stretch_below",
                 bar("hex", kBarStretch + criterion_table("stretch_force", 4.0)), pull_cube_2),
      4);
}

TEST(Criteria3D, SpringSplitSplitsTheExtremitiesAcrossTheSpring) {
  expect_cube_2_cut_out(
      *step_once("s3_split", bar("hex", kBarStretch + criterion_table("spring_split", 2.0)),
                 pull_cube_2),
      1);
  expect_unbroken(
      *step_once("s3_split_below", bar("hex", kBarStretch + criterion_table("spring_split", 4.0)),
                 pull_cube_2),
      4);
}

TEST(Criteria3D, ShearForceRemovesTheShearedHexahedron) {
  // The body diagonals of cube 2 grow from 0.4330 to 0.4637: 43 N/m * 0.0307 m = 1.32 N.
  const std::string shear = interaction_table("volume_shear", "stiffness = 43.0\ndamping = 0.0");
  expect_cube_2_removed(
      *step_once("s3_shear", bar("hex", shear + criterion_table("shear_force", 1.0)), pull_cube_2),
      1);
  expect_unbroken(*step_once("s3_shear_below",
                             bar("hex", shear + criterion_table("shear_force", 2.0)), pull_cube_2),
                  4);
}

TEST(Criteria3D, ElementStressRemovesTheStretchedTetrahedra) {
  // Strain 0.2 along x, E = 1e5 Pa: a principal stress between E * 0.2 and
  // (lambda + 2 mu) * 0.2 = 2.7e4 Pa in cube 2, none elsewhere.
  expect_cube_2_removed(
      *step_once("s3_element", bar("tet", kFem + criterion_table("element_stress", 1.0e4)),
                 pull_cube_2),
      6);
  expect_unbroken(
      *step_once("s3_element_below", bar("tet", kFem + criterion_table("element_stress", 1.0e5)),
                 pull_cube_2),
      24);
}

TEST(Criteria3D, VertexStressSplitsTheVerticesOfTheStretchedCube) {
  expect_cube_2_cut_out(
      *step_once("s3_vstress", bar("tet", kFem + criterion_table("vertex_stress", 5.0e3)),
                 pull_cube_2),
      6);
  expect_unbroken(
      *step_once("s3_vstress_below", bar("tet", kFem + criterion_table("vertex_stress", 1.0e5)),
                 pull_cube_2),
      24);
}

TEST(Criteria3D, InteractionForceSplitsOnlyVerticesOfTheStretchedCube) {
  // A single tetrahedron's force is not along x exactly: the planes need not
  // cut cube 2 out cleanly, but the splits are around it, and nothing is lost.
  auto torn = step_once("s3_iforce", bar("tet", kFem + criterion_table("interaction_force", 20.0)),
                        pull_cube_2);
  EXPECT_GE(torn->tears(), 1u);
  const Counts c = counts(torn->map());
  EXPECT_GT(c.vertices, 20u);
  EXPECT_EQ(c.volumes, 24u);
  EXPECT_NEAR(torn->total_mass(), kBarMass, 1e-12);
  // Whole faces separate: a plane that is not across x splits some faces of
  // cubes 1 and 3 at their far corners too, but never the end x = 0.
  std::size_t on_cube_2 = 0;
  for (const Vec3& p : split_positions(*torn)) {
    EXPECT_GT(p.x(), 0.2) << p.transpose();
    on_cube_2 += std::abs(p.x() - 0.5) < 1e-6 || std::abs(p.x() - 0.8) < 1e-6;
  }
  EXPECT_GE(on_cube_2, 4u);
  expect_unbroken(
      *step_once("s3_iforce_below", bar("tet", kFem + criterion_table("interaction_force", 1.0e4)),
                 pull_cube_2),
      24);
}

TEST(Criteria3D, VertexSumSplitsTheVerticesOfTheStretchedCube) {
  // Each end vertex of cube 2 is pulled by its two springs along x: 6 N.
  expect_cube_2_cut_out(
      *step_once("s3_vsum", bar("hex", kBarStretch + criterion_table("vertex_sum", 5.0)),
                 pull_cube_2),
      1);
  expect_unbroken(
      *step_once("s3_vsum_below", bar("hex", kBarStretch + criterion_table("vertex_sum", 7.0)),
                 pull_cube_2),
      4);
}

TEST(Criteria3D, GlobalFaceSeparatesTheFacesOfTheStretchedCube) {
  // The four vertices of the faces x = 0.5 and x = 0.75 are pulled by 6 N
  // each along the faces' normal: 24 N; every other inner face, 0.
  expect_cube_2_cut_out(
      *step_once("s3_gface", bar("hex", kBarStretch + criterion_table("global_face", 20.0)),
                 pull_cube_2),
      1);
  expect_unbroken(
      *step_once("s3_gface_below", bar("hex", kBarStretch + criterion_table("global_face", 30.0)),
                 pull_cube_2),
      4);
}

TEST(Criteria3D, AtomicFaceSeparatesTheFaceBothVolumesContract) {
  // At x = 0.5 cube 1 pulls the face by -24 N, cube 2 by +24 N: 48 N. At
  // x = 0.25 and 0.75 one of the two cubes does not pull.
  auto torn = step_once("s3_aface", bar("hex", kBarStretch + criterion_table("atomic_face", 40.0)),
                        pull_cubes_1_2);
  EXPECT_EQ(torn->tears(), 1u);
  const Counts c = counts(torn->map());
  EXPECT_EQ(c.vertices, 24u);
  EXPECT_EQ(c.components, 2u);
  expect_balls(c);
  EXPECT_NEAR(torn->total_mass(), kBarMass, 1e-12);
  for (const Vec3& p : split_positions(*torn))
    EXPECT_NEAR(p.x(), 0.55, 1e-9);
  expect_unbroken(
      *step_once("s3_aface_below", bar("hex", kBarStretch + criterion_table("atomic_face", 60.0)),
                 pull_cubes_1_2),
      4);
}

}  // namespace
}  // namespace rift::tearing_test
