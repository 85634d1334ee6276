// Identical matches evaluated once (runtime/rift/sim/match_groups.hpp, issue
// 12 deliverable 2): the grouped force pass gives the forces of the
// ungrouped one (to rounding), stores every member's atomic forces exactly,
// keeps apart matches whose parameters differ, and follows tears.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "physics_setup.hpp"
#include "rift/core/parallel.hpp"
#include "rift/core/prefetch.hpp"
#include "rift/sim/distinct_keys.hpp"
#include "rift/sim/match_groups.hpp"
#include "same_bits.hpp"

namespace rift::physics_test {
namespace {

using Stretch2d = packs::mass_spring2d::StretchInteraction;
using Bend2d = packs::mass_spring2d::BendInteraction;

std::unique_ptr<Simulation> make(GMap map, const std::vector<Use>& interactions, bool grouped,
                                 const std::vector<Use>& criteria = {}) {
  SimSetup setup;
  setup.settings.group_interactions = grouped;
  setup.interactions = interactions;
  setup.criteria = criteria;
  return simulate(std::move(map), setup);
}

Real largest(const std::vector<Vec3>& f) {
  Real m = 0;
  for (const Vec3& x : f)
    m = std::max(m, x.norm());
  return m;
}

std::size_t evaluated(const Simulation& sim) {
  std::size_t n = 0;
  for (const auto& m : sim.force_models())
    n += m->evaluated_matches();
  return n;
}
std::size_t matched(const Simulation& sim) {
  std::size_t n = 0;
  for (const auto& m : sim.force_models())
    n += m->active_matches();
  return n;
}

/// The forces of a grouped and an ungrouped simulation of one map, deformed
/// alike: equal to 1e-12 of the largest; then a storing pass, whose stored
/// atomic forces must be equal dart by dart, bit for bit (each match is
/// evaluated from the same dart either way, and a group's members share
/// their key, so their stored values are each member's own).
void expect_same(Simulation& grouped, Simulation& plain, const std::vector<std::string>& stored,
                 unsigned seed) {
  deform(grouped, seed, 0.05);
  deform(plain, seed, 0.05);
  const std::vector<Vec3> fg = internal_forces(grouped);
  const std::vector<Vec3> fp = internal_forces(plain);
  ASSERT_EQ(fg.size(), fp.size());
  const Real tol = 1e-12 * largest(fp);
  ASSERT_GT(largest(fp), 0);
  for (std::size_t s = 0; s < fp.size(); ++s)
    ASSERT_LE((fg[s] - fp[s]).norm(), tol) << "vertex slot " << s << ", seed " << seed;
  for (Simulation* sim : {&grouped, &plain}) {
    std::vector<Vec3> f(sim->position().values().size(), Vec3::Zero());
    const ForceInput in{sim->position().values().data(), sim->velocity().values().data()};
    for (const auto& m : sim->force_models())
      m->add_forces(in, f.data(), true);
  }
  for (const std::string& name : stored) {
    const auto a = grouped.map().embedding<Vec3>(name);
    const auto b = plain.map().embedding<Vec3>(name);
    ASSERT_TRUE(a && b) << name;
    ASSERT_EQ(a.values().size(), b.values().size()) << name;
    std::size_t nonzero = 0;
    for (std::size_t s = 0; s < a.values().size(); ++s) {
      ASSERT_EQ(a.values()[s], b.values()[s]) << name << " slot " << s << ", seed " << seed;
      nonzero += a.values()[s] != Vec3::Zero() ? 1 : 0;
    }
    EXPECT_GT(nonzero, 0u) << name;
  }
}

/// Cuts the map along `cuts` random interior (n-1)-cells (an edge of a
/// surface, a face of a volume): the same cells in both simulations, whose
/// maps were built alike, then announced like a tear.
void cut_alike(Simulation& grouped, Simulation& plain, int cuts, unsigned seed) {
  GMap& g = grouped.map();
  const int n = g.dimension();
  const Orbit cell = Orbit::cell(n - 1, n);  // the cut cell, both sides
  std::mt19937 rng(seed);
  for (int c = 0; c < cuts; ++c) {
    Dart d = kNoDart;
    for (int attempt = 0; attempt < 10000 && d == kNoDart; ++attempt) {
      const Dart x = static_cast<Dart>(rng() % g.capacity());
      if (g.is_alive(x) && !g.is_free(x, n)) d = x;
    }
    ASSERT_NE(d, kNoDart);
    std::vector<Dart> touched;
    g.for_each_in_orbit(d, cell, [&](Dart x) { touched.push_back(x); });
    for (Simulation* sim : {&grouped, &plain}) {
      sim->map().unsew(d, n);
      ASSERT_TRUE(sim->map().is_valid());
      sim->on_topology_changed(touched);
    }
  }
}

/// Grouped and ungrouped simulations of one mesh give the same forces and
/// store the same atomic forces, before and after random cuts.
void expect_same_forces(const MeshData& mesh, const std::vector<Use>& interactions,
                        const std::vector<std::string>& stored) {
  auto grouped = make(assemble_gmap(mesh), interactions, true);
  auto plain = make(assemble_gmap(mesh), interactions, false);
  EXPECT_EQ(matched(*grouped), matched(*plain));
  EXPECT_LT(evaluated(*grouped), evaluated(*plain)) << "nothing was grouped";
  EXPECT_EQ(evaluated(*plain), matched(*plain));
  for (unsigned seed = 1; seed <= 3; ++seed)
    expect_same(*grouped, *plain, stored, seed);
  for (unsigned round = 1; round <= 3; ++round) {
    cut_alike(*grouped, *plain, 4, 100 + round);
    EXPECT_EQ(matched(*grouped), matched(*plain));
    EXPECT_LT(evaluated(*grouped), evaluated(*plain));
    expect_same(*grouped, *plain, stored, 10 + round);
  }
}

TEST(Grouping, QuadClothGivesTheUngroupedForces) {
  expect_same_forces(make_grid(GridKind::Quad, 10, 10), paper_cloth_springs(),
                     {"f_stretch", "f_shear", "f_bend"});
}

TEST(Grouping, TriangleClothGivesTheUngroupedForces) {
  expect_same_forces(make_grid(GridKind::Tri, 10, 10),
                     {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}},
                      {"bend", {{"stiffness", 10.0}, {"damping", 0.1}}},
                      {"angular_shear", {{"stiffness", 0.1}, {"damping", 0.01}}}},
                     {"f_stretch", "f_bend", "f_ashear", "f_ashear_end"});
}

