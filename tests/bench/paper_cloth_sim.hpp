// The paper's hanging cloth (Fig. 14, Table 2) as the generated packs of
// rules/ simulate it, shared by the benchmarks: n × n patches of 1 m × 1 m,
// 100 g, stretch, shear and bend springs, its two upper corners pinned, RK4.
#pragma once

#include <memory>

#include "../physics/physics_setup.hpp"
#include "../reference/paper_cloth.hpp"

namespace rift::bench {

/// The paper's dt for 10 × 10 patches, scaled by h²: a finer grid of the same
/// cloth has lighter vertices, and the damped RK4 limit scales as h²
/// (docs/physics.md §5).
inline Real paper_cloth_dt(int n) {
  return reference::kPaperDt * (10.0 / n) * (10.0 / n);
}

/// `grouped`: identical springs evaluated once (the default of rift); false
/// evaluates every atomic spring, to measure what grouping gains.
inline std::unique_ptr<Simulation> paper_cloth_simulation(GridKind kind, int n,
                                                          bool grouped = true) {
  using namespace physics_test;
  const MeshData mesh = reference::hanging_grid(kind, n, n);
  SimSetup setup;
  setup.settings.integrator = IntegratorKind::kRK4;
  setup.settings.dt = paper_cloth_dt(n);
  setup.settings.group_interactions = grouped;
  // As `rift run` sets the scene up: no criterion reads the stored forces.
  setup.lean_forces = true;
  setup.interactions = paper_cloth_springs();
  setup.prepare = [&](Simulation& sim) {
    sim.set_total_mass(0.1);
    const Vec3 left = mesh.points[reference::grid_point(n, 0, n)];
    const Vec3 right = mesh.points[reference::grid_point(n, n, n)];
    sim.pin_where(
        [&](const Vec3& x) { return (x - left).norm() < 1e-9 || (x - right).norm() < 1e-9; });
  };
  return simulate(assemble_gmap(mesh), setup);
}

}  // namespace rift::bench
