// polar_rotation (the co-rotational kernels' R) against the Jacobi SVD on
// random, nearly rigid, inverted and degenerate matrices.
#include "rift/core/polar.hpp"

#include <gtest/gtest.h>

#include <random>

namespace rift {
namespace {

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<Real> n(0, 1);
  Eigen::Quaternion<Real> q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Mat3 random_matrix(std::mt19937& rng, Real scale = 1) {
  std::uniform_real_distribution<Real> u(-scale, scale);
  Mat3 m;
  for (int i = 0; i < 9; ++i)
    m(i) = u(rng);
  return m;
}

/// R is a proper rotation and no worse than the SVD's at maximising tr(Rᵀ F).
void expect_optimal_rotation(const Mat3& r, const Mat3& f, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_LT((r.transpose() * r - Mat3::Identity()).norm(), 1e-12);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  const Mat3 ref = polar_rotation_svd(f);
  EXPECT_GE((r.transpose() * f).trace(), (ref.transpose() * f).trace() - 1e-12 * (1 + f.norm()));
}

TEST(PolarRotation, MatchesTheSvdOnRandomMatrices) {
  std::mt19937 rng(7);
  int compared = 0;
  for (int k = 0; k < 20000; ++k) {
    const Mat3 f = random_matrix(rng, k % 2 ? 1.0 : 1e3);
    const Mat3 r = polar_rotation(f);
    expect_optimal_rotation(r, f, "random");
    // Where R is well conditioned (the two largest signed singular values of
    // the top pair are well apart from cancelling), it is unique: compare.
    Eigen::JacobiSVD<Mat3> svd(f);
    const Vec3 s = svd.singularValues();
    const Real s3 = f.determinant() < 0 ? -s(2) : s(2);
    if (s(1) + s3 > 1e-3 * s(0)) {
      EXPECT_LT((r - polar_rotation_svd(f)).norm(), 1e-9) << f;
      ++compared;
    }
  }
  EXPECT_GT(compared, 15000);
}

TEST(PolarRotation, RecoversTheRotationOfAStretchedRotation) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> stretch(0.5, 2.0);
  for (int k = 0; k < 2000; ++k) {
    const Mat3 q = random_rotation(rng);
    const Mat3 r0 = random_rotation(rng);
    const Mat3 s = q * Vec3(stretch(rng), stretch(rng), stretch(rng)).asDiagonal() * q.transpose();
    const Mat3 r = polar_rotation(r0 * s);
    EXPECT_LT((r - r0).norm(), 1e-12);
    // Nearly rigid: a small symmetric perturbation of the identity.
    const Mat3 e = random_matrix(rng, 1e-6);
    EXPECT_LT((polar_rotation(r0 * (Mat3::Identity() + e + e.transpose())) - r0).norm(), 1e-12);
  }
  EXPECT_LT((polar_rotation(Mat3::Identity()) - Mat3::Identity()).norm(), 1e-15);
}

TEST(PolarRotation, InvertedMatricesGiveAProperRotation) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<Real> stretch(0.2, 3.0);
  for (int k = 0; k < 2000; ++k) {
    const Mat3 u = random_rotation(rng), v = random_rotation(rng);
    Vec3 s(stretch(rng), stretch(rng), stretch(rng));
    std::sort(s.data(), s.data() + 3, std::greater<>());
    // det F < 0: the smallest singular axis is flipped, R = U diag(1,1,-1)... Vᵀ
    // with the flip on the smallest axis.
    const Mat3 f = u * Vec3(s(0), s(1), -s(2)).asDiagonal() * v.transpose();
    const Mat3 r = polar_rotation(f);
    expect_optimal_rotation(r, f, "inverted");
    if (s(1) - s(2) > 1e-3) {
      EXPECT_LT((r - u * v.transpose()).norm(), 1e-9);
    }
  }
  // A tetrahedron turned inside out through one face: F = diag(1, 1, -0.5).
  const Mat3 flat = Vec3(1, 1, -0.5).asDiagonal();
  EXPECT_LT((polar_rotation(flat) - Mat3::Identity()).norm(), 1e-12);
}

TEST(PolarRotation, DegenerateMatricesGiveAProperRotation) {
  std::mt19937 rng(17);
  for (int k = 0; k < 2000; ++k) {
    const Mat3 u = random_rotation(rng), v = random_rotation(rng);
    const Real a = 0.1 + (k % 7);
    const Vec3 cases[] = {
        {a, a * 0.5, 0},         // rank 2 (a flattened tetrahedron)
        {a, 0, 0},               // rank 1 (collapsed to a segment)
        {0, 0, 0},               // collapsed to a point
        {a, a, a * 1e-12},       // nearly flat
        {a, a * 0.3, -a * 0.3},  // inverted, the two smallest cancel: R not unique
        {a, a * 0.3, -a * (0.3 - 1e-9)},
        {a, a, -a},  // inverted, fully symmetric
    };
    for (const Vec3& s : cases) {
      const Mat3 f = u * s.asDiagonal() * v.transpose();
      expect_optimal_rotation(polar_rotation(f), f, "degenerate");
    }
    // Rank 2 with distinct values has a unique closest rotation.
    const Mat3 f = u * Vec3(a, 0.5 * a, 0).asDiagonal() * v.transpose();
    EXPECT_LT((polar_rotation(f) - u * v.transpose()).norm(), 1e-8);
  }
}

TEST(PolarRotation, NonFiniteInputGivesNonFiniteOutputNotAHang) {
  Mat3 f = Mat3::Identity();
  f(1, 2) = std::numeric_limits<Real>::quiet_NaN();
  const Mat3 r = polar_rotation(f);
  EXPECT_FALSE(r.allFinite());
}

}  // namespace
}  // namespace rift
