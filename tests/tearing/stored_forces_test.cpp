// Interactions store their forces only when the scene reads them (issue 12,
// lean memory): a criterion reading a stored force (ComponentSpec::reads) or
// an output array naming it makes the interactions that write it store;
// otherwise they store nothing and the column keeps no storage, and a
// stored-force column that no storing interaction of the scene writes reads
// as its default without storage. Nothing else may change: the same motion,
// the same tears, the same stored values where they are read.
#include <gtest/gtest.h>

#include <stdexcept>

#include "rift/output/frame_mesh.hpp"
#include "rift/scene/scene_setup.hpp"
#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

constexpr const char* kSprings =
    "[[interaction]]\nname = \"stretch\"\n"
    "[[interaction]]\nname = \"shear\"\n"
    "[[interaction]]\nname = \"bend\"\n";

// Every stored force of the 2D mass-spring pack read by an output: the
// interactions store as a simulation built by hand does.
const std::vector<std::string> kEveryForce = {"f_stretch", "f_shear", "f_bend", "f_membrane"};

std::unique_ptr<Simulation> build(const std::string& name, const std::string& toml,
                                  const std::vector<std::string>* output_arrays = nullptr) {
  SetupOptions options;
  options.check_each_rewrite = true;
  if (output_arrays) options.output_arrays = *output_arrays;
  return simulate("stored_" + name, toml, options);
}

bool has_storage(const Simulation& sim, const char* column) {
  const ColumnBase* c = sim.map().find_column(column);
  return c != nullptr && c->allocated();
}

Vec3 stretched(const Vec3& p) {
  return Vec3(1.25 * p.x(), 1.1 * p.y(), p.z() + 0.05 * p.x());
}

// Runs `steps` steps of both simulations from the same deformed state and
// expects the same motion and tears, bit for bit.
void expect_same_run(Simulation& lean, Simulation& full, int steps) {
  deform(lean, stretched);
  deform(full, stretched);
  for (int s = 0; s < steps; ++s) {
    lean.step();
    full.step();
    ASSERT_EQ(lean.tears(), full.tears()) << "step " << s;
    ASSERT_EQ(lean.position().values(), full.position().values()) << "step " << s;
    ASSERT_EQ(lean.velocity().values(), full.velocity().values()) << "step " << s;
  }
  EXPECT_TRUE(lean.map().check_validity().empty());
}

TEST(StoredForces, WithoutCriterionNothingIsStoredAndTheMotionIsTheSame) {
  const std::string toml = static_scene("grid:quad:4x4", "1.0", 1.0, kSprings);
  auto lean = build("none_lean", toml);
  auto full = build("none_full", toml, &kEveryForce);
  expect_same_run(*lean, *full, 3);
  for (const char* column : {"f_stretch", "f_shear", "f_bend", "f_membrane"})
    EXPECT_FALSE(has_storage(*lean, column)) << column;
  // The reference stores (else this test could not fail).
  for (const char* column : {"f_stretch", "f_shear", "f_bend"})
    EXPECT_TRUE(has_storage(*full, column)) << column;
  EXPECT_FALSE(has_storage(*full, "f_membrane"));  // no interaction of the scene writes it
}

// A scene without criteria is never rewritten: its set-up says so
// (SimulationSettings::rewrites, whose effect on the interactions
// NeverRewritten.* tests), unless the caller rewrites by hand; the motion is
// the same bit for bit either way.
TEST(StoredForces, ASceneWithoutCriteriaIsSetUpForAMapNeverRewritten) {
  const std::string toml = static_scene("grid:quad:5x4", "1.0", 1.0, kSprings);
  auto fixed = build("never_rewritten", toml);
  SetupOptions by_hand;
  by_hand.rewrites_by_hand = true;
  auto rewritable = simulate("rewritten_by_hand", toml, by_hand);
  EXPECT_FALSE(fixed->settings().rewrites);
  EXPECT_TRUE(rewritable->settings().rewrites);
  expect_same_run(*fixed, *rewritable, 4);
  const std::vector<Dart> touched = {0};
  EXPECT_THROW(fixed->on_topology_changed(touched), std::logic_error);
  EXPECT_NO_THROW(rewritable->on_topology_changed(touched));
  auto tearing =
      build("criteria_rewrite",
            static_scene("grid:quad:5x4", "1.0", 1.0,
                         std::string(kSprings) + "[[criterion]]\nname = \"spring_split\"\n"));
  EXPECT_TRUE(tearing->settings().rewrites);
  // Nothing of the cloth's packs reads the corner masses: a map never
  // rewritten keeps none (the same masses, hence the same run above); a
  // rewritten one, and a scene whose pack reads them (fem2d's membrane), do.
  EXPECT_FALSE(fixed->keeps_corner_masses());
  EXPECT_FALSE(fixed->corner_mass());
  EXPECT_TRUE(rewritable->keeps_corner_masses());
  EXPECT_TRUE(tearing->keeps_corner_masses());
  auto membrane =
      build("membrane_never_rewritten",
            static_scene("grid:tri:4x4", "1.0", 1.0, "[[interaction]]\nname = \"membrane\"\n"));
  EXPECT_FALSE(membrane->settings().rewrites);
  EXPECT_TRUE(membrane->keeps_corner_masses());
  EXPECT_TRUE(has_storage(*membrane, "corner_mass"));
}

