// The rewrites of topology2d.rules and topology3d.rules applied on their own
// (vertex split, element removal), what a split vertex keeps (a copy of its
// position and velocity), and the determinism of a torn simulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

const Pack& pack_named(const std::string& name) {
  for (const auto& pack : standard_packs().packs()) {
    if (pack->name() == name) return *pack;
  }
  throw std::invalid_argument("no pack " + name);
}

/// A rule of topology2d or topology3d, the map given the embeddings it needs
/// (the scenes' components declare only their own).
std::unique_ptr<Rule> rule(GMap& map, const std::string& name) {
  const Pack& pack = pack_named(map.dimension() == 2 ? "topology2d" : "topology3d");
  declare_embeddings(map, pack.embeddings());
  return pack.make_rule(name);
}

/// A dart of the vertex at `p`.
Dart vertex_at(const Simulation& sim, const Vec3& p) {
  Dart found = kNoDart;
  sim.map().for_each_dart([&](Dart d) {
    if (found == kNoDart && (sim.position()[d] - p).norm() < 1e-9) found = d;
  });
  EXPECT_NE(found, kNoDart) << p.transpose();
  return found;
}

/// The scene set up for the rewrites these tests apply by hand (it has no
/// criterion, which would otherwise set it up for a map never rewritten).
std::unique_ptr<Simulation> simulate_rewritten(const std::string& name, const std::string& toml) {
  SetupOptions options;
  options.check_each_rewrite = true;
  options.rewrites_by_hand = true;
  return simulate(name, toml, options);
}

std::string stretch_scene(const std::string& mesh, double mass) {
  return static_scene(mesh, "1.0", mass,
                      "[[interaction]]\nname = \"stretch\"\nstiffness = 60.0\ndamping = 0.0\n");
}

bool split(Simulation& sim, Dart v, const Vec3& normal) {
  std::vector<Dart> touched;
  const Value args[] = {Value(normal), Value(sim.position()[v])};
  const bool applied = rule(sim.map(), "split_vertex")
                           ->apply(sim.map(), std::span<const Dart>(&v, 1), args, touched);
  EXPECT_TRUE(sim.map().check_validity().empty());
  sim.on_topology_changed(touched);
  return applied;
}

TEST(VertexSplit, InnerVertexOfAQuadGridSplitsInTwo) {
  // The centre of a 4 x 4 grid, split along x = 0.5: the two edges above and
  // below it are separated; their other ends stay whole (a slit: V - E + F = 0).
  auto sim = simulate_rewritten("split2d", stretch_scene("grid:quad:4x4", 1.0));
  const Counts before = counts(sim->map());
  ASSERT_EQ(before.vertices, 25u);
  ASSERT_TRUE(split(*sim, vertex_at(*sim, Vec3(0.5, 0.5, 0)), Vec3(1, 0, 0)));
  const Counts after = counts(sim->map());
  EXPECT_EQ(after.vertices, 26u);
  EXPECT_EQ(after.edges, before.edges + 2);
  EXPECT_EQ(after.faces, 16u);
  EXPECT_EQ(after.components, 1u);
  EXPECT_EQ(after.euler(), 0);
  EXPECT_NEAR(sim->total_mass(), 1.0, 1e-12);
  // A plane that leaves every face on one side splits nothing.
  EXPECT_FALSE(split(*sim, vertex_at(*sim, Vec3(0.25, 0.25, 0)), Vec3(0, 0, 1)));
  EXPECT_EQ(counts(sim->map()).vertices, 26u);
}

TEST(VertexSplit, InnerVertexOfATriangleGridSplitsAlongTheDiagonal) {
  // The inner vertex (0.5, 0.5) of grid:tri:4x4 has six triangles around it;
  // the plane x = y through it leaves three on each side, separated along
  // the two diagonal edges at it, whose other ends stay whole.
  auto sim = simulate_rewritten("split2d_tri", stretch_scene("grid:tri:4x4", 1.0));
  ASSERT_EQ(counts(sim->map()).vertices, 25u);
  ASSERT_TRUE(split(*sim, vertex_at(*sim, Vec3(0.5, 0.5, 0)), Vec3(1, -1, 0).normalized()));
  EXPECT_EQ(counts(sim->map()).vertices, 26u);
  EXPECT_EQ(counts(sim->map()).components, 1u);
  EXPECT_NEAR(sim->total_mass(), 1.0, 1e-12);
}

TEST(VertexSplit, CornerOfATriangleGridSplitsWithTheSeparatedEdges) {
  // On grid:tri:2x2 the same cut runs from corner to corner: the diagonal's
  // ends (0,0) and (1,1) lose their only link too, and the square halves.
  auto sim = simulate_rewritten("split2d_tri_small", stretch_scene("grid:tri:2x2", 1.0));
  ASSERT_TRUE(split(*sim, vertex_at(*sim, Vec3(0.5, 0.5, 0)), Vec3(1, -1, 0).normalized()));
  EXPECT_EQ(counts(sim->map()).vertices, 12u);
  EXPECT_EQ(counts(sim->map()).components, 2u);
  EXPECT_NEAR(sim->total_mass(), 1.0, 1e-12);
}

