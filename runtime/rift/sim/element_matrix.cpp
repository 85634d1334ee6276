#include "rift/sim/element_matrix.hpp"

#include <algorithm>
#include <cmath>

namespace rift {

namespace {

// The projection on a matrix type: fixed-size (on the stack, unrolled) for
// the common element sizes, or the dynamic scratch for the others.
template <class Matrix, class Cholesky, class Eigensolver>
bool project(Mat3* blocks, int k, Matrix& s, Cholesky& cholesky, Eigensolver& eigen) {
  const int dofs = 3 * k;
  // s = -(J + Jᵀ)/2: CG needs a symmetric matrix, and the forces of a
  // potential have a symmetric Jacobian already.
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      s.template block<3, 3>(3 * i, 3 * j) = -blocks[i * k + j];
  for (int a = 0; a < dofs; ++a) {
    for (int b = a + 1; b < dofs; ++b) {
      const Real mean = 0.5 * (s(a, b) + s(b, a));
      s(a, b) = s(b, a) = mean;
    }
  }
  const Real scale = s.diagonal().cwiseAbs().maxCoeff();
  if (scale == 0) return false;
  // A cheap test first: a Cholesky factorisation exists exactly when the
  // matrix is positive definite, so most elements stop here. Element
  // matrices are singular (rigid translations cost nothing): the test
  // factors s + tiny·I, positive definite whenever s is semidefinite up to
  // rounding.
  const Real tiny = 1e-10 * scale;
  s.diagonal().array() += tiny;
  cholesky.compute(s);
  s.diagonal().array() -= tiny;
  if (cholesky.info() == Eigen::Success) return false;
  eigen.compute(s);
  const auto& lambda = eigen.eigenvalues();
  const auto& q = eigen.eigenvectors();
  if (lambda.minCoeff() >= -tiny) return false;  // semidefinite after all
  s.setZero();
  for (int c = 0; c < dofs; ++c) {
    if (lambda(c) > 0) s.noalias() += lambda(c) * q.col(c) * q.col(c).transpose();
  }
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      blocks[i * k + j] = -s.template block<3, 3>(3 * i, 3 * j);
  return true;
}

template <int kDofs>
bool project_fixed(Mat3* blocks, int k) {
  using Matrix = Eigen::Matrix<Real, kDofs, kDofs>;
  Matrix s;
  Eigen::LLT<Matrix> cholesky;
  Eigen::SelfAdjointEigenSolver<Matrix> eigen;
  return project(blocks, k, s, cholesky, eigen);
}

}  // namespace

bool project_to_semidefinite(Mat3* blocks, int k, ProjectionScratch& scratch) {
  switch (k) {
    case 2:
      return project_fixed<6>(blocks, k);  // springs
    case 3:
      return project_fixed<9>(blocks, k);  // triangles
    case 4:
      return project_fixed<12>(blocks, k);  // tetrahedra, quads, hinges
    default:
      return project(blocks, k, scratch.dense, scratch.cholesky, scratch.eigen);
  }
}

void ElementMatrix::set_models(std::span<ForceModel* const> models) {
  elements_.clear();
  scratch_.clear();
  for (ForceModel* m : models) {
    ElementBlocks e;
    e.model = m;
    e.k = m->jacobian_vertices();
    scratch_.emplace_back(3 * e.k);
    elements_.push_back(std::move(e));
  }
}

void ElementMatrix::assemble(const ForceInput& in, Real h, std::size_t n, std::vector<Vec3>& kxv) {
  kxv.assign(n, Vec3::Zero());
  projected_ = 0;
  for (std::size_t model = 0; model < elements_.size(); ++model) {
    ElementBlocks& e = elements_[model];
    const std::size_t k = static_cast<std::size_t>(e.k);
    e.matches = e.model->active_matches();
    // resize() keeps the capacity: after the largest match count seen,
    // assembling allocates nothing.
    e.slots.resize(e.matches * k);
    e.blocks.resize(e.matches * k * k);
    e.dfdv.resize(e.matches * k * k);
    e.model->jacobians(in, e.slots.data(), e.blocks.data(), e.dfdv.data());
    const Real h2 = h * h;
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      Mat3* c = e.blocks.data() + m * k * k;
      Mat3* dv = e.dfdv.data() + m * k * k;
      if (project_) {
        projected_ += project_to_semidefinite(c, e.k, scratch_[model]);
        projected_ += project_to_semidefinite(dv, e.k, scratch_[model]);
      }
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
          Mat3& b = c[i * k + j];  // holds ∂f_i/∂x_j on entry
          if (s[i] != kNoSlot && s[j] != kNoSlot) kxv[s[i]] += b * in.v[s[j]];
          b = -(h2 * b + h * dv[i * k + j]);
        }
      }
    }
  }
}

void ElementMatrix::multiply(const Vec3* p, Vec3* out, std::size_t n) const {
  for (std::size_t i = 0; i < n; ++i)
    out[i].setZero();
  for (const ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      const Mat3* c = e.blocks.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        if (s[i] == kNoSlot) continue;
        Vec3 sum = Vec3::Zero();
        for (std::size_t j = 0; j < k; ++j) {
          if (s[j] != kNoSlot) sum += c[i * k + j] * p[s[j]];
        }
        out[s[i]] += sum;
      }
    }
  }
}

void ElementMatrix::add_diagonal(Mat3* diag) const {
  for (const ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      const Mat3* c = e.blocks.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        if (s[i] != kNoSlot) diag[s[i]] += c[i * k + i];
      }
    }
  }
}

}  // namespace rift
