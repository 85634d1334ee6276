// A simulation set up for a map that is never rewritten (a scene without
// criteria: SimulationSettings::rewrites = false) keeps only what its force
// passes read (issue 12, lean memory): no owners in the match caches, groups
// of identical springs without their keys, table and per-match group (their
// member links only when the interaction stores), frozen colourings. It must
// step bit for bit as the same simulation set up to be rewritten, and refuse
// a rewrite instead of following it wrongly.
#include <gtest/gtest.h>

#include <stdexcept>

#include "physics_setup.hpp"
#include "rift/sim/match_groups.hpp"

namespace rift::physics_test {
namespace {

using Stretch2d = packs::mass_spring2d::StretchInteraction;
using Shear2d = packs::mass_spring2d::ShearInteraction;
using Bend2d = packs::mass_spring2d::BendInteraction;
using GroupsKeep = MatchGroups<packs::mass_spring2d::StretchKernel::Match>::Keep;

std::unique_ptr<Simulation> never_rewritten_cloth(bool rewrites, bool lean,
                                                  GridKind kind = GridKind::Quad) {
  SimSetup setup;
  setup.settings.rewrites = rewrites;
  setup.settings.dt = 5e-4;
  setup.interactions = paper_cloth_springs();
  if (kind == GridKind::Tri) setup.interactions.erase(setup.interactions.begin() + 1);
  setup.lean_forces = lean;  // lean: nothing stores (no criterion); else every force is stored
  return simulate(assemble_gmap(make_grid(kind, 9, 7)), setup);
}

template <class Model>
void expect_only_pass_arrays(const Model& m, bool rewrites, bool stores, const char* what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(m.stores_forces(), stores);
  EXPECT_EQ(m.cache().owners().size(), rewrites ? m.cache().size() : 0u);
  EXPECT_EQ(m.colouring().frozen(), !rewrites);
  EXPECT_EQ(m.colouring().entries(), m.evaluated_matches());
  if (m.grouped()) {
    const GroupsKeep keep =
        rewrites ? GroupsKeep::kEverything : (stores ? GroupsKeep::kMembers : GroupsKeep::kCounts);
    EXPECT_EQ(static_cast<int>(m.groups().keeps()), static_cast<int>(keep));
  }
  // The groups are those a fresh grouping of the matches gives, whatever was kept.
  EXPECT_EQ(m.check_groups(), "");
}

TEST(NeverRewritten, KeepsOnlyWhatTheForcePassesRead) {
  for (bool lean : {true, false}) {
    for (bool rewrites : {true, false}) {
      auto sim = never_rewritten_cloth(rewrites, lean);
      int seen = 0;
      for (const auto& model : sim->force_models()) {
        if (const auto* s = dynamic_cast<const Stretch2d*>(model.get())) {
          ASSERT_TRUE(s->grouped());
          expect_only_pass_arrays(*s, rewrites, !lean, "stretch");
          ++seen;
        } else if (const auto* b = dynamic_cast<const Bend2d*>(model.get())) {
          ASSERT_TRUE(b->grouped());
          expect_only_pass_arrays(*b, rewrites, !lean, "bend");
          ++seen;
        } else if (const auto* q = dynamic_cast<const Shear2d*>(model.get())) {
          ASSERT_FALSE(q->grouped());  // one match per face: nothing to share
          expect_only_pass_arrays(*q, rewrites, !lean, "shear");
          ++seen;
        }
      }
      EXPECT_EQ(seen, 3);
    }
  }
}

// Positions, velocities and (when stored) every stored force, bit for bit,
// over steps from a random deformed state: grouped storing and non-storing
// passes, the plain pass of shear, quads and triangles.
TEST(NeverRewritten, StepsBitForBitAsAMapThatMayBeRewritten) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri}) {
    for (bool lean : {true, false}) {
      auto fixed = never_rewritten_cloth(false, lean, kind);
      auto free = never_rewritten_cloth(true, lean, kind);
      deform(*fixed, 7, 0.03);
      deform(*free, 7, 0.03);
      for (int step = 0; step < 25; ++step) {
        fixed->step();
        free->step();
      }
      ASSERT_EQ(fixed->position().values(), free->position().values()) << "lean " << lean;
      ASSERT_EQ(fixed->velocity().values(), free->velocity().values()) << "lean " << lean;
      EXPECT_EQ(fixed->potential_energy(), free->potential_energy());
      if (!lean) {
        for (const char* name : {"f_stretch", "f_shear", "f_bend"}) {
          if (kind == GridKind::Tri && std::string(name) == "f_shear") continue;
          const auto a = fixed->map().embedding<Vec3>(name);
          const auto b = free->map().embedding<Vec3>(name);
          ASSERT_TRUE(a && b) << name;
          ASSERT_EQ(a.values(), b.values()) << name;
          std::size_t nonzero = 0;
          for (const Vec3& f : a.values())
            nonzero += f != Vec3::Zero() ? 1 : 0;
          EXPECT_GT(nonzero, 0u) << name;
        }
      }
    }
  }
}

TEST(NeverRewritten, RewritesAreRefused) {
  auto sim = never_rewritten_cloth(false, true);
  const std::vector<Dart> touched = {0};
  EXPECT_THROW(sim->on_topology_changed(touched), std::logic_error);
  for (const auto& model : sim->force_models())
    EXPECT_THROW(model->rematch(sim->map(), touched), std::logic_error) << model->name();
  // A simulation with criteria rewrites its map.
  SimSetup setup;
  setup.settings.rewrites = false;
  setup.interactions = paper_cloth_springs();
  setup.criteria = {{"spring_split", {{"threshold", 0.5}}}};
  EXPECT_THROW(simulate(assemble_gmap(make_grid(GridKind::Quad, 3, 3)), setup),
               std::invalid_argument);
}

}  // namespace
}  // namespace rift::physics_test