TEST(Grouping, HexahedraGiveTheUngroupedForces) {
  expect_same_forces(make_block(BlockKind::Hex, 3, 3, 3),
                     {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}},
                      {"shear", {{"stiffness", 43.0}, {"damping", 0.1}}},
                      {"volume_shear", {{"stiffness", 43.0}, {"damping", 0.1}}}},
                     {"f_stretch", "f_shear", "f_volume_shear"});
}

// A hexahedral block's face shear springs (tagged: each volume lists its
// face from its own dart) and body diagonals have keys of their own, and are
// told so without building their groups (rift/sim/distinct_keys.hpp): the
// plain pass, as a build of their groups would decide. The block's shear has
// more matches than the prefix the check reads first.
TEST(Grouping, MatchesWithKeysOfTheirOwnAreNotGrouped) {
  using Shear3d = packs::mass_spring3d::ShearInteraction;
  using VolumeShear3d = packs::mass_spring3d::VolumeShearInteraction;
  using Stretch3d = packs::mass_spring3d::StretchInteraction;
  auto sim = make(assemble_gmap(make_block(BlockKind::Hex, 16, 16, 12)),
                  {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}},
                   {"shear", {{"stiffness", 43.0}, {"damping", 0.1}}},
                   {"volume_shear", {{"stiffness", 43.0}, {"damping", 0.1}}}},
                  true);
  // Groups built from the same matches and keys.
  auto built_groups = [](auto& model) {
    using Match = std::decay_t<decltype(model.cache().matches()[0])>;
    MatchGroups<Match> groups;
    typename MatchGroups<Match>::NoObserver none;
    auto& kernel = model.kernel();
    groups.build(
        model.cache().matches(), std::decay_t<decltype(kernel)>::kGroupKey,
        [&](const Match& m, std::uint64_t* out) { kernel.group_key(m, out); }, none);
    return groups.size();
  };
  int seen = 0;
  for (auto& model : sim->force_models()) {
    if (auto* q = dynamic_cast<Shear3d*>(model.get())) {
      ASSERT_GT(q->cache().size(), kDistinctKeysPrefix);
      EXPECT_FALSE(q->grouped());
      EXPECT_EQ(q->evaluated_matches(), q->active_matches());
      EXPECT_EQ(built_groups(*q), q->cache().size());
      ++seen;
    } else if (auto* v = dynamic_cast<VolumeShear3d*>(model.get())) {
      EXPECT_FALSE(v->grouped());
      EXPECT_EQ(built_groups(*v), v->cache().size());
      ++seen;
    } else if (auto* s = dynamic_cast<Stretch3d*>(model.get())) {
      EXPECT_TRUE(s->grouped());
      EXPECT_LT(s->evaluated_matches(), s->active_matches());
      // Its key table is sized for the groups (about one per eight matches
      // here), not for half the matches (MatchGroups::expected_groups).
      ASSERT_GT(s->cache().size(),
                MatchGroups<std::decay_t<decltype(s->cache().matches()[0])>>::kSample);
      EXPECT_LT(s->groups().table_size(), s->cache().size());
      EXPECT_GE(s->groups().table_size(), 2 * s->groups().size() + 2);
      ++seen;
    }
  }
  EXPECT_EQ(seen, 3);
}

