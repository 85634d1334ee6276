// The set-up's fast paths (issue 12) against the general algorithms they
// replace, written out here as they were: a fresh attachment's slots must be
// the ones an orbit walk in dart order gives, and the corner masses the ones
// of measuring every element twice. Both feed byte-identical simulations, so
// values are compared exactly, on generated and real meshes of every element
// kind, and the maps must stay valid.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "jittered_mesh.hpp"
#include "rift/io/read_mesh.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/sim/mass_model.hpp"
#include "same_bits.hpp"
#include "shared_test_data.hpp"

namespace rift {
namespace {

using test::same_bits;

// Slots as the general walk numbers them: each orbit gets the next slot when
// the sweep in dart order reaches its first dart.
std::vector<Slot> walked_slots(const GMap& map, Orbit o, std::vector<std::uint32_t>& counts) {
  std::vector<Slot> slot(map.capacity(), kNoSlot);
  counts.clear();
  map.for_each_dart([&](Dart d) {
    if (slot[d] != kNoSlot) return;
    const auto s = static_cast<Slot>(counts.size());
    counts.push_back(0);
    map.for_each_in_orbit(d, o, [&](Dart x) {
      slot[x] = s;
      ++counts[s];
    });
  });
  return slot;
}

// Every orbit type of the map, declared on a fresh attachment, holds the
// walked slots; so do the embeddings assemble_gmap declared itself.
void expect_walked_slots(GMap& map, const std::string& what) {
  const int n = map.dimension();
  for (unsigned mask = 0; mask < (1u << (n + 1)); ++mask) {
    const Orbit o = Orbit::from_mask(static_cast<std::uint8_t>(mask));
    const std::string name = "probe_" + std::to_string(mask);
    if (!map.attachment_of(name)) map.add_embedding<Real>(name, o);
  }
  ASSERT_EQ(map.check_validity(), std::vector<std::string>{}) << what;
  std::vector<std::uint32_t> counts;
  for (const auto& att : map.attachments()) {
    if (att->by_dart()) {
      // <>: each live dart's slot is the dart itself, one dart a slot.
      ASSERT_EQ(att->slot_capacity(), map.capacity()) << what;
      for (std::size_t k = 0; k < map.capacity(); ++k) {
        const auto d = static_cast<Dart>(k);
        ASSERT_EQ(att->slot(d), map.is_alive(d) ? d : kNoSlot) << what << " dart " << d;
        ASSERT_EQ(att->darts_in_slot(d), map.is_alive(d) ? 1u : 0u) << what << " dart " << d;
      }
      continue;
    }
    const std::vector<Slot> want = walked_slots(map, att->orbit(), counts);
    ASSERT_EQ(att->slot_capacity(), counts.size()) << what << " " << att->orbit().str();
    std::size_t wrong = 0;
    map.for_each_dart([&](Dart d) { wrong += att->slot(d) != want[d]; });
    EXPECT_EQ(wrong, 0u) << what << " " << att->orbit().str();
    for (Slot s = 0; s < counts.size(); ++s)
      ASSERT_EQ(att->darts_in_slot(s), counts[s]) << what << " " << att->orbit().str();
  }
}

// The corner masses as they were computed before: every element measured
// once for the total and once more for its mass, its corners walked once to
// count them and once to share the mass.
Real masses_measured_twice(GMap& map, Real total_mass, Embedding<Real>& corner_mass,
                           const Embedding<Vec3>& position) {
  const int n = map.dimension();
  const Orbit element = element_orbit(n);
  const Orbit corner = corner_orbit(n);
  Real measure = 0;
  map.for_each_cell(element, [&](Dart e) { measure += element_measure(map, e, position); });
  const Real density = total_mass / measure;
  Real total = 0;
  map.for_each_cell(element, [&](Dart e) {
    const Real mass = density * element_measure(map, e, position);
    int corners = 0;
    map.for_each_sub_orbit(e, element, corner, [&](Dart) { ++corners; });
    map.for_each_sub_orbit(e, element, corner, [&](Dart c) { corner_mass[c] = mass / corners; });
    total += mass;
  });
  return total;
}

void expect_same_masses(GMap& map, const std::string& what) {
  const int n = map.dimension();
  auto position = map.embedding<Vec3>("position");
  auto by_total = map.add_embedding<Real>("by_total", corner_orbit(n));
  auto by_density = map.add_embedding<Real>("by_density", corner_orbit(n));
  auto reference = map.add_embedding<Real>("reference", corner_orbit(n));
  const Real total = 0.73;
  const Real want = masses_measured_twice(map, total, reference, position);
  const Real got = assign_corner_masses_by_total(map, total, by_total, position);
  EXPECT_TRUE(same_bits(got, want)) << what << ": " << got << " vs " << want;
  // The density path: the same masses when given the density the total implies.
  Real measure = 0;
  map.for_each_cell(element_orbit(n),
                    [&](Dart e) { measure += element_measure(map, e, position); });
  const Real density_total =
      assign_corner_masses_by_density(map, total / measure, by_density, position);
  EXPECT_TRUE(same_bits(density_total, want)) << what;
  std::size_t differ = 0;
  map.for_each_dart([&](Dart d) {
    differ += !same_bits(by_total[d], reference[d]) || !same_bits(by_density[d], reference[d]);
  });
  EXPECT_EQ(differ, 0u) << what;
  EXPECT_GT(want, 0.0) << what;
}

TEST(SetupFastPath, GeneratedMeshesOfEveryKind) {
  for (const char* spec :
       {"grid:quad:7x5", "grid:tri:6x4", "grid:mix:7x6", "block:hex:4x3x3", "block:tet:3x3x2"}) {
    GMap map = assemble_gmap(make_generated_mesh(spec));
    expect_same_masses(map, spec);
    expect_walked_slots(map, spec);
  }
}

TEST(SetupFastPath, SharedMeshes) {
  for (const char* file : {"liver.msh", "square3.msh", "cube.mesh", "triangleGrid_10_10.obj"}) {
    const std::string path = std::string(RIFT_SHARED_MESHES) + "/" + file;
    RIFT_EXPECT_SHARED_MESHES(std::filesystem::exists(path));
    GMap map = assemble_gmap(read_mesh_file(path));
    expect_same_masses(map, file);
    expect_walked_slots(map, file);
  }
}

// Elements that all differ, with warped faces (every vertex moved off the
// grid: a face's fan then depends on the vertex it starts from), and dead
// darts in the numbering (the first element cut off and deleted): the pass
// over the whole map and element_measure still agree bit for bit.
TEST(SetupFastPath, JitteredMeshesWithADeletedElement) {
  for (const char* spec : {"grid:mix:7x6", "block:hex:4x3x3", "block:tet:3x3x2"}) {
    GMap map = assemble_gmap(make_generated_mesh(spec));
    const int n = map.dimension();
    test::jitter_vertices(map, 11, 0.08);
    std::vector<Dart> first;
    map.for_each_in_orbit(0, element_orbit(n), [&](Dart d) { first.push_back(d); });
    for (Dart d : first) {
      if (!map.is_free(d, n)) map.unsew(d, n);
    }
    for (Dart d : first)
      map.delete_dart(d);
    ASSERT_TRUE(map.is_valid()) << spec;
    ASSERT_FALSE(map.is_alive(0)) << spec;
    expect_same_masses(map, std::string(spec) + " jittered");
  }
}

// Dead darts in the middle of the numbering, and free darts: the fast path
// skips the dead ones and gives each free dart its own orbit.
TEST(SetupFastPath, MapWithRecycledAndFreeDarts) {
  GMap map(2);
  const Dart first = map.create_darts(10);
  for (Dart d = first; d < first + 8; d += 2)
    map.link(d, d + 1, 0);
  map.link(first + 1, first + 2, 1);
  map.link(first + 5, first + 6, 1);
  map.delete_dart(first + 8);
  expect_walked_slots(map, "hand-made map");
}

// An attachment whose orbits already hold slots keeps the general walk: a
// new column on it gets the same slots, not fresh ones.
TEST(SetupFastPath, ExistingAttachmentKeepsItsSlots) {
  GMap map = assemble_gmap(make_generated_mesh("grid:mix:3x3"));
  auto first = map.add_embedding<Real>("first", Orbit{0, 1});
  std::vector<Slot> before;
  map.for_each_dart([&](Dart d) { before.push_back(first.slot(d)); });
  auto second = map.add_embedding<Real>("second", Orbit{0, 1});
  std::size_t moved = 0, index = 0;
  map.for_each_dart([&](Dart d) { moved += second.slot(d) != before[index++]; });
  EXPECT_EQ(moved, 0u);
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
}

}  // namespace
}  // namespace rift
