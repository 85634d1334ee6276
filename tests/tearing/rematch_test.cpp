// After a tear each interaction re-matches only the support orbits that may
// hold a match reading a touched dart: those its kernel's words (kReach,
// rift/sim/reach.hpp) lead back to from the touched darts. Through tears of
// every kind of the standard criteria, in 2D and 3D, every interaction must
// then hold exactly the matches a matching of the whole torn map finds: one
// per matchable support orbit, each equal to a fresh match from its owner.
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "fem2d.hpp"
#include "fem3d.hpp"
#include "mass_spring2d.hpp"
#include "mass_spring3d.hpp"
#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

/// The smallest dart of <o>(d): how GMap::for_each_cell names an orbit.
Dart smallest_of(const GMap& map, Dart d, Orbit o) {
  Dart smallest = d;
  map.for_each_in_orbit(d, o, [&](Dart x) { smallest = std::min(smallest, x); });
  return smallest;
}

/// What is wrong with `model`'s matches on `map`, or "" (nothing).
template <class Interaction>
std::string check_complete(Interaction& model, const GMap& map) {
  const auto& kernel = model.kernel();
  using Kernel = std::remove_cvref_t<decltype(kernel)>;
  const auto matches = model.cache().matches();
  const auto owners = model.cache().owners();
  std::set<Dart> held;
  for (std::size_t e = 0; e < matches.size(); ++e) {
    typename Kernel::Match m{};
    if (!kernel.match(map, owners[e], m))
      return "entry " + std::to_string(e) + " no longer matches";
    if (std::memcmp(&m, &matches[e], sizeof m) != 0)
      return "entry " + std::to_string(e) + " is another match than its owner's";
    if (!held.insert(smallest_of(map, owners[e], Kernel::kSupport)).second)
      return "two entries for the orbit of dart " + std::to_string(owners[e]);
  }
  // A whole-map matching, from the dart the cache itself would choose.
  std::set<Dart> matchable;
  map.for_each_cell(Kernel::kSupport, [&](Dart d) {
    Dart from = d;
    if constexpr (requires { kernel.support_dart(map, d); }) from = kernel.support_dart(map, d);
    typename Kernel::Match m{};
    if (kernel.match(map, from, m)) matchable.insert(d);
  });
  for (const Dart d : matchable) {
    if (!held.count(d)) return "the orbit of dart " + std::to_string(d) + " is not matched";
  }
  if (held.size() != matchable.size()) return "a held orbit no longer matches";
  return "";
}

/// check_complete for every model of the simulation whose type it knows;
/// counts the models checked.
std::string check_every_model(Simulation& sim, std::size_t& checked) {
  checked = 0;
  for (const auto& model : sim.force_models()) {
    std::string wrong;
    auto check = [&]<class I>(I* typed) {
      if (!typed) return;
      ++checked;
      wrong = check_complete(*typed, sim.map());
      if (!wrong.empty()) wrong = typed->name() + ": " + wrong;
    };
    check(dynamic_cast<packs::mass_spring2d::StretchInteraction*>(model.get()));
    check(dynamic_cast<packs::mass_spring2d::ShearInteraction*>(model.get()));
    check(dynamic_cast<packs::mass_spring2d::BendInteraction*>(model.get()));
    check(dynamic_cast<packs::mass_spring2d::AngularShearInteraction*>(model.get()));
    check(dynamic_cast<packs::mass_spring2d::AngularBendInteraction*>(model.get()));
    check(dynamic_cast<packs::fem2d::MembraneInteraction*>(model.get()));
    check(dynamic_cast<packs::mass_spring3d::StretchInteraction*>(model.get()));
    check(dynamic_cast<packs::mass_spring3d::ShearInteraction*>(model.get()));
    check(dynamic_cast<packs::mass_spring3d::VolumeShearInteraction*>(model.get()));
    check(dynamic_cast<packs::fem3d::CorotationalInteraction*>(model.get()));
    if (!wrong.empty()) return wrong;
  }
  return "";
}

