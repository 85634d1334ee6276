// A simulation set up for a map that is never rewritten (a scene without
// criteria: SimulationSettings::rewrites = false) keeps only what its force
// passes read (issue 12, lean memory): no owners in the match caches, groups
// of identical springs without their keys, table and per-match group (their
// member links only when the interaction stores), frozen colourings. It must
// step bit for bit as the same simulation set up to be rewritten, and refuse
// a rewrite instead of following it wrongly. A grouped interaction that
// stores nothing, under an explicit integrator, keeps its groups and not its
// matches; its energy is then summed over the groups (count × the
// representative's), which may change the last bits of the sum only. The
// vertex masses are summed without corner masses when nothing reads them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "physics_setup.hpp"
#include "rift/sim/match_groups.hpp"

namespace rift::physics_test {
namespace {

using Stretch2d = packs::mass_spring2d::StretchInteraction;
using Shear2d = packs::mass_spring2d::ShearInteraction;
using Bend2d = packs::mass_spring2d::BendInteraction;
using GroupsKeep = MatchGroups<packs::mass_spring2d::StretchKernel::Match>::Keep;

std::unique_ptr<Simulation> never_rewritten_cloth(
    bool rewrites, bool lean, GridKind kind = GridKind::Quad,
    IntegratorKind integrator = IntegratorKind::kRK4) {
  SimSetup setup;
  setup.settings.rewrites = rewrites;
  setup.settings.integrator = integrator;
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
  // The groups are those a fresh grouping of the matches gives, whatever was
  // kept (their counts add up to the matches when only the groups are kept).
  EXPECT_EQ(m.check_groups(), "");
  // Under RK4 (no Jacobians), a grouped pass that never stores reads only the groups.
  const bool given_back = !rewrites && !stores && m.grouped();
  EXPECT_EQ(m.matches_given_back(), given_back);
  EXPECT_EQ(m.cache().matches().empty(), given_back);
  EXPECT_GT(m.active_matches(), 0u);
}

// The same groups (representatives and counts, byte for byte) and number of
// matches as `twin`'s, set up to be rewritten: keeping only the groups
// keeps what the pass of a map that may be rewritten reads.
template <class Model>
void expect_same_groups(const Model& m, const Model& twin) {
  ASSERT_EQ(m.active_matches(), twin.active_matches());
  const auto a = m.groups().representatives();
  const auto b = twin.groups().representatives();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size_bytes()), 0);
  const auto ca = m.groups().counts();
  const auto cb = twin.groups().counts();
  EXPECT_TRUE(std::equal(ca.begin(), ca.end(), cb.begin(), cb.end()));
}