// The paper's 10 × 10 quad cloth: 960 atomic springs (400 stretch, 360
// bend, 100 shear matches of two diagonals each), 618 distinct ones
// (tests/reference's cumulated cloth: 220 stretch, 200 shear, 198 bend).
TEST(Grouping, QuadClothEvaluatesEachVertexPairOnce) {
  auto sim = make(assemble_gmap(make_grid(GridKind::Quad, 10, 10)), paper_cloth_springs(), true);
  EXPECT_EQ(matched(*sim), 400u + 100u + 360u);
  EXPECT_EQ(evaluated(*sim), 220u + 100u + 198u);
}

// Every member of a group stores exactly (bit for bit) what its own
// evaluation gives.
TEST(Grouping, StoredAtomicForcesAreEachMembersOwn) {
  auto sim = make(assemble_gmap(make_grid(GridKind::Quad, 6, 6)), paper_cloth_springs(), true);
  deform(*sim, 7, 0.05);
  const ForceInput in{sim->position().values().data(), sim->velocity().values().data()};
  std::vector<Vec3> f(sim->position().values().size(), Vec3::Zero());
  for (const auto& m : sim->force_models())
    m->add_forces(in, f.data(), true);
  const auto stretch = sim->map().embedding<Vec3>("f_stretch");
  const auto bend = sim->map().embedding<Vec3>("f_bend");
  int checked = 0;
  for (const auto& model : sim->force_models()) {
    if (auto* s = dynamic_cast<Stretch2d*>(model.get())) {
      ASSERT_TRUE(s->grouped());
      // The stored-force slots are kept beside the matches (Stored).
      ASSERT_EQ(s->stored().size(), s->cache().size());
      for (std::size_t e = 0; e < s->cache().size(); ++e) {
        Vec3 t[2];
        s->kernel().evaluate_terms(s->cache().matches()[e], in, t);
        ASSERT_EQ(stretch.values()[s->stored()[e].dart_a], t[0]);
        ASSERT_EQ(stretch.values()[s->stored()[e].dart_b], t[1]);
        ++checked;
      }
    }
    if (auto* b = dynamic_cast<Bend2d*>(model.get())) {
      ASSERT_EQ(b->stored().size(), b->cache().size());
      for (std::size_t e = 0; e < b->cache().size(); ++e) {
        Vec3 t[2];
        b->kernel().evaluate_terms(b->cache().matches()[e], in, t);
        ASSERT_EQ(bend.values()[b->stored()[e].dart_l], t[0]);
        ASSERT_EQ(bend.values()[b->stored()[e].dart_r], t[1]);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

// One face's stretch spring stiffer than its twin across the edge: the two
// no longer group, and the forces still equal the ungrouped ones.
TEST(Grouping, DifferentParametersDoNotGroup) {
  const MeshData mesh = make_grid(GridKind::Quad, 4, 4);
  const std::vector<Use> springs = {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}}};
  auto grouped = make(assemble_gmap(mesh), springs, true);
  auto plain = make(assemble_gmap(mesh), springs, false);
  const std::size_t before = evaluated(*grouped);
  // An interior half-edge: a dart whose α2 is another dart.
  Dart edge = kNoDart;
  grouped->map().for_each_cell(Orbit{0}, [&](Dart d) {
    if (edge == kNoDart && grouped->map().alpha(d, 2) != d) edge = d;
  });
  ASSERT_NE(edge, kNoDart);
  for (auto* sim : {grouped.get(), plain.get()}) {
    auto k = sim->map().embedding<Real>("stretch_k");
    k[edge] = 3 * k[edge];
    // Parameters changed outside a rewrite are announced like a rewrite.
    const Dart touched[] = {edge};
    sim->on_topology_changed(touched);
  }
  EXPECT_EQ(evaluated(*grouped), before + 1);
  deform(*grouped, 3, 0.05);
  deform(*plain, 3, 0.05);
  const std::vector<Vec3> fg = internal_forces(*grouped);
  const std::vector<Vec3> fp = internal_forces(*plain);
  for (std::size_t s = 0; s < fp.size(); ++s)
    ASSERT_LE((fg[s] - fp[s]).norm(), 1e-12 * largest(fp)) << "slot " << s;
}

// After random tears the groups are those a fresh grouping of the matches
// gives, and the grouped forces are the sum of every match's own.
/// The paper cloth's forces as the grouped passes give them against the plain
/// sum of every stretch and bend match's own forces (shear: no two faces
/// share a diagonal, its pass is the sum): equal to 1e-12 of the largest.
void expect_grouped_forces_sum_the_matches(const Simulation& sim) {
  const ForceInput in{sim.position().values().data(), sim.velocity().values().data()};
  std::vector<Vec3> fg(sim.position().values().size(), Vec3::Zero());
  std::vector<Vec3> fp = fg;
  for (const auto& model : sim.force_models()) {
    model->add_forces(in, fg.data(), false);
    if (auto* s = dynamic_cast<Stretch2d*>(model.get())) {
      for (const auto& m : s->cache().matches()) {
        Vec3 t[2];
        s->kernel().evaluate_terms(m, in, t);
        fp[m.vertex_a] += t[0];
        fp[m.vertex_b] += t[1];
      }
    } else if (auto* b = dynamic_cast<Bend2d*>(model.get())) {
      for (const auto& m : b->cache().matches()) {
        Vec3 t[2];
        b->kernel().evaluate_terms(m, in, t);
        fp[m.vertex_l] += t[0];
        fp[m.vertex_r] += t[1];
      }
    } else {
      model->add_forces(in, fp.data(), false);
    }
  }
  const Real tolerance = 1e-12 * largest(fp);
  ASSERT_GT(tolerance, 0);
  for (std::size_t s = 0; s < fp.size(); ++s)
    ASSERT_LE((fg[s] - fp[s]).norm(), tolerance) << "slot " << s;
}

TEST(Grouping, GroupsFollowTears) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri}) {
    SimSetup setup;
    setup.interactions = paper_cloth_springs();
    // Triangles: no quad, no shear.
    if (kind == GridKind::Tri) setup.interactions.erase(setup.interactions.begin() + 1);
    setup.criteria = {{"spring_split", {{"threshold", 0.5}}}};
    setup.settings.max_tears_per_step = 3;
    setup.settings.dt = 1e-4;
    auto sim = simulate(assemble_gmap(make_grid(kind, 12, 12)), setup);
    // Stretched: every spring pulls, the criterion picks among many.
    move_vertices(*sim, [](const Vec3& x) { return Vec3(1.3 * x.x(), 1.3 * x.y(), x.z()); });
    for (int step = 0; step < 8; ++step) {
      sim->step();
      for (const auto& model : sim->force_models()) {
        if (auto* s = dynamic_cast<Stretch2d*>(model.get())) {
          ASSERT_EQ(s->check_groups(), "") << "step " << step;
          const auto reps = s->groups().representatives();
          ASSERT_EQ(s->colouring().check(
                        reps.size(), 2,
                        [&](std::size_t g, Slot* out) { s->kernel().force_targets(reps[g], out); }),
                    "")
              << "step " << step;
          // A fresh grouping of the same matches has as many groups.
          using Match = packs::mass_spring2d::StretchKernel::Match;
          MatchGroups<Match> fresh;
          MatchGroups<Match>::NoObserver none;
          fresh.build(
              s->cache().matches(), packs::mass_spring2d::StretchKernel::kGroupKey,
              [&](const auto& m, std::uint64_t* out) { s->kernel().group_key(m, out); }, none);
          ASSERT_EQ(fresh.size(), s->groups().size()) << "step " << step;
        }
      }
      // Grouped forces against the plain sum of every match's own forces.
      expect_grouped_forces_sum_the_matches(*sim);
      if (HasFatalFailure()) return;
    }
    EXPECT_GT(sim->tears(), 0u);
  }
}