TEST(VertexSplit, InnerVertexOfAHexBlockSplitsInTwo) {
  // The centre of a 4 x 4 x 4 block, split along x = 0.5: the four faces
  // around it on that plane separate; their other vertices stay whole.
  auto sim = simulate_rewritten("split3d", stretch_scene("block:hex:4x4x4", 1.0));
  const Counts before = counts(sim->map());
  ASSERT_EQ(before.vertices, 125u);
  ASSERT_TRUE(split(*sim, vertex_at(*sim, Vec3(0.5, 0.5, 0.5)), Vec3(1, 0, 0)));
  const Counts after = counts(sim->map());
  EXPECT_EQ(after.vertices, 126u);
  EXPECT_EQ(after.faces, before.faces + 4);
  EXPECT_EQ(after.volumes, 64u);
  EXPECT_EQ(after.components, 1u);
  EXPECT_NEAR(sim->total_mass(), 1.0, 1e-12);
}

TEST(VertexSplit, HexBlockOfTwoHalvesWhenEveryFaceOfThePlaneTouchesTheVertex) {
  // In a 2 x 2 x 2 block the four faces at the centre are the whole plane
  // x = 0.5: separating them splits its nine vertices and halves the block.
  auto sim = simulate_rewritten("split3d_small", stretch_scene("block:hex:2x2x2", 1.0));
  ASSERT_TRUE(split(*sim, vertex_at(*sim, Vec3(0.5, 0.5, 0.5)), Vec3(1, 0, 0)));
  EXPECT_EQ(counts(sim->map()).vertices, 27u + 9u);
  EXPECT_EQ(counts(sim->map()).components, 2u);
  EXPECT_NEAR(sim->total_mass(), 1.0, 1e-12);
}

TEST(VertexSplit, InnerVertexOfATetBlockSplitsInTwo) {
  auto sim = simulate_rewritten("split3d_tet", stretch_scene("block:tet:4x4x4", 1.0));
  ASSERT_EQ(counts(sim->map()).vertices, 125u);
  ASSERT_TRUE(split(*sim, vertex_at(*sim, Vec3(0.5, 0.5, 0.5)), Vec3(0, 0, 1)));
  const Counts after = counts(sim->map());
  EXPECT_EQ(after.vertices, 126u);
  EXPECT_EQ(after.volumes, 384u);
  EXPECT_EQ(after.components, 1u);
  EXPECT_NEAR(sim->total_mass(), 1.0, 1e-12);
}

TEST(VertexSplit, SplitVerticesKeepTheirPositionAndVelocity) {
  for (const char* mesh : {"grid:quad:3x3", "block:hex:2x2x2"}) {
    auto sim = simulate_rewritten("split_copies", stretch_scene(mesh, 1.0));
    const int dim = sim->map().dimension();
    sim->map().for_each_cell(Orbit::cell(0, dim), [&](Dart d) {
      const Vec3 p = sim->position()[d];
      sim->velocity()[d] = Vec3(p.y() + 2 * p.z(), -p.x(), 0.5 + p.x() * p.y());
    });
    const Vec3 centre = dim == 2 ? Vec3(1.0 / 3, 1.0 / 3, 0) : Vec3(0.5, 0.5, 0.5);
    const Vec3 velocity = sim->velocity()[vertex_at(*sim, centre)];
    ASSERT_TRUE(split(*sim, vertex_at(*sim, centre), Vec3(1, 0, 0)));
    std::size_t copies = 0;
    sim->map().for_each_cell(Orbit::cell(0, dim), [&](Dart d) {
      if (sim->position()[d] != centre) return;
      ++copies;
      EXPECT_EQ(sim->velocity()[d], velocity);
    });
    EXPECT_EQ(copies, 2u) << mesh;
  }
}