TEST(StoredForces, ACriterionSeesTheForcesItReadsExactlyThroughTears) {
  // spring_split reads f_stretch (its measure and its split plane): stretch
  // stores, bend and shear do not; the tears and the stored stretch forces
  // are those of a simulation where every interaction stores.
  const std::string toml = static_scene(
      "grid:quad:4x4", "1.0", 1.0,
      std::string(kSprings) + "[[criterion]]\nname = \"spring_split\"\nthreshold = 2.0\n");
  auto lean = build("split_lean", toml);
  auto full = build("split_full", toml, &kEveryForce);
  expect_same_run(*lean, *full, 3);
  EXPECT_GT(lean->tears(), 0u);
  EXPECT_TRUE(has_storage(*lean, "f_stretch"));
  EXPECT_FALSE(has_storage(*lean, "f_bend"));
  EXPECT_FALSE(has_storage(*lean, "f_shear"));
  EXPECT_TRUE(has_storage(*full, "f_bend"));
  const auto& a = lean->map().embedding<Vec3>("f_stretch").values();
  const auto& b = full->map().embedding<Vec3>("f_stretch").values();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a, b);
  EXPECT_TRUE(std::any_of(a.begin(), a.end(), [](const Vec3& f) { return f.norm() > 0; }));
}

TEST(StoredForces, AColumnNoInteractionWritesReadsAsZeroWithoutStorage) {
  // atomic_edge reads f_stretch, f_shear and f_membrane; no interaction of
  // this scene writes f_membrane: it stays without storage and reads zero.
  const std::string toml = static_scene(
      "grid:quad:4x4", "1.0", 1.0,
      std::string(kSprings) + "[[criterion]]\nname = \"atomic_edge\"\nthreshold = 0.5\n");
  auto lean = build("edge_lean", toml);
  auto full = build("edge_full", toml, &kEveryForce);
  expect_same_run(*lean, *full, 2);
  EXPECT_TRUE(has_storage(*lean, "f_stretch"));
  EXPECT_TRUE(has_storage(*lean, "f_shear"));
  EXPECT_FALSE(has_storage(*lean, "f_bend"));
  EXPECT_FALSE(has_storage(*lean, "f_membrane"));
  const Embedding<Vec3> membrane = std::as_const(lean->map()).embedding<Vec3>("f_membrane");
  const Embedding<Vec3>& read = membrane;
  EXPECT_EQ(read[0], Vec3::Zero());
  EXPECT_FALSE(has_storage(*lean, "f_membrane"));
}

// The quad cloth's packs declare the angular bending's parameters on
// <0,2>, which no component of a stretch/shear/bend scene asks for: that
// attachment keeps no slots (attachment.hpp, dormant) through the scene's
// tears, and a column asked for afterwards gets one slot per orbit of the
// torn map. The motion and tears are those of a run where the attachment
// was woken before the first step and kept its slots through every tear.
TEST(StoredForces, AnOrbitNoComponentAsksForKeepsNoSlotsThroughTears) {
  const std::string toml = static_scene(
      "grid:quad:4x4", "1.0", 1.0,
      std::string(kSprings) + "[[criterion]]\nname = \"spring_split\"\nthreshold = 2.0\n");
  auto lean = build("dormant_lean", toml);
  auto awake = build("dormant_awake", toml);
  const OrbitAttachment* wing = lean->map().attachment_of("abend_k");
  ASSERT_NE(wing, nullptr);
  ASSERT_EQ(wing->orbit(), (Orbit{0, 2}));
  EXPECT_TRUE(wing->dormant());
  const Embedding<Real> kept = awake->map().embedding<Real>("abend_k");
  EXPECT_FALSE(kept.attachment().dormant());
  expect_same_run(*lean, *awake, 3);
  ASSERT_GT(lean->tears(), 0u);
  EXPECT_TRUE(wing->dormant());
  // Woken after the tears: as many slots as the awake run kept, valid.
  const Embedding<Real> late = lean->map().embedding<Real>("abend_k");
  EXPECT_FALSE(wing->dormant());
  EXPECT_EQ(lean->map().check_validity(), std::vector<std::string>{});
  EXPECT_EQ(wing->live_slots(), kept.attachment().live_slots());
  EXPECT_EQ(wing->live_slots(), lean->map().count_cells(Orbit{0, 2}));
  EXPECT_EQ(awake->map().check_validity(), std::vector<std::string>{});
  lean->map().for_each_dart([&](Dart d) { EXPECT_EQ(late[d], late.default_value()) << d; });
}

TEST(StoredForces, AnOutputArrayNamingAStoredForceIsStored) {
  const std::string toml = static_scene("grid:quad:4x4", "1.0", 1.0, kSprings);
  const std::vector<std::string> bend = {"f_bend"};
  auto sim = build("output", toml, &bend);
  deform(*sim, stretched);
  sim->step();
  EXPECT_TRUE(has_storage(*sim, "f_bend"));
  EXPECT_FALSE(has_storage(*sim, "f_stretch"));
  const auto& f = sim->map().embedding<Vec3>("f_bend").values();
  EXPECT_TRUE(std::any_of(f.begin(), f.end(), [](const Vec3& v) { return v.norm() > 0; }));
  // The set-up's default names what the frame outputs write.
  const FrameOptions frame;
  std::vector<std::string> written = frame.point_arrays;
  written.insert(written.end(), frame.cell_arrays.begin(), frame.cell_arrays.end());
  EXPECT_EQ(SetupOptions{}.output_arrays, written);
}

}  // namespace
}  // namespace rift::tearing_test