// A re-match on a map of kPrefetchFromDarts darts or more first asks for the
// entries, groups and slots it will read (rift/core/prefetch.hpp): the tears
// and cuts of such a cloth must leave the same groups, colouring and forces as the
// small cloths of GroupsFollowTears, and a valid map.
TEST(Grouping, TearsOfAMapPastThePrefetchSizeKeepGroupsAndForces) {
  SimSetup setup;
  setup.interactions = paper_cloth_springs();
  setup.criteria = {{"spring_split", {{"threshold", 1e-9}}}};
  auto sim = simulate(assemble_gmap(make_grid(GridKind::Quad, 260, 260)), setup);
  ASSERT_GE(sim->map().capacity(), kPrefetchFromDarts) << "the cloth no longer takes that path";
  move_vertices(*sim, [](const Vec3& x) { return Vec3(1.1 * x.x(), 1.05 * x.y(), x.z()); });
  const ForceInput in{sim->position().values().data(), sim->velocity().values().data()};
  std::vector<Vec3> f(sim->position().values().size(), Vec3::Zero());
  for (const auto& m : sim->force_models())
    m->add_forces(in, f.data(), true);
  std::vector<TearCandidate> candidates;
  sim->criteria()[0]->collect(sim->map(), candidates);
  ASSERT_GT(candidates.size(), 1000u);
  std::size_t tears = 0;
  std::vector<Dart> touched;
  // Spread over the cloth, as the tear benchmark does.
  for (std::size_t k = 0; k < 60; ++k) {
    if (tear_at(*sim, candidates[(k * 7919) % candidates.size()], touched)) ++tears;
  }
  ASSERT_GT(tears, 30u);
  // Cuts along random interior edges too: their matches are dropped, which
  // moves the last entries and groups into the holes.
  GMap& map = sim->map();
  std::mt19937 rng(7);
  for (int c = 0; c < 40; ++c) {
    Dart d = kNoDart;
    while (d == kNoDart) {
      const Dart x = static_cast<Dart>(rng() % map.capacity());
      if (map.is_alive(x) && !map.is_free(x, 2)) d = x;
    }
    touched.clear();
    map.for_each_in_orbit(d, Orbit::cell(1, 2), [&](Dart x) { touched.push_back(x); });
    map.unsew(d, 2);
    sim->on_topology_changed(touched);
  }
  ASSERT_TRUE(sim->map().is_valid());
  for (const auto& model : sim->force_models()) {
    if (auto* s = dynamic_cast<Stretch2d*>(model.get())) {
      ASSERT_EQ(s->check_groups(), "");
      const auto reps = s->groups().representatives();
      ASSERT_EQ(s->colouring().check(
                    reps.size(), 2,
                    [&](std::size_t g, Slot* out) { s->kernel().force_targets(reps[g], out); }),
                "");
    } else if (auto* b = dynamic_cast<Bend2d*>(model.get())) {
      ASSERT_EQ(b->check_groups(), "");
    }
  }
  expect_grouped_forces_sum_the_matches(*sim);
}

