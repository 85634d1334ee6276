// Generated code applied to real G-maps: every rewrite leaves a valid map with
// the expected cell counts and embedding values (Jerboa's classic rules and
// the tearing rules of §4), interactions compute opposite forces, criteria
// trigger their rule, and the registry lists everything by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "gen2d.hpp"
#include "gen3d.hpp"
#include "rift/io/load_map.hpp"
#include "rift/mesh/map_statistics.hpp"
#include "rift/sim/mass_model.hpp"

namespace {

namespace g2 = rift::packs::gen2d;
namespace g3 = rift::packs::gen3d;
using rift::Dart;
using rift::GMap;
using rift::Vec3;

/// A grid with the pack's embeddings, a mass of 0.25 on every corner and the
/// vertex masses summed from them, as the runtime sets masses (an init cannot).
GMap grid(const char* spec) {
  GMap g = rift::load_map(spec);
  g2::declare_embeddings(g);
  g2::run_initialisers(g);
  auto corner = g.embedding<rift::Real>("corner_mass");
  g.for_each_dart([&](Dart d) { corner[d] = 0.25; });
  auto vertex = g.embedding<rift::Real>("vertex_mass");
  rift::update_all_vertex_masses(g, corner, vertex);
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
  // sew_edges through the pack's factory, as a simulator would.
  const auto sew = g2::Pack().make_rule("sew_edges");
  ASSERT_NE(sew, nullptr);
  EXPECT_EQ(sew->hook_count(), 2);
  std::vector<Dart> touched;
  const Dart hooks[] = {d, b};
  ASSERT_TRUE(sew->apply(g, hooks, {}, touched));
  EXPECT_NE(std::find(touched.begin(), touched.end(), d), touched.end());
  EXPECT_NE(std::find(touched.begin(), touched.end(), b), touched.end());
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

/// The first dart whose position is p.
Dart dart_at(const GMap& g, const Vec3& p) {
  const auto position = g.embedding<Vec3>("position");
  Dart found = rift::kNoDart;
  g.for_each_dart([&](Dart d) {
    if (found == rift::kNoDart && (position[d] - p).norm() < 1e-12) found = d;
  });
  return found;
}

TEST(GeneratedRules, HooksWithDifferentLabelsRemoveTwoFaces) {
  GMap g = grid("grid:quad:2x1");
  const Dart d = find_dart(g, 2, false);
  const Dart b = g.alpha(d, 2);
  ASSERT_TRUE(g2::apply_separate_faces(g, std::span<const Dart>(&d, 1)));
  // Not two faces: both hooks in one face make the match non-injective.
  const Dart same[] = {d, g.alpha(d, 0)};
  EXPECT_FALSE(g2::apply_remove_two_faces(g, same));
  EXPECT_EQ(g.size(), 16u);
  // a walks its face 0 then 1, b walks the other 1 then 0: both quads match.
  const Dart hooks[] = {d, b};
  ASSERT_TRUE(g2::apply_remove_two_faces(g, hooks));
  EXPECT_EQ(g.size(), 0u);
  expect_valid(g);
}

TEST(GeneratedRules, HooksWithDifferentLabelsMatchOnlyIsomorphicOrbits) {
  // A quad face (8 darts, a cycle of 0- and 1-links) corresponds to a vertex
  // of degree 4 (8 darts, a cycle of 1- and 2-links) after renaming; a
  // boundary vertex's orbit is an open chain and does not.
  GMap g = grid("grid:quad:3x3");
  auto position = g.embedding<Vec3>("position");
  const Dart f = dart_at(g, Vec3(0, 0, 0));
  ASSERT_NE(f, rift::kNoDart);
  Vec3 centre = Vec3::Zero();
  Dart x = f;
  for (int k = 0; k < 8; ++k) {  // the face orbit: alpha_0, alpha_1, ... back to f
    centre += position[x] / 8.0;
    x = g.alpha(x, k % 2);
  }
  ASSERT_EQ(x, f);
  // The grid spans the unit square, three cells a side.
  for (const Vec3& boundary : {Vec3(1, 0, 0), Vec3(2.0 / 3, 0, 0)}) {  // degree 2, degree 3
    const Dart v = dart_at(g, boundary);
    ASSERT_NE(v, rift::kNoDart);
    const Dart hooks[] = {f, v};
    EXPECT_FALSE(g2::apply_vertex_to_face_centre(g, hooks)) << boundary.transpose();
    EXPECT_EQ(position[v], boundary);
  }
  const Dart v = dart_at(g, Vec3(2.0 / 3, 2.0 / 3, 0));
  ASSERT_NE(v, rift::kNoDart);
  const Dart hooks[] = {f, v};
  ASSERT_TRUE(g2::apply_vertex_to_face_centre(g, hooks));
  expect_valid(g);
  EXPECT_TRUE(position[v].isApprox(centre)) << position[v].transpose();
  EXPECT_EQ(position[f], Vec3(0, 0, 0));  // the face did not move
  Dart y = v;                             // every dart of the vertex sees the new position
  for (int k = 0; k < 8; ++k) {
    EXPECT_TRUE(position[y].isApprox(centre)) << k;
    y = g.alpha(y, 1 + k % 2);
  }
  EXPECT_EQ(y, v);
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

TEST(GeneratedRules, TouchedDartsCoverTheRewrite) {
  GMap g = grid("grid:quad:2x1");
  const Dart d = find_dart(g, 2, false);
  const Dart b = g.alpha(d, 2);
  std::vector<Dart> touched;
  ASSERT_TRUE(g2::apply_separate_faces(g, std::span<const Dart>(&d, 1), {}, {}, &touched));
  // Both sides of the edge were relinked.
  for (Dart x : {d, g.alpha(d, 0), b, g.alpha(b, 0)})
    EXPECT_NE(std::find(touched.begin(), touched.end(), x), touched.end()) << x;
  // A rule that does not apply touches nothing.
  touched.clear();
  EXPECT_FALSE(g2::apply_separate_faces(g, std::span<const Dart>(&d, 1), {}, {}, &touched));
  EXPECT_TRUE(touched.empty());
}

TEST(GeneratedInteractions, StretchKernelGivesOppositeForces) {
  GMap g = grid("grid:quad:1x1");
  g2::StretchInteraction stretch(g2::StretchParams{10.0, 0.0});
  stretch.initialise(g);
  EXPECT_EQ(stretch.active_matches(), 4u);
  EXPECT_EQ(g2::StretchKernel::kRadius, 1);
  auto position = g.embedding<Vec3>("position");
  auto velocity = g.embedding<Vec3>("velocity");
  std::vector<Vec3> f(position.values().size(), Vec3::Zero());
  const rift::ForceInput rest{position.values().data(), velocity.values().data()};
  stretch.add_forces(rest, f.data(), true);
  EXPECT_NEAR(stretch.potential_energy(rest), 0.0, 1e-12);
  for (const Vec3& v : f)
    EXPECT_LT(v.norm(), 1e-12);
  // The kernel reads the stage arrays it is given, not the map's positions.
  std::vector<Vec3> x = position.values();
  const Dart moved = find_dart(g, 2, true);
  x[position.slot(moved)] += Vec3(0.5, 0.25, 0.0);
  const rift::ForceInput stage{x.data(), velocity.values().data()};
  std::fill(f.begin(), f.end(), Vec3::Zero());
  stretch.add_forces(stage, f.data(), true);
  EXPECT_GT(stretch.potential_energy(stage), 0.0);
  Vec3 total = Vec3::Zero();
  for (const Vec3& v : f)
    total += v;
  EXPECT_GT(f[position.slot(moved)].norm(), 0.1);
  EXPECT_LT(total.norm(), 1e-9);  // action and reaction
  // Stored per dart (Table 1): the two ends of a half-edge hold opposite forces.
  auto stored = g.embedding<Vec3>("f_stretch");
  EXPECT_GT(stored[moved].norm(), 0.1);
  EXPECT_LT((stored[moved] + stored[g.alpha(moved, 0)]).norm(), 1e-12);
}

TEST(GeneratedInteractions, TaggedElementsAreMatchedFromTheirFirstDart) {
  GMap g = grid("grid:tri:2x2");
  g2::AreaInteraction area;
  area.initialise(g);
  EXPECT_TRUE(g2::AreaKernel::kTagged);
  EXPECT_EQ(area.active_matches(), 8u);
  // Whatever dart of a triangle the match starts from, it reaches the same
  // corners in the same order: the one tagged at initialisation.
  const g2::AreaKernel& kernel = area.kernel();
  std::size_t checked = 0;
  g.for_each_cell(g2::AreaKernel::kSupport, [&](Dart face) {
    g2::AreaKernel::Match first{};
    ASSERT_TRUE(kernel.match(g, face, first));
    g.for_each_in_orbit(face, g2::AreaKernel::kSupport, [&](Dart x) {
      g2::AreaKernel::Match m{};
      ASSERT_TRUE(kernel.match(g, x, m));
      EXPECT_EQ(std::memcmp(&m, &first, sizeof m), 0);
      ++checked;
    });
  });
  EXPECT_EQ(checked, g.size());
  // So the rest shape computed at initialisation gives no force at rest.
  auto position = g.embedding<Vec3>("position");
  auto velocity = g.embedding<Vec3>("velocity");
  std::vector<Vec3> f(position.values().size(), Vec3::Zero());
  area.add_forces({position.values().data(), velocity.values().data()}, f.data(), false);
  for (const Vec3& v : f)
    EXPECT_LT(v.norm(), 1e-12);
}

TEST(GeneratedCriteria, ProposeCandidatesAndApplyTheirRule) {
  GMap g = grid("grid:quad:2x1");
  // Vertical edges have length 1, horizontal ones 0.5: three edges pass 0.5,
  // and only the interior one can be separated.
  g2::LongEdgeCriterion criterion;
  criterion.initialise(g);
  std::vector<rift::TearCandidate> candidates;
  criterion.collect(g, candidates);
  ASSERT_EQ(candidates.size(), 3u);
  std::size_t applied = 0;
  std::vector<Dart> touched;
  for (const auto& c : candidates) {
    EXPECT_DOUBLE_EQ(c.measure, 0.5);  // length 1 passed the limit 0.5 by 0.5
    if (criterion.apply(g, c, touched)) ++applied;
  }
  EXPECT_EQ(applied, 1u);
  EXPECT_FALSE(touched.empty());
  expect_valid(g);
  EXPECT_EQ(rift::compute_statistics(g).boundary, 8u);
  GMap calm = grid("grid:quad:2x1");
  g2::LongEdgeCriterion strict(g2::LongEdgeParams{2.0});
  strict.initialise(calm);
  candidates.clear();
  strict.collect(calm, candidates);
  EXPECT_TRUE(candidates.empty());
}

TEST(GeneratedCriteria, MeasureWrittenWithLessThanPutsTheSmallestFirst) {
  // Vertical edges have length 1, horizontal ones 0.5: with `length < 2` all
  // pass, and the shorter ones are the more critical, so they must carry the
  // larger measure (the simulation applies larger measures first, which
  // decides which tears happen under max_per_step).
  GMap g = grid("grid:quad:2x1");
  g2::ShortEdgeCriterion criterion;
  criterion.initialise(g);
  std::vector<rift::TearCandidate> candidates;
  criterion.collect(g, candidates);
  ASSERT_EQ(candidates.size(), 7u);
  auto position = g.embedding<Vec3>("position");
  for (const auto& c : candidates) {
    const double length = (position[g.alpha(c.at, 0)] - position[c.at]).norm();
    EXPECT_DOUBLE_EQ(c.measure, 2.0 - length);
  }
  const auto most =
      std::max_element(candidates.begin(), candidates.end(),
                       [](const rift::TearCandidate& a, const rift::TearCandidate& b) {
                         return a.measure < b.measure;
                       });
  EXPECT_DOUBLE_EQ((position[g.alpha(most->at, 0)] - position[most->at]).norm(), 0.5);
}

TEST(GeneratedPack, ListsEverythingByName) {
  const g2::Pack pack;
  EXPECT_EQ(pack.name(), "gen2d");
  EXPECT_EQ(pack.dimension(), 2);
  const auto rules = pack.rule_names();
  ASSERT_EQ(rules.size(), 9u);
  EXPECT_EQ(rules[0], "separate_faces");
  EXPECT_EQ(pack.make_rule("separate_faces")->hook_count(), 1);
  EXPECT_EQ(pack.make_rule("sew_edges")->hook_count(), 2);
  EXPECT_EQ(pack.make_rule("nope"), nullptr);
  ASSERT_EQ(pack.catalog().interactions.size(), 4u);
  EXPECT_EQ(pack.catalog().interactions[0].name, "stretch");
  EXPECT_EQ(pack.catalog().interactions[3].name, "chain");
  ASSERT_EQ(pack.catalog().criteria.size(), 2u);
  EXPECT_EQ(pack.catalog().criteria[0].name, "long_edge");
  EXPECT_EQ(g2::kDimension, 2);
  // The tag of the tagged interaction is one of the pack's embeddings.
  bool tag = false;
  for (const auto& e : pack.embeddings())
    tag = tag || (e.name == "area_first_dart" && e.type == rift::ValueType::kBool);
  EXPECT_TRUE(tag);
}

TEST(GeneratedPack, RuleArgumentsAreCheckedAtRunTime) {
  GMap g = grid("grid:quad:2x1");
  const auto lift = g2::Pack().make_rule("lift_if_right");
  ASSERT_EQ(lift->params().size(), 1u);
  EXPECT_EQ(lift->params()[0].name, "dx");
  std::vector<Dart> touched;
  const Dart right = find_dart(g, 2, true);
  EXPECT_THROW(lift->apply(g, std::span<const Dart>(&right, 1), {}, touched),
               std::invalid_argument);
  const rift::Value wrong[] = {rift::Value(Vec3(Vec3::Zero()))};
  EXPECT_THROW(lift->apply(g, std::span<const Dart>(&right, 1), wrong, touched),
               std::invalid_argument);
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