// Tears `rounds` times at the first candidate that applies of each criterion
// in turn, and checks every interaction after each tear.
void tear_and_check(const std::string& name, const std::string& mesh,
                    const std::string& interactions, const std::vector<std::string>& criteria,
                    std::size_t models, int rounds) {
  std::string components = interactions;
  for (const std::string& c : criteria)
    components += criterion_table(c, 1e-6);
  auto sim = simulate(name, static_scene(mesh, "[1.0, 1.0, 1.0]", 1.0, components));
  deform(*sim, shear_and_stretch);
  store_forces(*sim);
  std::size_t checked = 0;
  ASSERT_EQ(check_every_model(*sim, checked), "") << name << " before any tear";
  ASSERT_EQ(checked, models) << name;
  std::size_t tears = 0;
  for (int round = 0; round < rounds; ++round) {
    const std::size_t c = static_cast<std::size_t>(round) % criteria.size();
    tears += tear_once(*sim, c);
    store_forces(*sim);
    ASSERT_EQ(check_every_model(*sim, checked), "")
        << name << " after round " << round << " (" << criteria[c] << ")";
  }
  EXPECT_GE(tears, static_cast<std::size_t>(rounds) / 2) << name;
}

// The bending springs read two links past their edge: with the touched
// darts' own support orbits alone (no words), bend keeps stale matches after
// the first split.
TEST(Rematch, EveryClothInteractionHoldsTheMatchesOfTheWholeTornMap) {
  const std::string cloth = interaction_table("stretch", "stiffness = 60.0") +
                            interaction_table("shear", "stiffness = 43.0") +
                            interaction_table("bend", "stiffness = 10.0") +
                            interaction_table("angular_shear", "stiffness = 0.01") +
                            interaction_table("angular_bend", "stiffness = 0.01") +
                            interaction_table("membrane", "young = 100.0");
  for (const char* mesh : {"grid:quad:9x7", "grid:mix:8x8", "grid:tri:7x7"}) {
    // Triangles have no linear shear spring: it matches nothing there.
    tear_and_check(std::string("rematch2d_") + mesh[5], mesh, cloth,
                   {"spring_split", "atomic_edge", "vertex_sum", "global_edge"}, 6, 24);
  }
}

// The 3D kernels' patterns lie inside their support orbits (a volume, a
// face, an edge): the touched darts' own support orbits hold every match to
// re-match, which this checks through tears of faces, springs and vertices.
TEST(Rematch, EveryBlockInteractionHoldsTheMatchesOfTheWholeTornMap) {
  tear_and_check("rematch3d_hex", "block:hex:4x3x3",
                 interaction_table("stretch", "stiffness = 60.0") +
                     interaction_table("shear", "stiffness = 43.0") +
                     interaction_table("volume_shear", "stiffness = 43.0"),
                 {"global_face", "spring_split", "atomic_face", "vertex_sum"}, 3, 16);
  tear_and_check("rematch3d_tet", "block:tet:3x3x3",
                 interaction_table("stretch", "stiffness = 60.0") +
                     interaction_table("corotational", "young = 1000.0"),
                 {"global_face", "spring_split", "vertex_sum"}, 2, 16);
}

/// The kernel's words as text, "" for the empty word: "{}, {1}, {1,0}".
template <class Kernel>
std::string words_of() {
  std::string out;
  for (const ReachWord& w : Kernel::kReach) {
    std::string links;
    for (int k = 0; k < w.length; ++k)
      links += (k ? "," : "") + std::to_string(w.links[static_cast<std::size_t>(k)]);
    out += (out.empty() ? "{" : ", {") + links + "}";
  }
  return out;
}

// riftc leaves out each word's first links that stay in the support orbit
// (the re-match walks the support orbit whole): a pattern inside its support
// orbit keeps the empty word alone, and the others only the links that leave
// it. The completeness tests above pass with longer words too; this one
// fails when the words are not reduced.
TEST(Rematch, WordsLeaveOutTheLinksInsideTheSupportOrbit) {
  // Support <0,1> (a face), links 0 and 1 only: eight words before.
  EXPECT_EQ(words_of<packs::mass_spring2d::ShearKernel>(), "{}");
  // Support <0> (an edge): {} and {0} before.
  EXPECT_EQ(words_of<packs::mass_spring2d::StretchKernel>(), "{}");
  // Support <2>: {2}, {2,1} and {2,1,0} lose their first link.
  EXPECT_EQ(words_of<packs::mass_spring2d::BendKernel>(), "{}, {1}, {1,0}");
  // A hexahedron's volume shear (support <0,1,2>): 48 words before.
  EXPECT_EQ(words_of<packs::mass_spring3d::VolumeShearKernel>(), "{}");
}

}  // namespace
}  // namespace rift::tearing_test