// The inits choose each support orbit's dart and hand it to the match cache
// as they go (rift/sim/support_sink.hpp): the cache must hold, in order,
// exactly the orbits a walk of the cells matches from the dart support_dart
// chooses, owned by that dart, with its match.
template <class Interaction>
void expect_owners_chosen_by_support_dart(const Simulation& sim, Interaction& it) {
  using Kernel = std::decay_t<decltype(it.kernel())>;
  const GMap& map = sim.map();
  std::vector<Dart> owners;
  std::vector<typename Kernel::Match> matches;
  map.for_each_cell(Kernel::kSupport, [&](Dart cell) {
    const Dart d = it.kernel().support_dart(map, cell);
    typename Kernel::Match m{};
    if (!it.kernel().match(map, d, m)) return;
    owners.push_back(d);
    matches.push_back(m);
  });
  const auto got = it.cache().owners();
  ASSERT_EQ(std::vector<Dart>(got.begin(), got.end()), owners) << it.name();
  const auto built = it.cache().matches();
  ASSERT_EQ(built.size(), matches.size()) << it.name();
  for (std::size_t e = 0; e < matches.size(); ++e) {
    Slot a[2], b[2];
    it.kernel().force_targets(built[e], a);
    it.kernel().force_targets(matches[e], b);
    ASSERT_TRUE(a[0] == b[0] && a[1] == b[1]) << it.name() << " entry " << e;
  }
}

TEST(Grouping, OrbitsAreMatchedFromTheDartsTheInitsChose) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri}) {
    SimSetup setup;
    setup.interactions = paper_cloth_springs();
    if (kind == GridKind::Tri) setup.interactions.erase(setup.interactions.begin() + 1);
    setup.criteria = {{"spring_split", {{"threshold", 0.5}}}};  // keeps the owners
    auto sim = simulate(assemble_gmap(make_grid(kind, 7, 5)), setup);
    int checked = 0;
    for (const auto& model : sim->force_models()) {
      if (auto* s = dynamic_cast<Stretch2d*>(model.get())) {
        expect_owners_chosen_by_support_dart(*sim, *s);
        ++checked;
      } else if (auto* b = dynamic_cast<Bend2d*>(model.get())) {
        expect_owners_chosen_by_support_dart(*sim, *b);
        ++checked;
      }
    }
    EXPECT_EQ(checked, 2);
  }
}