TEST(NeverRewritten, KeepsOnlyWhatTheForcePassesRead) {
  for (bool lean : {true, false}) {
    auto twin = never_rewritten_cloth(true, lean);
    for (bool rewrites : {true, false}) {
      auto sim = never_rewritten_cloth(rewrites, lean);
      std::size_t seen = 0;
      for (const auto& model : sim->force_models()) {
        if (const auto* s = dynamic_cast<const Stretch2d*>(model.get())) {
          ASSERT_TRUE(s->grouped());
          expect_only_pass_arrays(*s, rewrites, !lean, "stretch");
          expect_same_groups(*s, *dynamic_cast<const Stretch2d*>(twin->force_models()[seen].get()));
          ++seen;
        } else if (const auto* b = dynamic_cast<const Bend2d*>(model.get())) {
          ASSERT_TRUE(b->grouped());
          expect_only_pass_arrays(*b, rewrites, !lean, "bend");
          expect_same_groups(*b, *dynamic_cast<const Bend2d*>(twin->force_models()[seen].get()));
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
      if (lean) {
        // Summed over the groups (EnergyOfTheGroupsIsTheSumOverEveryMatch).
        EXPECT_NEAR(fixed->potential_energy(), free->potential_energy(),
                    1e-12 * std::abs(free->potential_energy()));
      } else {
        EXPECT_EQ(fixed->potential_energy(), free->potential_energy());
      }
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

// An interaction keeping only its groups sums its energy as count × the
// representative's energy: against the sum over every match of the same
// cloth set up to be rewritten, per interaction, to 1e-12 relative. A count
// left out (each interior spring counted once) would be off by about half.
TEST(NeverRewritten, EnergyOfTheGroupsIsTheSumOverEveryMatch) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    auto fixed = never_rewritten_cloth(false, true, kind);
    auto free = never_rewritten_cloth(true, true, kind);
    deform(*fixed, 11, 0.05);
    deform(*free, 11, 0.05);
    const ForceInput in{fixed->position().values().data(), fixed->velocity().values().data()};
    ASSERT_EQ(fixed->position().values(), free->position().values());
    int given_back = 0;
    for (std::size_t i = 0; i < fixed->force_models().size(); ++i) {
      const ForceModel& a = *fixed->force_models()[i];
      const ForceModel& b = *free->force_models()[i];
      const Real sum_over_matches = b.potential_energy(in);
      ASSERT_GT(sum_over_matches, 0) << a.name();
      EXPECT_NEAR(a.potential_energy(in), sum_over_matches, 1e-12 * sum_over_matches) << a.name();
      if (const auto* s = dynamic_cast<const Stretch2d*>(&a)) given_back += s->matches_given_back();
      if (const auto* s = dynamic_cast<const Bend2d*>(&a)) given_back += s->matches_given_back();
    }
    EXPECT_EQ(given_back, 2);
  }
}

// An implicit integrator asks every interaction for its Jacobians, per
// match: the matches are kept, and the run is the same bit for bit as the
// same cloth set up to be rewritten.
TEST(NeverRewritten, AnImplicitIntegratorKeepsTheMatchesForItsJacobians) {
  auto fixed = never_rewritten_cloth(false, true, GridKind::Quad, IntegratorKind::kImplicitEuler);
  auto free = never_rewritten_cloth(true, true, GridKind::Quad, IntegratorKind::kImplicitEuler);
  for (const auto& model : fixed->force_models()) {
    if (const auto* s = dynamic_cast<const Stretch2d*>(model.get())) {
      EXPECT_TRUE(s->grouped());
      EXPECT_FALSE(s->matches_given_back());
      EXPECT_EQ(s->cache().matches().size(), s->active_matches());
    }
  }
  deform(*fixed, 5, 0.02);
  deform(*free, 5, 0.02);
  for (int step = 0; step < 3; ++step) {
    fixed->step();
    free->step();
  }
  ASSERT_EQ(fixed->position().values(), free->position().values());
  ASSERT_EQ(fixed->velocity().values(), free->velocity().values());
  EXPECT_EQ(fixed->potential_energy(), free->potential_energy());
}

// Without corner masses (a map never rewritten whose corner masses nothing
// reads), the vertex masses are the same bits as summed from them, on a
// randomly deformed mesh of uneven elements (by total mass and by density,
// 2D and 3D); no corner slots are kept, and an interaction that reads the
// corner masses is refused rather than given zeros.
TEST(NeverRewritten, VertexMassesWithoutCornerMassesAreTheSameBits) {
  struct Case {
    MeshData mesh;
    std::vector<Use> interactions;
  };
  std::vector<Case> cases;
  cases.push_back({make_grid(GridKind::Mix, 7, 5), paper_cloth_springs()});
  cases.push_back({make_grid(GridKind::Tri, 6, 6), {{"stretch", {{"stiffness", 10.0}}}}});
  cases.push_back({make_block(BlockKind::Hex, 3, 2, 2), {{"stretch", {{"stiffness", 10.0}}}}});
  cases.push_back({make_block(BlockKind::Tet, 2, 2, 3), {{"stretch", {{"stiffness", 10.0}}}}});
  for (bool by_density : {false, true}) {
    for (const Case& c : cases) {
      std::unique_ptr<Simulation> sims[2];
      for (int keep = 0; keep < 2; ++keep) {
        SimSetup setup;
        setup.settings.rewrites = false;
        setup.settings.keep_corner_masses = keep == 1;
        setup.interactions = c.interactions;
        setup.lean_forces = true;  // nothing stores (the shear's forces are on corners)
        setup.prepare = [&](Simulation& sim) {
          deform(sim, 3, 0.2);  // uneven elements: every sum's order shows
          if (by_density) {
            sim.set_density(3.7);
          } else {
            sim.set_total_mass(2.3);
          }
        };
        sims[keep] = simulate(assemble_gmap(c.mesh), setup);
      }
      const Simulation& lean = *sims[0];
      const Simulation& kept = *sims[1];
      SCOPED_TRACE(testing::Message()
                   << "dimension " << lean.map().dimension() << ", density " << by_density);
      EXPECT_FALSE(lean.keeps_corner_masses());
      EXPECT_TRUE(kept.keeps_corner_masses());
      const auto& a = lean.vertex_mass().values();
      const auto& b = kept.vertex_mass().values();
      ASSERT_EQ(a.size(), b.size());
      EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Real)), 0);
      EXPECT_GT(sum_of_vertex_masses(lean), 0);
      EXPECT_FALSE(lean.map().has_embedding("corner_mass") &&
                   lean.map().find_column("corner_mass")->allocated());
      for (const auto& att : lean.map().attachments()) {
        if (att->orbit() == corner_orbit(lean.map().dimension())) {
          EXPECT_TRUE(att->dormant());
        }
      }
    }
  }
  // fem2d's membrane reads the corner masses (its element mass).
  SimSetup setup;
  setup.settings.rewrites = false;
  setup.settings.keep_corner_masses = false;
  setup.interactions = {{"membrane", {}}};
  EXPECT_THROW(simulate(assemble_gmap(make_grid(GridKind::Tri, 3, 3)), setup), std::logic_error);
  setup.settings.keep_corner_masses = true;
  EXPECT_NO_THROW(simulate(assemble_gmap(make_grid(GridKind::Tri, 3, 3)), setup));
}

// A tagged interaction (the quad shear) of a map never rewritten keeps no
// tag: its <> attachment keeps no slot per dart (nothing else of the cloth
// is on <>), and its matches are those of the tagged twin.
TEST(NeverRewritten, ATaggedInteractionKeepsNoTag) {
  auto fixed = never_rewritten_cloth(false, true);
  auto free = never_rewritten_cloth(true, true);
  const ColumnBase* tag = fixed->map().find_column("shear_first_dart");
  ASSERT_NE(tag, nullptr);
  EXPECT_FALSE(tag->allocated());
  EXPECT_TRUE(fixed->map().attachment_of("shear_first_dart")->dormant());
  EXPECT_TRUE(free->map().find_column("shear_first_dart")->allocated());
  for (std::size_t i = 0; i < fixed->force_models().size(); ++i) {
    const auto* a = dynamic_cast<const Shear2d*>(fixed->force_models()[i].get());
    const auto* b = dynamic_cast<const Shear2d*>(free->force_models()[i].get());
    if (a == nullptr) continue;
    ASSERT_NE(b, nullptr);
    const auto ma = a->cache().matches();
    const auto mb = b->cache().matches();
    ASSERT_EQ(ma.size(), mb.size());
    ASSERT_GT(ma.size(), 0u);
    EXPECT_EQ(std::memcmp(ma.data(), mb.data(), ma.size_bytes()), 0);
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
