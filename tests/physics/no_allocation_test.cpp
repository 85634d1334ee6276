// "A step allocates nothing" (issue 4): the generated packs' force passes,
// the integrator and the criteria's evaluation run without a heap allocation
// once warm. Every operator new of this test binary is counted
// (allocation_watch.hpp).
#include <gtest/gtest.h>

#include "allocation_watch.hpp"
#include "physics_setup.hpp"
#include "rift/core/huge_pages.hpp"
#include "standard_packs.hpp"

namespace rift::physics_test {
namespace {

long allocations_during_steps(GridKind kind, const std::vector<Use>& criteria, int steps,
                              IntegratorKind integrator = IntegratorKind::kRK4,
                              JacobianMode jacobian = JacobianMode::kAssembled) {
  SimSetup setup;
  setup.settings = {integrator, 5e-4, Vec3(0, 0, -9.81), 0, false};
  setup.settings.implicit.jacobian = jacobian;
  setup.interactions = {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}},
                        {"shear", {{"stiffness", 43.0}, {"damping", 0.1}}},
                        {"bend", {{"stiffness", 10.0}, {"damping", 0.1}}}};
  setup.criteria = criteria;
  setup.prepare = [](Simulation& sim) {
    sim.set_total_mass(0.1);
    sim.pin_where([](const Vec3& p) { return p.y() > 0.99 && (p.x() < 0.01 || p.x() > 0.99); });
  };
  auto sim = simulate(assemble_gmap(make_grid(kind, 10, 10)), setup);
  for (int s = 0; s < 10; ++s)
    sim->step();  // warm-up: buffers reach their size
  const long before = test_support::allocation_count();
  for (int s = 0; s < steps; ++s)
    sim->step();
  EXPECT_EQ(sim->tears(), 0u);
  return test_support::allocation_count() - before;
}

TEST(NoAllocation, Rk4StepsOfTheClothAllocateNothing) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    EXPECT_EQ(allocations_during_steps(kind, {}, 100), 0) << static_cast<int>(kind);
  }
}

TEST(NoAllocation, ImplicitEulerStepsOfTheClothAllocateNothing) {
  // Element Jacobians, block Jacobi and CG: every buffer keeps its capacity.
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    EXPECT_EQ(allocations_during_steps(kind, {}, 20, IntegratorKind::kImplicitEuler), 0)
        << static_cast<int>(kind);
  }
  EXPECT_EQ(allocations_during_steps(GridKind::Mix, {}, 20, IntegratorKind::kImplicitEuler,
                                     JacobianMode::kMatrixFree),
            0);
}

TEST(NoAllocation, Bdf2StepsOfTheClothAllocateNothing) {
  // BDF2 keeps the previous state and its extrapolation in buffers of its
  // own (bdf2.hpp) on top of implicit Euler's; the warm-up's first step is
  // the backward Euler start, every counted step a BDF2 step.
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    EXPECT_EQ(allocations_during_steps(kind, {}, 20, IntegratorKind::kBdf2), 0)
        << static_cast<int>(kind);
  }
  EXPECT_EQ(allocations_during_steps(GridKind::Mix, {}, 20, IntegratorKind::kBdf2,
                                     JacobianMode::kMatrixFree),
            0);
}

TEST(NoAllocation, EvaluatingACriterionThatDoesNotHoldAllocatesNothing) {
  EXPECT_EQ(allocations_during_steps(GridKind::Quad, {{"global_edge", {{"threshold", 1e3}}}}, 100),
            0);
}

