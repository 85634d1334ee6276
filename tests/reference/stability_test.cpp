// The time step of docs/physics.md: the hand estimate of the highest
// frequency, the RK4 stability limit from the linearised cloth, and runs that
// stay bounded below that limit and blow up above it.
#include <gtest/gtest.h>

#include <cmath>

#include "linear_stability.hpp"
#include "stability.hpp"

namespace rift::reference {
namespace {

// RK4's stability interval on the negative real axis, |R(-x)| = 1 at x = 2.785...
Real rk4_real_axis_limit() {
  Real lo = 1, hi = 4;
  for (int it = 0; it < 80; ++it) {
    const Real mid = (lo + hi) / 2;
    (rk4_amplification({-mid, 0}) <= 1 ? lo : hi) = mid;
  }
  return lo;
}

TEST(TimeStep, HandEstimateBracketsTheHighestFrequency) {
  // docs/physics.md: at rest, without damping, w_max^2 lies between the
  // Rayleigh quotient of the mode u_ij = (-1)^i e_x and Gershgorin's bound
  // 2 * 366 N/m / 1 g (the same for interior, edge and corner vertices).
  ClothParameters p;
  p.gravity = Vec3::Zero();
  p.stretch_c = p.shear_c = p.bend_c = 0;
  const int n = 10;
  ReferenceCloth cloth(make_grid(GridKind::Quad, n, n), p);
  const Spectrum s = linear_spectrum(cloth);

  // Rayleigh quotient u.K u / u.M u, with K u from central differences of the forces.
  const std::size_t count = cloth.vertex_count();
  std::vector<Vec3> u(count), xp(count), xm(count), fp(count), fm(count);
  std::vector<Vec3> zero(count, Vec3::Zero());
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i)
      u[grid_point(n, i, j)] = Vec3(i % 2 == 0 ? 1 : -1, 0, 0);
  }
  const Real eps = 1e-6;
  for (std::size_t k = 0; k < count; ++k) {
    xp[k] = cloth.positions()[k] + eps * u[k];
    xm[k] = cloth.positions()[k] - eps * u[k];
  }
  cloth.internal_forces(xp.data(), zero.data(), fp.data());
  cloth.internal_forces(xm.data(), zero.data(), fm.data());
  Real uku = 0, umu = 0;
  for (std::size_t k = 0; k < count; ++k) {
    uku -= u[k].dot(fp[k] - fm[k]) / (2 * eps);
    umu += cloth.masses()[k] * u[k].squaredNorm();
  }
  const Real gershgorin = std::sqrt(2 * 366.0 / 0.001);
  EXPECT_GE(s.max_imaginary, std::sqrt(uku / umu) * (1 - 1e-6));
  EXPECT_LE(s.max_imaginary, gershgorin);
  // Interior rows of that mode give 652 N/m per gram: the bracket is tight.
  EXPECT_GE(s.max_imaginary, 0.9 * std::sqrt(652.0 / 0.001));
}

class Meshes : public ::testing::TestWithParam<GridKind> {};

TEST_P(Meshes, ChosenStepIsInsideTheRk4RegionWithMargin) {
  ReferenceCloth cloth = settled_cloth(GetParam());
  const Spectrum s = linear_spectrum(cloth);
  EXPECT_LE(s.max_amplification(kPaperDt), 1 + 1e-9);
  EXPECT_GE(s.rk4_limit(), 2 * kPaperDt);
}

TEST_P(Meshes, RunsStayBoundedBelowTheLimitAndBlowUpAbove) {
  ReferenceCloth cloth = settled_cloth(GetParam());
  const Real limit = linear_spectrum(cloth).rk4_limit();
  for (int multiple : {1, 2, 4, 8}) {
    const Real dt = multiple * kPaperDt;
    if (dt < 0.9 * limit) {
      EXPECT_FALSE(blow_up_time(GetParam(), dt)) << multiple << " x dt";
    } else if (dt > 1.1 * limit) {
      EXPECT_TRUE(blow_up_time(GetParam(), dt)) << multiple << " x dt";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Table2, Meshes,
                         ::testing::Values(GridKind::Quad, GridKind::Tri, GridKind::Mix));

TEST(TimeStep, DampingSetsTheQuadLimitOnTheRealAxis) {
  // The stiffest mode of the damped quad cloth is overdamped: its eigenvalue
  // is real, and the limit is RK4's real-axis interval over it.
  ReferenceCloth cloth = settled_cloth(GridKind::Quad);
  const Spectrum s = linear_spectrum(cloth);
  EXPECT_NEAR(s.rk4_limit() * -s.most_negative_real, rk4_real_axis_limit(), 1e-3);
  EXPECT_NEAR(rk4_real_axis_limit(), 2.785, 1e-3);
}

}  // namespace
}  // namespace rift::reference
