// The semidefinite projection of element matrices (element_matrix.hpp): a
// compressed spring's Jacobian is indefinite and gets projected, a stretched
// one is left exactly as it is, and the projection is the nearest
// semidefinite matrix (eigenvalues of -J clamped at zero, eigenvectors kept).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>
#include <vector>

#include "rift/sim/element_matrix.hpp"

namespace rift {
namespace {

// ∂f/∂x of a spring of stiffness k and rest length rest between vertices at
// a and b, as 2×2 blocks (row-major): f_a = k (L - rest) n.
std::vector<Mat3> spring_jacobian(const Vec3& a, const Vec3& b, Real k, Real rest) {
  const Vec3 d = b - a;
  const Real length = d.norm();
  const Vec3 n = d / length;
  const Mat3 nn = n * n.transpose();
  const Mat3 kab = k * (nn + (1 - rest / length) * (Mat3::Identity() - nn));
  return {-kab, kab, kab, -kab};
}

Eigen::MatrixXd dense_minus(const std::vector<Mat3>& blocks, int k) {
  Eigen::MatrixXd s(3 * k, 3 * k);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      s.block<3, 3>(3 * i, 3 * j) = -blocks[i * k + j];
  return s;
}

Real smallest_eigenvalue(const Eigen::MatrixXd& s) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s).eigenvalues().minCoeff();
}

TEST(Definiteness, StretchedSpringIsLeftExactlyAsItIs) {
  std::vector<Mat3> j = spring_jacobian(Vec3(0, 0, 0), Vec3(1.5, 0.2, 0.1), 100, 1.0);
  const std::vector<Mat3> before = j;
  EXPECT_FALSE(project_to_semidefinite(j.data(), 2));
  for (std::size_t b = 0; b < j.size(); ++b)
    EXPECT_EQ(j[b], before[b]);
}

TEST(Definiteness, CompressedSpringBecomesSemidefiniteAlongItsAxisUnchanged) {
  const Vec3 a(0, 0, 0), b(0.5, 0.1, 0);
  std::vector<Mat3> j = spring_jacobian(a, b, 100, 1.0);  // half its rest length
  ASSERT_LT(smallest_eigenvalue(dense_minus(j, 2)), -1);  // transverse: k (1 - 1/0.5) < 0
  EXPECT_TRUE(project_to_semidefinite(j.data(), 2));
  const Eigen::MatrixXd s = dense_minus(j, 2);
  EXPECT_GE(smallest_eigenvalue(s), -1e-9);
  EXPECT_LT((s - s.transpose()).norm(), 1e-12);
  // The axial stiffness is positive and stays; the transverse part, negative,
  // goes to zero: -J = k [nn, -nn; -nn, nn].
  const Vec3 n = (b - a).normalized();
  const Mat3 nn = n * n.transpose();
  EXPECT_LT((j[0] + 100 * nn).norm(), 1e-9);
  EXPECT_LT((j[1] - 100 * nn).norm(), 1e-9);
}

TEST(Definiteness, ProjectionIsTheNearestSemidefiniteMatrix) {
  // Random symmetric 12×12 (a tetrahedron's size): projecting keeps the
  // eigenvectors, clamps the negative eigenvalues, and no random
  // semidefinite matrix is closer in the Frobenius norm.
  std::mt19937 rng(7);
  std::normal_distribution<Real> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::MatrixXd s(12, 12);
    for (int r = 0; r < 12; ++r)
      for (int c = 0; c < 12; ++c)
        s(r, c) = u(rng);
    s = 0.5 * (s + s.transpose());
    std::vector<Mat3> j(16);
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k)
        j[i * 4 + k] = -s.block<3, 3>(3 * i, 3 * k);
    ASSERT_TRUE(project_to_semidefinite(j.data(), 4));
    const Eigen::MatrixXd p = dense_minus(j, 4);
    EXPECT_GE(smallest_eigenvalue(p), -1e-9);
    const Real distance = (p - s).norm();
    for (int other = 0; other < 20; ++other) {
      Eigen::MatrixXd g(12, 12);
      for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 12; ++c)
          g(r, c) = u(rng);
      const Eigen::MatrixXd candidate = p + 0.1 * g * g.transpose();  // semidefinite too
      EXPECT_LE(distance, (candidate - s).norm() + 1e-12);
    }
  }
}

}  // namespace
}  // namespace rift