// A tear as the loop pays it (the criterion's rewrite, then the masses and
// the re-match around the touched darts) on a cloth whose arrays all have
// headroom: once warm, it appends in place and allocates nothing.
long allocations_of_warm_tears(GMap map, const std::vector<Use>& interactions, int* tears) {
  SimSetup setup;
  setup.registry = &test_support::standard_packs();
  setup.interactions = interactions;
  setup.criteria = {{"spring_split", {{"threshold", 1e-9}}}};
  auto sim = simulate(std::move(map), setup);
  move_vertices(*sim, [](const Vec3& p) { return Vec3(1.1 * p.x(), 1.05 * p.y(), p.z()); });
  const auto& x = sim->position().values();
  const auto& v = sim->velocity().values();
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  for (const auto& m : sim->force_models())
    m->add_forces({x.data(), v.data()}, f.data(), true);
  std::vector<TearCandidate> candidates;
  sim->criteria()[0]->collect(sim->map(), candidates);
  EXPECT_GT(candidates.size(), 200u);
  std::vector<Dart> touched;
  touched.reserve(1 << 14);
  std::size_t next = 0;
  // The next candidate still alive, spread over the mesh, torn as the loop
  // tears it (Simulation::on_topology_changed: masses, re-match).
  auto tear = [&] {
    for (; next < candidates.size(); ++next) {
      if (!tear_at(*sim, candidates[(next * 7919) % candidates.size()], touched)) continue;
      ++next;
      return true;
    }
    return false;
  };
  for (int k = 0; k < 20; ++k)
    EXPECT_TRUE(tear());  // warm-up: scratch buffers reach their size
  const long before = test_support::allocation_count();
  *tears = 0;
  for (int k = 0; k < 40 && tear(); ++k)
    ++*tears;
  const long allocations = test_support::allocation_count() - before;
  EXPECT_TRUE(sim->map().check_validity(5).empty());
  return allocations;
}

// A tear as the loop pays it (the criterion's rewrite, then the masses and
// the re-match around the touched darts) on a mesh whose arrays all have
// headroom (huge_pages.hpp): once warm, it appends in place and allocates
// nothing, scripts that call scripts included.
TEST(NoAllocation, WarmTearsAllocateNothing) {
  set_headroom_factor(4, 0);
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    int tears = 0;
    EXPECT_EQ(allocations_of_warm_tears(assemble_gmap(make_grid(kind, 30, 30)),
                                        paper_cloth_springs(), &tears),
              0)
        << static_cast<int>(kind) << ", " << tears << " tears";
    EXPECT_GT(tears, 30);
  }
  for (const char* block : {"block:hex:6x6x6", "block:tet:5x5x5"}) {
    int tears = 0;
    EXPECT_EQ(allocations_of_warm_tears(assemble_gmap(make_generated_mesh(block)),
                                        {{"stretch", {{"stiffness", 60.0}}}}, &tears),
              0)
        << block << ", " << tears << " tears";
    EXPECT_GT(tears, 30) << block;
  }
  set_headroom_factor(2);
}

// rift run --check validates the whole map after every rewrite: on a valid
// map the check is flat passes over kept scratch arrays, no string, no new.
TEST(NoAllocation, CheckingAValidMapAllocatesNothing) {
  for (const char* mesh : {"grid:mix:20x20", "block:tet:4x4x4", "block:hex:4x4x4"}) {
    GMap map = assemble_gmap(make_generated_mesh(mesh));
    map.add_embedding<Real>("corner_value", Orbit{1}, MergePolicy::kKeepFirst, 0.0);
    ASSERT_TRUE(map.check_validity(5).empty()) << mesh;  // warm-up
    const long before = test_support::allocation_count();
    const bool valid = map.check_validity(5).empty();
    EXPECT_EQ(test_support::allocation_count() - before, 0) << mesh;
    EXPECT_TRUE(valid) << mesh;
  }
}

std::vector<int>* volatile g_sink = nullptr;

TEST(NoAllocation, TheCounterSeesAllocations) {
  const long before = test_support::allocation_count();
  auto* p = new std::vector<int>(100);
  // Let the pointer escape: the compiler may otherwise elide the pair of
  // allocations (new-expressions may be merged or removed since C++14).
  g_sink = p;
  delete p;
  EXPECT_GE(test_support::allocation_count() - before, 2);
}

}  // namespace
}  // namespace rift::physics_test
