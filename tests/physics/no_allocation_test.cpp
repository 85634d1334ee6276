// "A step allocates nothing" (issue 4): the generated packs' force passes,
// the integrator and the criteria's evaluation run without a heap allocation
// once warm. Every operator new of this test binary is counted
// (allocation_watch.hpp).
#include <gtest/gtest.h>

#include "allocation_watch.hpp"
#include "physics_setup.hpp"

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