// The inits of a tagged kernel (the corners' order fixed by the dart an
// element is first matched from, §3.2) hand the darts they found to the
// match cache too: the cache must hold, in order, the match of each support
// orbit from its first dart, as a walk of the cells finds it, owned by that
// dart when the map is rewritten. Whole matches are compared, every slot.
template <class Interaction>
void expect_matches_of_each_first_dart(const Simulation& sim, ForceModel& model) {
  auto* it = dynamic_cast<Interaction*>(&model);
  ASSERT_NE(it, nullptr) << model.name();
  using Kernel = std::decay_t<decltype(it->kernel())>;
  using Match = typename Kernel::Match;
  static_assert(std::has_unique_object_representations_v<Match>);
  const GMap& map = sim.map();
  std::vector<Dart> owners;
  std::vector<Match> matches;
  map.for_each_cell(Kernel::kSupport, [&](Dart cell) {
    Match m{};
    if (!it->kernel().match(map, cell, m)) return;
    owners.push_back(cell);
    matches.push_back(m);
  });
  ASSERT_FALSE(matches.empty()) << model.name();
  const auto built = it->cache().matches();
  ASSERT_EQ(built.size(), matches.size()) << model.name();
  for (std::size_t e = 0; e < matches.size(); ++e)
    ASSERT_EQ(std::memcmp(&built[e], &matches[e], sizeof(Match)), 0) << model.name() << " " << e;
  if (it->cache().keeps_owners()) {
    const auto got = it->cache().owners();
    ASSERT_EQ(std::vector<Dart>(got.begin(), got.end()), owners) << model.name();
  }
}

TEST(Grouping, TaggedOrbitsAreMatchedFromTheDartsTheInitsFound) {
  using Shear3d = packs::mass_spring3d::ShearInteraction;
  using VolumeShear3d = packs::mass_spring3d::VolumeShearInteraction;
  using Corotational3d = packs::fem3d::CorotationalInteraction;
  for (const bool rewritten : {false, true}) {
    SimSetup hex;
    hex.interactions = {{"shear", {}}, {"volume_shear", {}}};
    hex.settings.rewrites = rewritten;
    auto block = simulate(assemble_gmap(make_block(BlockKind::Hex, 3, 2, 2)), hex);
    ASSERT_EQ(block->force_models().size(), 2u);
    expect_matches_of_each_first_dart<Shear3d>(*block, *block->force_models()[0]);
    expect_matches_of_each_first_dart<VolumeShear3d>(*block, *block->force_models()[1]);

    SimSetup tet;
    tet.interactions = {{"corotational", {}}};
    tet.settings.rewrites = rewritten;
    auto beam = simulate(assemble_gmap(make_block(BlockKind::Tet, 3, 2, 2)), tet);
    ASSERT_EQ(beam->force_models().size(), 1u);
    expect_matches_of_each_first_dart<Corotational3d>(*beam, *beam->force_models()[0]);
  }
}

// A tear leaves the scatter's block out of order (an erased group's place
// taken by the last one): the grouped pass then reads that block's groups in
// place through its entries. Storing or not, it must add exactly what the
// colouring's order gives — count × each representative's terms, group after
// group, block after block — and store each member's own terms. (A colouring
// of one block stays in order through tears, so the cloth has more springs
// than a block holds: 40 × 40 quads, 3 280 edges, two blocks of at most 2 048;
// its springs, shorter, pull less, hence a lower threshold.)
TEST(Grouping, ABlockATearReshuffledIsEvaluatedInItsOrder) {
  SimSetup setup;
  setup.interactions = paper_cloth_springs();
  setup.criteria = {{"spring_split", {{"threshold", 0.15}}}};
  setup.settings.max_tears_per_step = 3;
  setup.settings.dt = 1e-4;
  auto sim = simulate(assemble_gmap(make_grid(GridKind::Quad, 40, 40)), setup);
  move_vertices(*sim, [](const Vec3& x) { return Vec3(1.3 * x.x(), 1.3 * x.y(), x.z()); });
  for (int step = 0; step < 4; ++step)
    sim->step();
  ASSERT_GT(sim->tears(), 0u);
  deform(*sim, 3, 0.05);
  const ForceInput in{sim->position().values().data(), sim->velocity().values().data()};
  const auto stored = sim->map().embedding<Vec3>("f_stretch");
  int reshuffled = 0;
  for (const auto& model : sim->force_models()) {
    auto* s = dynamic_cast<Stretch2d*>(model.get());
    if (s == nullptr) continue;
    ASSERT_TRUE(s->grouped());
    const auto reps = s->groups().representatives();
    const auto counts = s->groups().counts();
    std::vector<Vec3> expected(sim->position().values().size(), Vec3::Zero());
    auto in_order = [&](const std::uint32_t* entries, std::size_t n, bool consecutive) {
      if (!consecutive) ++reshuffled;
      for (std::size_t i = 0; i < n; ++i) {
        // A consecutive block is read from its first entry only.
        const std::size_t g = consecutive ? entries[0] + i : entries[i];
        const auto& m = reps[g];
        Vec3 t[2];
        s->kernel().evaluate_terms(m, in, t);
        const Real count = counts[g];
        expected[m.vertex_a] += count * t[0];
        expected[m.vertex_b] += count * t[1];
      }
    };
    set_thread_count(1);
    s->colouring().run(in_order);
    std::vector<Vec3> plain(expected.size(), Vec3::Zero());
    std::vector<Vec3> storing = plain;
    s->add_forces(in, plain.data(), false);
    s->add_forces(in, storing.data(), true);
    set_thread_count(0);
    for (std::size_t v = 0; v < expected.size(); ++v) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_TRUE(test::same_bits(plain[v][c], expected[v][c])) << "slot " << v;
        ASSERT_TRUE(test::same_bits(storing[v][c], expected[v][c])) << "slot " << v;
      }
    }
    for (std::size_t e = 0; e < s->cache().size(); ++e) {
      Vec3 t[2];
      s->kernel().evaluate_terms(s->cache().matches()[e], in, t);
      ASSERT_EQ(stored.values()[s->stored()[e].dart_a], t[0]) << "match " << e;
      ASSERT_EQ(stored.values()[s->stored()[e].dart_b], t[1]) << "match " << e;
    }
  }
  EXPECT_GT(reshuffled, 0) << "no tear reshuffled a block: the test checks nothing new";
}

