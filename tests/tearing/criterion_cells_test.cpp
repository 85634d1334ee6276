// After a tear, a criterion's cells follow the darts the tear touched
// (CellList::note_changed, through Simulation::on_topology_changed) instead
// of being listed anew from the whole map. What it collects must stay what
// the same criterion made afresh on the torn map collects (its cells listed
// from the whole map): the same candidates, in the same order, bit for bit,
// tear after tear, for criteria on every kind of orbit, in 2D and 3D. The
// same for a handle's held slots, which follow the split vertices.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

std::vector<TearCandidate> collected(const Criterion& c, const GMap& map) {
  std::vector<TearCandidate> out;
  c.collect(map, out);
  return out;
}

bool same_candidate(const TearCandidate& a, const TearCandidate& b) {
  return a.at == b.at && std::memcmp(&a.measure, &b.measure, sizeof(Real)) == 0 &&
         a.payload_reals == b.payload_reals &&
         std::memcmp(a.payload.data(), b.payload.data(), sizeof(a.payload)) == 0;
}

// Criteria made afresh from the scene's [[criterion]] names: never told of a
// tear, they list their cells from the whole map at each collect.
std::vector<std::unique_ptr<Criterion>> fresh_criteria(Simulation& sim,
                                                       const std::vector<std::string>& names,
                                                       double threshold) {
  const int n = sim.map().dimension();
  std::vector<std::unique_ptr<Criterion>> out;
  for (const std::string& name : names) {
    ComponentUse use;
    use.name = name;
    use.params["threshold"] = SceneParam{Value(threshold), 0};
    out.push_back(standard_packs().pack_of_criterion(name, n)->make_criterion(use));
    out.back()->initialise(sim.map());
  }
  return out;
}

// Tears `rounds` times, each time at the first candidate of the criteria in
// turn (every rule of the scene's criteria runs), and after each tear
// compares every criterion with its fresh counterpart.
void tear_and_compare(const std::string& name, const std::string& mesh, const std::string& scale,
                      const std::string& interactions, const std::vector<std::string>& criteria,
                      Vec3 (*deformation)(const Vec3&), int rounds) {
  // Thresholds small enough for (almost) every cell to be a candidate: the
  // candidates then list the cells themselves.
  const double threshold = 1e-6;
  std::string components = interactions;
  for (const std::string& c : criteria)
    components += criterion_table(c, threshold);
  auto sim = simulate(name, static_scene(mesh, scale, 1.0, components));
  deform(*sim, deformation);
  store_forces(*sim);
  auto fresh = fresh_criteria(*sim, criteria, threshold);
  std::size_t tears = 0, compared = 0;
  for (int round = 0; round < rounds; ++round) {
    const std::size_t c = static_cast<std::size_t>(round) % criteria.size();
    tears += tear_once(*sim, c);
    store_forces(*sim);
    for (std::size_t k = 0; k < criteria.size(); ++k) {
      const std::vector<TearCandidate> got = collected(*sim->criteria()[k], sim->map());
      const std::vector<TearCandidate> want = collected(*fresh[k], sim->map());
      ASSERT_EQ(got.size(), want.size()) << criteria[k] << " after round " << round;
      for (std::size_t i = 0; i < got.size(); ++i) {
        ASSERT_TRUE(same_candidate(got[i], want[i]))
            << criteria[k] << " after round " << round << ", candidate " << i << ": dart "
            << got[i].at << " vs " << want[i].at;
      }
      compared += got.size();
    }
  }
  EXPECT_GE(tears, static_cast<std::size_t>(rounds) / 2) << name;
  EXPECT_GT(compared, 0u) << name;
}

TEST(CriterionCells, FollowTearsOfACloth) {
  const std::string cloth = interaction_table("stretch", "stiffness = 60.0") +
                            interaction_table("shear", "stiffness = 43.0") +
                            interaction_table("bend", "stiffness = 10.0");
  for (const char* mesh : {"grid:quad:9x7", "grid:mix:8x8"}) {
    tear_and_compare(
        std::string("cells2d_") + mesh[5], mesh, "[1.0, 1.0, 1.0]", cloth,
        {"spring_split", "global_edge", "vertex_sum", "shear_force", "bend_force", "atomic_edge"},
        shear_and_stretch, 18);
  }
}

TEST(CriterionCells, FollowTearsOfAHexahedralBlock) {
  const std::string block = interaction_table("stretch", "stiffness = 60.0") +
                            interaction_table("shear", "stiffness = 43.0") +
                            interaction_table("volume_shear", "stiffness = 43.0");
  tear_and_compare("cells3d_hex", "block:hex:4x3x3", "[1.0, 1.0, 1.0]", block,
                   {"global_face", "spring_split", "shear_force", "interaction_force", "vertex_sum",
                    "atomic_face"},
                   shear_and_stretch, 18);
}

}  // namespace
}  // namespace rift::tearing_test

namespace rift::tearing_test {
namespace {

// The held slots of a handle follow tears that split its vertices (each half
// stays on the handle) without a sweep of every slot: after each tear they
// are the slots alive with a handle, as a sweep finds them.
TEST(HandlesAfterTears, FollowTheSplitVerticesWithoutASweep) {
  const std::string components =
      "[[handle]]\nname = \"grip\"\nselect = { box = { min = [-1, 0.4, -1], max = [2, 2, 1] } }\n"
      "velocity = [0, 0.5, 0]\n" +
      interaction_table("stretch", "stiffness = 60.0") +
      interaction_table("shear", "stiffness = 43.0") + criterion_table("spring_split", 1e-6);
  auto sim = simulate("handles_tears",
                      static_scene("grid:quad:10x10", "[1.0, 1.0, 1.0]", 1.0, components));
  deform(*sim, shear_and_stretch);
  store_forces(*sim);
  const Handles& handles = *sim->handles();
  const OrbitAttachment& vertices = sim->position().attachment();
  const std::size_t held_before = handles.held_slots(vertices).size();
  ASSERT_GT(held_before, 40u);
  const auto handle = sim->map().embedding<std::int64_t>("handle");
  std::size_t tears = 0;
  for (int round = 0; round < 25; ++round) {
    // The first spring that splits among the held vertices.
    std::vector<TearCandidate> candidates = collected(*sim->criteria()[0], sim->map());
    std::vector<Dart> touched;
    for (const TearCandidate& c : candidates) {
      if (sim->position()[c.at].y() < 0.6) continue;
      touched.clear();
      if (!sim->criteria()[0]->apply(sim->map(), c, touched)) continue;
      sim->on_topology_changed(touched);
      ++tears;
      break;
    }
    store_forces(*sim);
    std::vector<Slot> swept;
    for (Slot s = 0; s < vertices.slot_capacity(); ++s) {
      if (vertices.slot_alive(s) && handle.values()[s] >= 0) swept.push_back(s);
    }
    ASSERT_EQ(handles.held_slots(vertices), swept) << "after round " << round;
  }
  EXPECT_GT(tears, 20u);
  EXPECT_GT(handles.held_slots(vertices).size(), held_before + 10);  // the split vertices' halves
  EXPECT_EQ(handles.held_sweeps(), 1u);
}

}  // namespace
}  // namespace rift::tearing_test
