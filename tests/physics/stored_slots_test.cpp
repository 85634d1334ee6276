// The slots only stored forces are written at (a kernel's Stored,
// rift/sim/cached_interaction.hpp) are cached beside the matches when the
// interaction stores, and not at all when it does not (issue 12, lean
// memory): through tears they stay those a fresh match of each owner gives,
// and an interaction that stores nothing leaves its stored-force embedding
// unbound, so that an orbit nothing else uses keeps no slots, with the same
// motion bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>

#include "physics_setup.hpp"

namespace rift::physics_test {
namespace {

template <class Interaction>
Interaction* find_model(Simulation& sim) {
  for (const auto& m : sim.force_models())
    if (auto* i = dynamic_cast<Interaction*>(m.get())) return i;
  return nullptr;
}

/// Every cached match and Stored equals a fresh match from its owner dart.
template <class Interaction>
std::string check_against_fresh_matches(Interaction& model, const GMap& map) {
  const auto matches = model.cache().matches();
  const auto owners = model.cache().owners();
  const auto stored = model.stored();
  if (stored.size() != matches.size()) return "stored slots not parallel to the matches";
  const auto& kernel = model.kernel();
  using Kernel = std::remove_cvref_t<decltype(kernel)>;
  for (std::size_t e = 0; e < matches.size(); ++e) {
    typename Kernel::Match m{};
    typename Kernel::Stored s{};
    if (!kernel.match(map, owners[e], m, &s)) return "entry " + std::to_string(e) + " lost";
    if (std::memcmp(&m, &matches[e], sizeof m) != 0)
      return "entry " + std::to_string(e) + ": another match";
    if (std::memcmp(&s, &stored[e], sizeof s) != 0)
      return "entry " + std::to_string(e) + ": other stored slots";
  }
  return "";
}

// spring_split reads f_stretch: stretch stores, bend does not. Grouped or
// not, through the tears of a stretched cloth, stretch's Stored follow its
// matches and bend keeps none.
TEST(StoredSlots, FollowTheMatchesThroughTears) {
  for (bool grouped : {true, false}) {
    SimSetup setup;
    setup.interactions = paper_cloth_springs();
    setup.criteria = {{"spring_split", {{"threshold", 0.5}}}};
    setup.settings.max_tears_per_step = 3;
    setup.settings.dt = 1e-4;
    setup.settings.group_interactions = grouped;
    setup.lean_forces = true;
    auto sim = simulate(assemble_gmap(make_grid(GridKind::Quad, 12, 12)), setup);
    auto* stretch = find_model<packs::mass_spring2d::StretchInteraction>(*sim);
    auto* bend = find_model<packs::mass_spring2d::BendInteraction>(*sim);
    ASSERT_NE(stretch, nullptr);
    ASSERT_NE(bend, nullptr);
    EXPECT_TRUE(stretch->keeps_stored_slots());
    EXPECT_FALSE(bend->keeps_stored_slots());
    EXPECT_TRUE(bend->stored().empty());
    ASSERT_EQ(check_against_fresh_matches(*stretch, sim->map()), "");
    move_vertices(*sim, [](const Vec3& x) { return Vec3(1.3 * x.x(), 1.3 * x.y(), x.z()); });
    for (int step = 0; step < 8; ++step) {
      sim->step();
      ASSERT_EQ(check_against_fresh_matches(*stretch, sim->map()), "")
          << "grouped " << grouped << ", step " << step;
      EXPECT_TRUE(bend->stored().empty());
    }
    EXPECT_GT(sim->tears(), 0u) << "grouped " << grouped;
  }
}

// The hexahedra's linear shear stores on face corners <1>, which nothing
// else of a stretch and shear block uses: without a reader of f_shear that
// attachment keeps no slots (shear binds neither the column nor the slots),
// and the block moves as one whose every interaction stores.
TEST(StoredSlots, AnInteractionThatStoresNothingLeavesItsStoredForcesOrbitWithoutSlots) {
  auto make = [](bool lean) {
    SimSetup setup;
    setup.interactions = {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}},
                          {"shear", {{"stiffness", 43.0}, {"damping", 0.1}}}};
    setup.settings.dt = 1e-4;
    setup.lean_forces = lean;
    return simulate(assemble_gmap(make_block(BlockKind::Hex, 3, 3, 3)), setup);
  };
  auto lean = make(true);
  auto full = make(false);
  const OrbitAttachment* corners = lean->map().attachment_of("f_shear");
  ASSERT_NE(corners, nullptr);
  ASSERT_EQ(corners->orbit(), (Orbit{1}));
  EXPECT_TRUE(corners->dormant());
  EXPECT_FALSE(full->map().attachment_of("f_shear")->dormant());
  auto* lean_shear = find_model<packs::mass_spring3d::ShearInteraction>(*lean);
  auto* full_shear = find_model<packs::mass_spring3d::ShearInteraction>(*full);
  ASSERT_NE(lean_shear, nullptr);
  ASSERT_NE(full_shear, nullptr);
  EXPECT_TRUE(lean_shear->stored().empty());
  EXPECT_EQ(full_shear->stored().size(), full_shear->active_matches());
  EXPECT_GT(full_shear->active_matches(), 0u);
  ASSERT_EQ(check_against_fresh_matches(*full_shear, full->map()), "");
  deform(*lean, 3, 0.02);
  deform(*full, 3, 0.02);
  for (int step = 0; step < 3; ++step) {
    lean->step();
    full->step();
    ASSERT_EQ(lean->position().values(), full->position().values()) << "step " << step;
    ASSERT_EQ(lean->velocity().values(), full->velocity().values()) << "step " << step;
  }
  EXPECT_TRUE(corners->dormant());
  // The reference stored its shear forces (else this test could not fail).
  const auto& f = full->map().embedding<Vec3>("f_shear").values();
  EXPECT_TRUE(std::any_of(f.begin(), f.end(), [](const Vec3& v) { return v.norm() > 0; }));
}

}  // namespace
}  // namespace rift::physics_test