// The groups' table is sized up front for half as many groups as matches;
// with far more groups (every key but a few distinct) it must still grow and
// give each entry the group of its key's first match, numbered in order of
// first appearance, as a plain search over the keys seen so far does.
TEST(Grouping, MoreGroupsThanTheTableExpectsKeepFirstAppearanceOrder) {
  struct Pair {
    std::uint32_t a, b;
  };
  // Scattered but fixed numbers (a multiplicative hash of the index).
  auto scatter = [](std::uint32_t i) { return i * 2654435761u; };
  std::vector<Pair> matches;
  for (std::uint32_t i = 0; i < 5000; ++i) {
    if (i % 10 == 9) {
      matches.push_back(matches[scatter(i) % matches.size()]);  // a repeat
    } else {
      matches.push_back({i, scatter(i + 1)});
    }
  }
  auto key = [](const Pair& m, std::uint64_t* out) {
    out = key_words(m.a, out);
    key_words(m.b, out);
  };
  // Every prefix length around the build's look-ahead too (fewer matches
  // than it reads ahead, exactly as many, one more), then all of them.
  for (const std::size_t n :
       {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{MatchGroups<Pair>::kAhead},
        std::size_t{MatchGroups<Pair>::kAhead + 1}, matches.size()}) {
    const std::span<const Pair> some(matches.data(), n);
    MatchGroups<Pair> groups;
    MatchGroups<Pair>::NoObserver none;
    groups.build(some, 2, key, none);
    ASSERT_EQ(groups.check(some, key), "") << n << " matches";
    std::vector<Pair> firsts;
    std::vector<std::uint32_t> counts;
    for (std::uint32_t e = 0; e < n; ++e) {
      std::uint32_t g = 0;
      while (g < firsts.size() && (firsts[g].a != some[e].a || firsts[g].b != some[e].b))
        ++g;
      if (g == firsts.size()) {
        firsts.push_back(some[e]);
        counts.push_back(0);
      }
      ++counts[g];
      ASSERT_EQ(groups.group_of(e), g) << "entry " << e << " of " << n;
    }
    if (n == matches.size()) {
      EXPECT_GT(firsts.size(), matches.size() / 2);
    }
    ASSERT_EQ(groups.size(), firsts.size());
    for (std::uint32_t g = 0; g < firsts.size(); ++g)
      EXPECT_EQ(groups.counts()[g], Real(counts[g])) << "group " << g << " of " << n << " matches";
  }
}

// The table is sized for the groups its first kSample matches announce: a
// first part with few keys and a rest with many makes it grow while it
// builds, and the groups are still those of a plain search, in order of
// first appearance.
TEST(Grouping, AnEstimateShortOfTheGroupsGrowsTheTable) {
  struct Pair {
    std::uint32_t a, b;
  };
  constexpr std::size_t kSample = MatchGroups<Pair>::kSample;
  std::vector<Pair> matches;
  for (std::uint32_t i = 0; i < 2 * kSample; ++i)
    matches.push_back({i % 4, 7});  // four keys only
  constexpr std::uint32_t kDistinct = 30000;
  for (std::uint32_t i = 0; i < kDistinct; ++i)
    matches.push_back({100 + i, i * 2654435761u});
  auto key = [](const Pair& m, std::uint64_t* out) {
    out = key_words(m.a, out);
    key_words(m.b, out);
  };
  MatchGroups<Pair> groups;
  MatchGroups<Pair>::NoObserver none;
  groups.build(matches, 2, key, none);
  ASSERT_EQ(groups.check(matches, key), "");
  ASSERT_EQ(groups.size(), 4u + kDistinct);
  for (std::uint32_t e = 0; e < 4; ++e)
    EXPECT_EQ(groups.group_of(e), e);
  for (std::uint32_t i = 0; i < kDistinct; ++i)
    ASSERT_EQ(groups.group_of(static_cast<std::uint32_t>(2 * kSample + i)), 4 + i) << i;
  EXPECT_EQ(groups.counts()[0], Real(kSample / 2));
  // Grown past what the first matches announced (about 12 groups).
  EXPECT_GE(groups.table_size(), 2 * groups.size() + 2);
}

