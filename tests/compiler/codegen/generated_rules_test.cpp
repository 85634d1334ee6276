// Generated code applied to real G-maps: every rewrite leaves a valid map with
// the expected cell counts and embedding values (Jerboa's classic rules and
// the tearing rules of §4), interactions compute opposite forces, criteria
// trigger their rule, and the registry lists everything by name.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "gen2d.hpp"
#include "gen3d.hpp"
#include "rift/mesh/load_map.hpp"
#include "rift/mesh/map_statistics.hpp"

namespace {

namespace g2 = rift::packs::gen2d;
namespace g3 = rift::packs::gen3d;
using rift::Dart;
using rift::GMap;
using rift::Vec3;

GMap grid(const char* spec) {
  GMap g = rift::load_map(spec);
  g2::declare_embeddings(g);
  g2::run_initialisers(g);
  return g;
}

/// The first dart that is (or is not) i-free.
Dart find_dart(const GMap& g, int i, bool free) {
  Dart found = rift::kNoDart;
  g.for_each_dart([&](Dart d) {
    if (found == rift::kNoDart && g.is_free(d, i) == free) found = d;
  });
  return found;
}

bool apply(bool (*rule)(GMap&, std::span<const Dart>, const g2::Params&), GMap& g,
           std::initializer_list<Dart> hooks) {
  return rule(g, std::span<const Dart>(hooks.begin(), hooks.size()), {});
}

void expect_valid(const GMap& g) {
  const auto problems = g.check_validity();
  EXPECT_TRUE(problems.empty()) << problems.front();
}

TEST(GeneratedRules, SeparateFacesSplitsTheEdgeAndItsVertices) {
  GMap g = grid("grid:quad:2x1");
  const auto before = rift::compute_statistics(g);
  const Dart d = find_dart(g, 2, false);
  const Dart b = g.alpha(d, 2);
  ASSERT_TRUE(g2::apply_separate_faces(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.darts, before.darts);
  EXPECT_EQ(after.edges, before.edges + 1);
  EXPECT_EQ(after.vertices, before.vertices + 2);
  EXPECT_EQ(after.faces, before.faces);
  EXPECT_TRUE(g.is_free(d, 2));
  EXPECT_TRUE(g.is_free(b, 2));
  // §4.1: the split vertex keeps a copy of its position; its mass is recomputed.
  auto position = g.embedding<Vec3>("position");
  auto mass = g.embedding<rift::Real>("vertex_mass");
  EXPECT_NE(position.slot(d), position.slot(b));
  EXPECT_TRUE(position[d].isApprox(position[b]));
  EXPECT_DOUBLE_EQ(mass[d], 0.25);
  EXPECT_DOUBLE_EQ(mass[b], 0.25);
}

TEST(GeneratedRules, SewingWithTwoHooksUndoesTheSeparation) {
  GMap g = grid("grid:quad:2x1");
  const auto original = rift::compute_statistics(g);
  const Dart d = find_dart(g, 2, false);
  const Dart b = g.alpha(d, 2);
  ASSERT_TRUE(g2::apply_separate_faces(g, std::span<const Dart>(&d, 1)));
  ASSERT_TRUE(apply(g2::rules()[1].apply, g, {d, b}));  // sew_edges through the registry
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.edges, original.edges);
  EXPECT_EQ(after.vertices, original.vertices);
  EXPECT_EQ(g.alpha(d, 2), b);
  EXPECT_DOUBLE_EQ(g.embedding<rift::Real>("vertex_mass")[d], 0.5);
}

TEST(GeneratedRules, RemovesAnIsolatedFaceOnly) {
  GMap g = grid("grid:quad:2x1");
  const Dart d = find_dart(g, 2, false);
  // Not isolated yet: the pattern (f -2- f) does not match and nothing changes.
  EXPECT_FALSE(g2::apply_remove_face(g, std::span<const Dart>(&d, 1)));
  EXPECT_EQ(g.size(), 16u);
  ASSERT_TRUE(g2::apply_separate_faces(g, std::span<const Dart>(&d, 1)));
  ASSERT_TRUE(g2::apply_remove_face(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.darts, 8u);
  EXPECT_EQ(after.faces, 1u);
  EXPECT_EQ(after.vertices, 4u);
}

TEST(GeneratedRules, TriangulatesAQuadAroundItsCentre) {
  GMap g = grid("grid:quad:1x1");
  const Dart d = find_dart(g, 2, true);
  ASSERT_TRUE(g2::apply_triangulate(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.darts, 24u);
  EXPECT_EQ(after.faces, 4u);
  EXPECT_EQ(after.vertices, 5u);
  EXPECT_EQ(after.edges, 8u);
  auto position = g.embedding<Vec3>("position");
  int centres = 0;
  g.for_each_cell(rift::Orbit{1, 2}, [&](Dart v) {
    if (position[v].isApprox(Vec3(0.5, 0.5, 0.0))) ++centres;
  });
  EXPECT_EQ(centres, 1);
}

TEST(GeneratedRules, InsertsAVertexInTheMiddleOfAnEdge) {
  GMap g = grid("grid:quad:1x1");
  const Dart d = find_dart(g, 2, true);
  const Vec3 mid =
      0.5 * (g.embedding<Vec3>("position")[d] + g.embedding<Vec3>("position")[g.alpha(d, 0)]);
  ASSERT_TRUE(g2::apply_insert_vertex(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.darts, 10u);
  EXPECT_EQ(after.vertices, 5u);
  EXPECT_EQ(after.edges, 5u);
  const Dart created = g.alpha(d, 0);
  EXPECT_TRUE(g.embedding<Vec3>("position")[created].isApprox(mid));
  EXPECT_DOUBLE_EQ(g.embedding<rift::Real>("vertex_mass")[created], 1.5);
}

TEST(GeneratedRules, InsertsAVertexOnAnInteriorEdge) {
  GMap g = grid("grid:quad:2x1");
  const Dart d = find_dart(g, 2, false);
  ASSERT_TRUE(g2::apply_insert_vertex(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.darts, 20u);
  EXPECT_EQ(after.vertices, 7u);
  EXPECT_EQ(after.edges, 8u);
}

TEST(GeneratedRules, RelabellingTurnsAnIsolatedFaceIntoItsDualVertex) {
  GMap g = grid("grid:quad:1x1");
  const Dart d = find_dart(g, 2, true);
  ASSERT_TRUE(g2::apply_dual(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.vertices, 1u);
  EXPECT_EQ(after.faces, 4u);
  EXPECT_TRUE(g.embedding<Vec3>("position")[d].isApprox(Vec3(0.5, 0.5, 0.0)));
  EXPECT_DOUBLE_EQ(g.embedding<rift::Real>("corner_mass")[d], 1.0);
  GMap joined = grid("grid:quad:2x1");
  const Dart inner = find_dart(joined, 2, false);
  EXPECT_FALSE(g2::apply_dual(joined, std::span<const Dart>(&inner, 1)));
  expect_valid(joined);
}

TEST(GeneratedRules, PreconditionAndParameters) {
  GMap g = grid("grid:quad:1x1");
  auto position = g.embedding<Vec3>("position");
  Dart left = rift::kNoDart, right = rift::kNoDart;
  g.for_each_dart([&](Dart d) {
    if (position[d].x() < 0.5) left = d;
    if (position[d].x() > 0.5) right = d;
  });
  g2::lift_if_right_args args;
  args.dx = 2.0;
  EXPECT_FALSE(g2::apply_lift_if_right(g, std::span<const Dart>(&left, 1), args));
  EXPECT_DOUBLE_EQ(position[left].z(), 0.0);
  ASSERT_TRUE(g2::apply_lift_if_right(g, std::span<const Dart>(&right, 1), args));
  EXPECT_DOUBLE_EQ(position[right].z(), 2.0);
  expect_valid(g);
}

TEST(GeneratedRules, ANonInjectiveMatchIsRejected) {
  GMap g = grid("grid:quad:1x1");
  const Dart d = find_dart(g, 2, true);  // b = alpha2(a) = a: not injective
  EXPECT_FALSE(g2::apply_separate_faces(g, std::span<const Dart>(&d, 1)));
  EXPECT_EQ(g.size(), 8u);
  expect_valid(g);
}

TEST(GeneratedInteractions, StretchSpringsGiveOppositeForces) {
  GMap g = grid("grid:quad:1x1");
  const auto rest = g2::interaction_stretch(g);
  EXPECT_EQ(rest.matched, 4u);
  EXPECT_NEAR(rest.energy, 0.0, 1e-12);
  auto position = g.embedding<Vec3>("position");
  const Dart moved = find_dart(g, 2, true);
  position[moved] += Vec3(0.5, 0.25, 0.0);
  const auto stretched = g2::interaction_stretch(g);
  EXPECT_GT(stretched.energy, 0.0);
  auto force = g.embedding<Vec3>("f_stretch");
  Vec3 total = Vec3::Zero();
  rift::Real largest = 0;
  g.for_each_dart([&](Dart d) {
    total += force[d];
    largest = std::max(largest, force[d].norm());
  });
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(total.norm(), 1e-9);  // action and reaction
}

TEST(GeneratedCriteria, TriggerTheirRuleWhereTheMeasurePasses) {
  GMap g = grid("grid:quad:2x1");
  // Vertical edges have length 1, horizontal ones 0.5: three edges pass 0.5,
  // and only the interior one can be separated.
  const auto result = g2::criterion_long_edge(g);
  EXPECT_EQ(result.triggered, 3u);
  EXPECT_EQ(result.applied, 1u);
  EXPECT_DOUBLE_EQ(result.max_measure, 1.0);
  expect_valid(g);
  EXPECT_EQ(rift::compute_statistics(g).boundary, 8u);
  GMap calm = grid("grid:quad:2x1");
  g2::Params params;
  params.threshold = 2.0;
  EXPECT_EQ(g2::criterion_long_edge(calm, params).triggered, 0u);
}

TEST(GeneratedRegistry, ListsEverythingByName) {
  ASSERT_EQ(g2::rules().size(), 7u);
  EXPECT_STREQ(g2::rules()[0].name, "separate_faces");
  EXPECT_EQ(g2::rules()[0].hooks, 1u);
  EXPECT_STREQ(g2::rules()[1].name, "sew_edges");
  EXPECT_EQ(g2::rules()[1].hooks, 2u);
  ASSERT_EQ(g2::interactions().size(), 1u);
  EXPECT_STREQ(g2::interactions()[0].name, "stretch");
  ASSERT_EQ(g2::criteria().size(), 1u);
  EXPECT_STREQ(g2::criteria()[0].name, "long_edge");
  EXPECT_EQ(g2::kDimension, 2);
}

TEST(GeneratedRules3D, SeparatesAndRemovesVolumes) {
  GMap g = rift::load_map("block:hex:2x1x1");
  g3::declare_embeddings(g);
  const auto before = rift::compute_statistics(g);
  const Dart d = find_dart(g, 3, false);
  ASSERT_TRUE(g3::apply_separate_volumes(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.faces, before.faces + 1);
  EXPECT_EQ(after.volumes, 2u);
  EXPECT_EQ(after.components, 2u);
  ASSERT_TRUE(g3::apply_remove_volume(g, std::span<const Dart>(&d, 1)));
  expect_valid(g);
  EXPECT_EQ(g.size(), before.darts / 2);
  EXPECT_EQ(rift::compute_statistics(g).volumes, 1u);
}

TEST(GeneratedSource, CarriesLineDirectivesIntoTheRulesFile) {
  std::ifstream in(RIFT_GEN2D_SOURCE);
  ASSERT_TRUE(in) << RIFT_GEN2D_SOURCE;
  std::stringstream text;
  text << in.rdbuf();
  const std::string source = text.str();
  EXPECT_TRUE(
      std::regex_search(source, std::regex("#line \\d+ \"[^\"]*topology2d_test\\.rules\"")));
  EXPECT_TRUE(std::regex_search(source, std::regex("#line \\d+ \"gen2d\\.cpp\"")));
}

}  // namespace
