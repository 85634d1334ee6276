#include "rift/sim/element_matrix.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <atomic>

#include "rift/core/parallel.hpp"

namespace rift {

void ElementMatrix::report_memory(MemoryReport& report) const {
  for (const ElementBlocks& e : elements_) {
    const std::string of = " (" + e.model->name() + ")";
    report.add("implicit", "Jacobian blocks" + of, e.blocks);
    report.add("implicit", "damping blocks" + of, e.dfdv);
    report.add("implicit", "block vertex slots" + of, e.slots);
    report.add("implicit", "product terms" + of, e.terms);
    report.add("implicit", "product gather" + of, e.gather.bytes());
  }
}

namespace {

// The symmetric part s = -(J + Jᵀ)/2 of an element's blocks: CG needs a
// symmetric matrix, and the forces of a potential have a symmetric Jacobian
// already.
template <class Matrix>
void symmetric_part(const Mat3* blocks, int k, Matrix& s) {
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      s.template block<3, 3>(3 * i, 3 * j) = -blocks[i * k + j];
  const int dofs = 3 * k;
  for (int a = 0; a < dofs; ++a) {
    for (int b = a + 1; b < dofs; ++b) {
      const Real mean = 0.5 * (s(a, b) + s(b, a));
      s(a, b) = s(b, a) = mean;
    }
  }
}

// Clips the negative eigenvalues of s and writes -s back into the blocks.
// Only indefinite elements get here, after the Cholesky screen, so one
// eigensolver of bounded size serves every element type: each fixed-size
// SelfAdjointEigenSolver instantiation cost about ten seconds of compile
// time and bought nothing measurable on this rare path.
template <int kMaxDofs>
bool clip_negative_eigenvalues(Mat3* blocks, int k, const Real* symmetric, Real tiny) {
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDofs, kMaxDofs>;
  const int dofs = 3 * k;
  Matrix s =
      Eigen::Map<const Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>>(symmetric, dofs, dofs);
  Eigen::SelfAdjointEigenSolver<Matrix> eigen(s);
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

// Fixed-size or bounded matrices live on the stack: each thread of the
// assembly projects its own elements without shared scratch.
template <int kDofs, int kMaxDofs = kDofs>
bool project_on_stack(Mat3* blocks, int k) {
  using Matrix = Eigen::Matrix<Real, kDofs, kDofs, 0, kMaxDofs, kMaxDofs>;
  Matrix s(3 * k, 3 * k);
  symmetric_part(blocks, k, s);
  const Real scale = s.diagonal().cwiseAbs().maxCoeff();
  if (scale == 0) return false;
  // A cheap test first: a Cholesky factorisation exists exactly when the
  // matrix is positive definite, so most elements stop here. Element
  // matrices are singular (rigid translations cost nothing): the test
  // factors s + tiny·I, positive definite whenever s is semidefinite up to
  // rounding.
  const Real tiny = 1e-10 * scale;
  s.diagonal().array() += tiny;
  const Eigen::LLT<Matrix> cholesky(s);
  s.diagonal().array() -= tiny;
  if (cholesky.info() == Eigen::Success) return false;
  if (3 * k <= 48) return clip_negative_eigenvalues<48>(blocks, k, s.data(), tiny);
  // Larger patterns are rare enough to allocate their scratch.
  return clip_negative_eigenvalues<Eigen::Dynamic>(blocks, k, s.data(), tiny);
}

}  // namespace

bool project_to_semidefinite(Mat3* blocks, int k) {
  switch (k) {
    case 2:
      return project_on_stack<6>(blocks, k);  // springs
    case 3:
      return project_on_stack<9>(blocks, k);  // triangles
    case 4:
      return project_on_stack<12>(blocks, k);  // tetrahedra, quads, hinges
    default:
      if (k <= 16) return project_on_stack<Eigen::Dynamic, 48>(blocks, k);  // hexahedra...
      return project_on_stack<Eigen::Dynamic, Eigen::Dynamic>(blocks, k);
  }
}

void ElementMatrix::set_models(std::span<ForceModel* const> models) {
  elements_.clear();
  for (ForceModel* m : models) {
    ElementBlocks e;
    e.model = m;
    e.k = m->jacobian_vertices();
    e.semidefinite = m->jacobian_semidefinite();
    elements_.push_back(std::move(e));
  }
}

void ElementMatrix::pattern_changed() {
  for (ElementBlocks& e : elements_)
    e.gather_stale = true;
}

void ElementMatrix::assemble(const ForceInput& in, Real h, std::size_t n, std::vector<Vec3>& kxv) {
  kxv.resize(n);
  parallel_for(n, [&](std::size_t i) { kxv[i].setZero(); });
  // A count, the same whatever the order the blocks add to it in.
  std::atomic<std::size_t> projected{0};
  std::atomic<bool> velocity_dependent{false};
  for (ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    const std::size_t matches = e.model->active_matches();
    if (matches != e.matches) e.gather_stale = true;
    e.matches = matches;
    // resize() keeps the capacity: after the largest match count seen,
    // assembling allocates nothing.
    e.slots.resize(e.matches * k);
    e.blocks.resize(e.matches * k * k);
    e.dfdv.resize(e.matches * k * k);
    e.terms.resize(e.matches * k);
    e.model->jacobians(in, e.slots.data(), e.blocks.data(), e.dfdv.data());
    if (e.gather_stale) {
      e.gather.build(e.slots);
      e.gather_stale = false;
    }
    const Real h2 = h * h;
    // Row i of each match: its part of kxv (a term for the gather), then
    // the blocks of A.
    parallel_for(e.matches, [&](std::size_t m) {
      const Slot* s = e.slots.data() + m * k;
      Mat3* c = e.blocks.data() + m * k * k;
      Mat3* dv = e.dfdv.data() + m * k * k;
      if (project_ && !e.semidefinite) {
        const int changed = project_to_semidefinite(c, e.k) + project_to_semidefinite(dv, e.k);
        if (changed) projected.fetch_add(changed, std::memory_order_relaxed);
      }
      bool damped = false;
      for (std::size_t i = 0; i < k; ++i) {
        Vec3 row = Vec3::Zero();
        for (std::size_t j = 0; j < k; ++j) {
          Mat3& b = c[i * k + j];  // holds ∂f_i/∂x_j on entry
          if (s[i] != kNoSlot && s[j] != kNoSlot) row += b * in.v[s[j]];
          damped = damped || !(dv[i * k + j].array() == 0).all();
          b = -(h2 * b + h * dv[i * k + j]);
        }
        e.terms[m * k + i] = row;
      }
      if (damped) velocity_dependent.store(true, std::memory_order_relaxed);
    });
    e.gather.add_to(e.terms.data(), kxv.data());
  }
  projected_ = projected.load();
  velocity_dependent_ = velocity_dependent.load();
}

void ElementMatrix::multiply(const Vec3* p, Vec3* out, std::size_t n) const {
  parallel_for(n, [&](std::size_t i) { out[i].setZero(); });
  for (const ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    parallel_for(e.matches, [&](std::size_t m) {
      const Slot* s = e.slots.data() + m * k;
      const Mat3* c = e.blocks.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        Vec3 sum = Vec3::Zero();
        for (std::size_t j = 0; j < k; ++j) {
          if (s[j] != kNoSlot) sum += c[i * k + j] * p[s[j]];
        }
        e.terms[m * k + i] = sum;  // dropped by the gather when s[i] is kNoSlot
      }
    });
    e.gather.add_to(e.terms.data(), out);
  }
}

void ElementMatrix::add_diagonal(Mat3* diag) const {
  // Through each element kind's gather (built by assemble, which comes
  // first): per vertex, its blocks in increasing term order, the order of a
  // serial loop over the matches, so the sums do not depend on the threads.
  for (const ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    e.gather.add_each(diag, [&](std::uint32_t t) -> const Mat3& {
      const std::size_t m = t / k, i = t % k;
      return e.blocks[m * k * k + i * k + i];
    });
  }
}

}  // namespace rift