// The table homes a key by its first word (a vertex slot, near which the
// build's next keys fall). Keys that all begin with the same word (a vertex
// in every group, or a first word that is not a slot) would make one long
// run: the table must then turn to the hash of the whole key, at the build
// and when tears add groups, and still give every entry the group a plain
// search gives, find each group and drop groups cleanly.
TEST(Grouping, KeysSharingTheirFirstWordGroupAsAPlainSearch) {
  struct Pair {
    std::uint32_t a, b;
  };
  auto key = [](const Pair& m, std::uint64_t* out) {
    out = key_words(m.a, out);
    key_words(m.b, out);
  };
  // Groups by a plain search, in order of first appearance.
  auto plain = [](std::span<const Pair> ms) {
    std::vector<Pair> firsts;
    std::vector<std::uint32_t> group;
    for (const Pair& m : ms) {
      std::uint32_t g = 0;
      while (g < firsts.size() && (firsts[g].a != m.a || firsts[g].b != m.b))
        ++g;
      if (g == firsts.size()) firsts.push_back(m);
      group.push_back(g);
    }
    return group;
  };
  MatchGroups<Pair>::NoObserver none;
  // A hub: 3000 matches, every one on vertex 7, 1000 distinct partners.
  std::vector<Pair> hub;
  for (std::uint32_t i = 0; i < 3000; ++i)
    hub.push_back({7, (i * 2654435761u) % 1000});
  MatchGroups<Pair> groups;
  groups.build(hub, 2, key, none);
  EXPECT_FALSE(groups.homes_by_first_word()) << "the hub's run did not turn the table over";
  ASSERT_EQ(groups.check(hub, key), "");
  const std::vector<std::uint32_t> expected = plain(hub);
  for (std::uint32_t e = 0; e < hub.size(); ++e)
    ASSERT_EQ(groups.group_of(e), expected[e]) << "entry " << e;

  // Every first word heading 24 keys, none shared (a hexahedral block's face
  // diagonals): told how many first words there are, the table gives each
  // enough room to keep homing by them, for as many groups as matches.
  std::vector<Pair> fan;
  for (std::uint32_t v = 0; v < 2000; ++v) {
    for (std::uint32_t j = 0; j < 24; ++j)
      fan.push_back({v, 100000 + 24 * v + j});
  }
  MatchGroups<Pair> fanned;
  fanned.build(fan, 2, key, none, MatchGroups<Pair>::Keep::kEverything, 2000);
  EXPECT_TRUE(fanned.homes_by_first_word());
  ASSERT_EQ(fanned.check(fan, key), "");
  EXPECT_EQ(fanned.size(), fan.size());
  MatchGroups<Pair> unsized;  // the same keys, the first words' count unknown
  unsized.build(fan, 2, key, none);
  EXPECT_FALSE(unsized.homes_by_first_word());
  ASSERT_EQ(unsized.check(fan, key), "");

  // Spread keys first (the table homes by slot), then a tear adds a hub.
  std::vector<Pair> ms;
  for (std::uint32_t i = 0; i < 2000; ++i)
    ms.push_back({i / 2, i / 2 + 1});  // two matches per group
  MatchGroups<Pair> torn;
  torn.build(ms, 2, key, none);
  EXPECT_TRUE(torn.homes_by_first_word());
  ASSERT_EQ(torn.check(ms, key), "");
  for (std::uint32_t i = 0; i < 400; ++i) {
    ms.push_back({500, 5000 + i});
    torn.inserted(static_cast<std::uint32_t>(ms.size() - 1), ms.back(), key, none);
  }
  EXPECT_FALSE(torn.homes_by_first_word());
  ASSERT_EQ(torn.check(ms, key), "");
  EXPECT_EQ(torn.size(), 1000u + 400u);
  // Then drops entries (the MatchCache's swap with the last), emptying
  // groups of both kinds.
  for (std::uint32_t k = 0; k < 700; ++k) {
    const std::uint32_t e = (k * 7919u) % static_cast<std::uint32_t>(ms.size());
    const auto last = static_cast<std::uint32_t>(ms.size() - 1);
    torn.erased(e, last, ms, none);
    ms[e] = ms[last];
    ms.pop_back();
    ASSERT_EQ(torn.check(ms, key), "") << "after dropping " << k + 1 << " entries";
  }
}
}  // namespace
}  // namespace rift::physics_test