TEST(ElementRemoval, MassDecreasesByExactlyTheRemovedElements) {
  // 2D: the centre quad of a 3 x 3 grid of 1 kg (1/9 kg each) leaves a hole.
  auto sim2 = simulate_rewritten("remove2d", stretch_scene("grid:quad:3x3", 1.0));
  std::vector<Dart> touched;
  Dart inner = kNoDart;  // a dart of the centre face
  sim2->map().for_each_cell(Orbit::cell(2, 2), [&](Dart d) {
    Vec3 sum = Vec3::Zero();
    sim2->map().for_each_sub_orbit(d, Orbit::cell(2, 2), Orbit::cell(0, 2),
                                   [&](Dart v) { sum += sim2->position()[v]; });
    if ((sum / 4 - Vec3(0.5, 0.5, 0)).norm() < 1e-9) inner = d;
  });
  ASSERT_NE(inner, kNoDart);
  ASSERT_TRUE(rule(sim2->map(), "remove_element")
                  ->apply(sim2->map(), std::span<const Dart>(&inner, 1), {}, touched));
  EXPECT_TRUE(sim2->map().check_validity().empty());
  sim2->on_topology_changed(touched);
  Counts c = counts(sim2->map());
  EXPECT_EQ(c.faces, 8u);
  EXPECT_EQ(c.vertices, 16u);
  EXPECT_EQ(c.euler(), 0);  // a ring
  EXPECT_NEAR(sim2->total_mass(), 8.0 / 9.0, 1e-12);

  // 3D: a corner cube of a 2 x 2 x 2 block of 1 kg.
  auto sim3 = simulate_rewritten("remove3d", stretch_scene("block:hex:2x2x2", 1.0));
  touched.clear();
  const Dart corner = vertex_at(*sim3, Vec3(0, 0, 0));
  ASSERT_TRUE(rule(sim3->map(), "remove_element")
                  ->apply(sim3->map(), std::span<const Dart>(&corner, 1), {}, touched));
  EXPECT_TRUE(sim3->map().check_validity().empty());
  sim3->on_topology_changed(touched);
  c = counts(sim3->map());
  EXPECT_EQ(c.volumes, 7u);
  EXPECT_EQ(c.vertices, 26u);
  EXPECT_EQ(c.components, 1u);
  EXPECT_NEAR(sim3->total_mass(), 7.0 / 8.0, 1e-12);
}

TEST(TearingRun, SpringSplitCopiesPositionAndVelocityOfEverySplitVertex) {
  // The first candidate of spring_split on the stretched strip, applied by
  // hand: the split vertices' copies are equal right after the split.
  auto sim = simulate("copies_strip",
                      static_scene("grid:quad:6x1", "[1.0, 0.2, 1.0]", 0.6,
                                   "[[interaction]]\nname = \"stretch\"\nstiffness = 60.0\n"
                                   "[[criterion]]\nname = \"spring_split\"\nthreshold = 2.0\n"));
  deform(*sim, [](const Vec3& p) { return p.x() > 0.55 ? Vec3(p.x() + 0.05, p.y(), p.z()) : p; });
  sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
    sim->velocity()[d] = Vec3(0.1 * sim->position()[d].y(), 0, sim->position()[d].x());
  });
  store_forces(*sim);
  apply_first_candidate(*sim);
  EXPECT_EQ(counts(sim->map()).vertices, 18u);
  std::map<std::pair<long long, long long>, std::vector<Dart>> at;
  sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
    at[{std::llround(sim->position()[d].x() * 1e9), std::llround(sim->position()[d].y() * 1e9)}]
        .push_back(d);
  });
  std::size_t pairs = 0;
  for (const auto& [key, darts] : at) {
    if (darts.size() < 2) continue;
    ++pairs;
    for (Dart d : darts) {
      EXPECT_EQ(sim->position()[d], sim->position()[darts[0]]);
      EXPECT_EQ(sim->velocity()[d], sim->velocity()[darts[0]]);
    }
  }
  EXPECT_EQ(pairs, 4u);
}

/// A small pinned cloth under gravity, torn by the global edge criterion.
std::string hanging_cloth() {
  return "[mesh]\nsource = \"grid:quad:6x6\"\nrotate = [90, 0, 0]\n"
         "[simulation]\nintegrator = \"rk4\"\ndt = 0.001\nsteps = 400\n"
         "[mass]\ntotal = 0.1\n[pin]\ncorners = [\"top-left\", \"top-right\"]\n"
         "[[interaction]]\nname = \"stretch\"\nstiffness = 60.0\ndamping = 0.1\n"
         "[[interaction]]\nname = \"shear\"\nstiffness = 43.0\ndamping = 0.1\n"
         "[[interaction]]\nname = \"bend\"\nstiffness = 10.0\ndamping = 0.1\n"
         "[[criterion]]\nname = \"global_edge\"\nthreshold = 0.06\n";
}

TEST(TearingRun, HangingClothTearsNearThePinsAndRunsAreIdentical) {
  auto a = simulate("cloth_a", hanging_cloth());
  auto b = simulate("cloth_b", hanging_cloth());
  std::size_t first_tear_step = 0;
  for (int s = 0; s < 400; ++s) {
    a->step();
    b->step();
    if (first_tear_step == 0 && a->tears() > 0) {
      first_tear_step = a->steps_done();
      // The first edges to open have a pinned top corner (z = 1) as an end.
      for (const Vec3& p : split_positions(*a))
        EXPECT_GT(p.z(), 0.6) << p.transpose();
    }
  }
  ASSERT_GT(first_tear_step, 0u) << "the cloth never tore";
  EXPECT_NEAR(a->total_mass(), 0.1, 1e-12);
  EXPECT_TRUE(a->map().check_validity().empty());
  // Deterministic: the same tears in the same order give the same state.
  EXPECT_EQ(a->tears(), b->tears());
  EXPECT_EQ(counts(a->map()).vertices, counts(b->map()).vertices);
  EXPECT_EQ(a->position().values(), b->position().values());
  EXPECT_EQ(a->velocity().values(), b->velocity().values());
}

}  // namespace
}  // namespace rift::tearing_test
