// The generated mass-spring pack against the hand-written flat-array
// reference (tests/reference/reference_cloth.hpp): the paper's hung cloth,
// three meshes, same trajectory to round-off.
#include <gtest/gtest.h>

#include "../reference/paper_cloth.hpp"
#include "physics_setup.hpp"

namespace rift::physics_test {
namespace {

using reference::kPaperDt;

TEST(Reference, GeneratedClothFollowsTheHandWrittenSolver) {
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    SCOPED_TRACE(static_cast<int>(kind));
    const int n = 10;
    const MeshData mesh = reference::hanging_grid(kind, n, n);
    SimSetup setup;
    setup.settings.integrator = IntegratorKind::kRK4;
    setup.settings.dt = kPaperDt;
    setup.interactions = paper_cloth_springs();
    setup.prepare = [&](Simulation& sim) {
      sim.set_total_mass(0.1);
      const Vec3 left = mesh.points[reference::grid_point(n, 0, n)];
      const Vec3 right = mesh.points[reference::grid_point(n, n, n)];
      EXPECT_EQ(sim.pin_where([&](const Vec3& x) {
        return (x - left).norm() < 1e-9 || (x - right).norm() < 1e-9;
      }),
                2u);
    };
    auto sim = simulate(assemble_gmap(mesh), setup);
    reference::ReferenceCloth cloth = reference::paper_cloth(kind, n, n);
    const Embedding<std::int64_t> point = sim->map().embedding<std::int64_t>("point_index");
    Real worst = 0;
    for (int s = 0; s < 400; ++s) {
      sim->step();
      cloth.step_rk4(kPaperDt);
    }
    sim->map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
      worst = std::max(worst, (sim->position()[d] - cloth.positions()[point[d]]).norm());
      worst = std::max(worst, (sim->velocity()[d] - cloth.velocities()[point[d]]).norm());
    });
    EXPECT_LT(worst, 1e-11);
    EXPECT_GT(cloth.kinetic_energy(), 1e-6);  // it moved
    EXPECT_NEAR(sim->kinetic_energy(), cloth.kinetic_energy(), 1e-12);
    EXPECT_NEAR(elastic_energy(*sim), cloth.elastic_energy(), 1e-12);
  }
}

}  // namespace
}  // namespace rift::physics_test
