// Simulation::report_memory (what `rift bench --json` reports as `memory`):
// every large array of a scene under its owner, each counted exactly as the
// bytes of its elements, following the map through tears; columns without
// storage and interactions' arrays a scene does not keep are not listed.
#include <gtest/gtest.h>

#include <string>

#include "rift/core/memory_report.hpp"
#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

std::size_t bytes_of(const MemoryReport& report, const std::string& owner,
                     const std::string& what) {
  std::size_t found = 0;
  for (const MemoryReport::Item& i : report.items()) {
    if (i.owner == owner && i.what == what) found += i.bytes;
  }
  return found;
}

// What the report must say of the map and its columns, counted here from
// the map itself.
void expect_map_counted(const Simulation& sim, const MemoryReport& report) {
  const GMap& map = sim.map();
  for (int i = 0; i <= map.dimension(); ++i) {
    EXPECT_EQ(bytes_of(report, "map", "alpha" + std::to_string(i) + " links"),
              map.capacity() * sizeof(Dart))
        << i;
  }
  const OrbitAttachment& darts = *map.attachment_of("f_stretch");
  // <> is by dart: one bit a dart, no slot of each dart, no darts of each slot.
  EXPECT_EQ(bytes_of(report, "attachment <>", "darts holding their value (bits)"),
            (map.capacity() + 63) / 64 * sizeof(std::uint64_t));
  EXPECT_EQ(bytes_of(report, "attachment <>", "slot of each dart"), 0u);
  EXPECT_EQ(bytes_of(report, "attachment <>", "darts of each slot"), 0u);
  EXPECT_EQ(bytes_of(report, "column f_stretch", "values"), darts.slot_capacity() * sizeof(Vec3));
  const OrbitAttachment& vertices = sim.position().attachment();
  EXPECT_EQ(bytes_of(report, "column position", "values"), vertices.slot_capacity() * sizeof(Vec3));
  // atomic_edge reads f_membrane, which no interaction of the scene writes:
  // it keeps no storage (lean memory), and the report lists none.
  EXPECT_EQ(report.of("column f_membrane"), 0u);
}

TEST(MemoryReport, CountsEachArrayOfAQuadClothUnderItsOwnerThroughTears) {
  const std::string toml = static_scene("grid:quad:8x6", "1.0", 1.0,
                                        interaction_table("stretch", "stiffness = 60.0") +
                                            interaction_table("shear", "stiffness = 40.0") +
                                            interaction_table("bend", "stiffness = 10.0") +
                                            criterion_table("atomic_edge", 0.05));
  auto sim = simulate("memory_report", toml);
  sim->step();
  MemoryReport before;
  sim->report_memory(before);
  expect_map_counted(*sim, before);
  // The criterion's cells: one dart per edge (after a tear, the list follows
  // the new edges at the next collection).
  EXPECT_EQ(bytes_of(before, "criterion atomic_edge", "cells"),
            sim->map().count_cells_of_dimension(1) * sizeof(Dart));
  for (const auto& model : sim->force_models()) {
    const std::string owner = "interaction " + model->name();
    EXPECT_GT(bytes_of(before, owner, "matches"), 0u) << owner;
    // The owner index: an array by dart, or a hash table where that is
    // smaller (owner_index.hpp), never both.
    const std::size_t array = bytes_of(before, owner, "entry of each dart");
    const std::size_t table = bytes_of(before, owner, "entries of the owners (hash table)");
    EXPECT_TRUE((array > 0) != (table > 0)) << owner << ": " << array << " and " << table;
    if (model->name() == "shear") {
      // One match per quad of 8 darts: 128 cells of 8 bytes beat 4 bytes a dart (384 darts).
      EXPECT_EQ(array, 0u);
      EXPECT_LT(table, sim->map().capacity() * sizeof(std::uint32_t));
    }
  }
  // RK4's four stage arrays, and the loop's forces and start forces.
  const std::size_t vertex_slots = sim->position().attachment().slot_capacity();
  EXPECT_EQ(bytes_of(before, "integrator", "stage arrays"), 4 * vertex_slots * sizeof(Vec3));
  EXPECT_EQ(bytes_of(before, "simulation", "forces"), vertex_slots * sizeof(Vec3));
  // The total is the sum of the items, and no item is empty.
  std::size_t sum = 0;
  for (const MemoryReport::Item& i : before.items()) {
    EXPECT_GT(i.bytes, 0u) << i.owner << " " << i.what;
    sum += i.bytes;
  }
  EXPECT_EQ(before.total(), sum);

  // Tear it: the vertices the separated faces split are counted too.
  deform(*sim, [](const Vec3& p) { return Vec3(1.6 * p.x(), p.y(), p.z()); });
  for (int s = 0; s < 3 && sim->tears() == 0; ++s)
    sim->step();
  ASSERT_GT(sim->tears(), 0u);
  MemoryReport after;
  sim->report_memory(after);
  expect_map_counted(*sim, after);
  EXPECT_GT(bytes_of(after, "column position", "values"),
            bytes_of(before, "column position", "values"));
}

TEST(MemoryReport, CountsTheImplicitSolversArrays) {
  // A hanging 4x4 cloth on backward Euler with the incomplete Cholesky
  // preconditioner: each interaction's blocks (k² per match, k vertices),
  // their vertex slots, and the factor are listed under "implicit".
  const std::string toml =
      "[mesh]\nsource = \"grid:quad:4x4\"\nrotate = [90, 0, 0]\n"
      "[simulation]\nintegrator = \"implicit_euler\"\ndt = 0.001\nsteps = 2\n"
      "[implicit]\npreconditioner = \"incomplete_cholesky\"\n"
      "[mass]\ntotal = 0.1\n[pin]\ncorners = [\"top-left\", \"top-right\"]\n" +
      interaction_table("stretch", "stiffness = 60.0\ndamping = 0.1") +
      interaction_table("shear", "stiffness = 43.0");
  auto sim = simulate("memory_report_implicit", toml);
  sim->step();
  MemoryReport report;
  sim->report_memory(report);
  ASSERT_NE(sim->implicit(), nullptr);
  std::size_t models = 0;
  for (const ElementBlocks& e : sim->implicit()->blocks().elements()) {
    ++models;
    const std::string of = " (" + e.model->name() + ")";
    const auto k = static_cast<std::size_t>(e.k);
    EXPECT_GT(e.matches, 0u) << of;
    EXPECT_EQ(bytes_of(report, "implicit", "Jacobian blocks" + of),
              e.matches * k * k * sizeof(Mat3))
        << of;
    EXPECT_EQ(bytes_of(report, "implicit", "block vertex slots" + of), e.matches * k * sizeof(Slot))
        << of;
  }
  EXPECT_EQ(models, 2u);
  EXPECT_GT(bytes_of(report, "implicit", "incomplete Cholesky factor"), 0u);
  EXPECT_GT(bytes_of(report, "implicit", "conjugate gradient vectors"), 0u);
  // An explicit scene lists nothing under "implicit".
  auto explicit_sim = simulate(
      "memory_report_explicit",
      static_scene("grid:quad:4x4", "1.0", 0.1, interaction_table("stretch", "stiffness = 60.0")));
  explicit_sim->step();
  MemoryReport none;
  explicit_sim->report_memory(none);
  EXPECT_EQ(none.of("implicit"), 0u);
}

}  // namespace
}  // namespace rift::tearing_test
